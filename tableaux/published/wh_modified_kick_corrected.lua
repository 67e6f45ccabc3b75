-- The Wisdom-Holman drift-kick-drift map with a modified kick, processed
-- by the symplectic corrector of order 11 of Wisdom, Holman & Touma (1996)
-- (the kernel method): generalized order (12,4), error O(eps h^12 + eps^2
-- h^4), against (12,2) for the plain kernel with the same corrector
-- (wisdom_holman_corrected_11).
-- The corrector is the runtime's (runtime/nbody/correctors.c, docs/
-- splitting.md "Symplectic correctors") as exact numbers, in the form
-- written first in the step (true state -> kernel's):
--   for i = 5..1:  Kepler(a_i h) interaction(b_i h) Kepler(-2 a_i h)
--                  interaction(-b_i h) Kepler(a_i h),
-- a_i = i sqrt(7/40), b_i = r_i / sqrt(7/40) with r_i rational: the
-- solution of sum_i 2 b_i a_i^k / k! = [x^k] (f(x) - 1)/x for k = 1, 3,
-- ..., 9, f(x) = (x/2)/sinh(x/2) (Bernoulli numbers; the runtime's 17-digit
-- b_i are these rounded).  It removes the eps h^2 .. eps h^11 terms, and
-- its conjugation shifts the kernel's eps^2 h^2 term by -2 sum a_i b_i
-- (= -1/24, fixed by its k = 1 equation), so that the kick's bracket
-- coefficient is c = -1/24 here, not the -1/12 of the bare kernel
-- (wh_modified_kick).  The corrector's own eps^2 h^3 term,
-- (sum_i a_i b_i^2) [[A,B],B] to the sign the checker decides, would leave an
-- eps^2 h^3 error in the step: the corrector ends with the bracket flow for
-- x h^3, x = sum_i a_i b_i^2 = 3892997393283437/642706774802104320 /
-- sqrt(7/40), which removes it.  vigen check derives and certifies c and x.
-- J. Wisdom, M. Holman, J. Touma, "Symplectic correctors", Fields Inst.
-- Commun. 10 (1996) 217-244; J. Wisdom, Astron. J. 131 (2006) 2294-2298.
return {
  name = "wh_modified_kick_corrected",
  generalized_order = {12, 4},
  symplectic = true,
  source = "kernel method of J. Wisdom, M. Holman, J. Touma, \"Symplectic correctors\", Fields Inst. Commun. 10 (1996) 217-244: the Wisdom-Holman map with the modified kick exp(h eps B + c eps^2 h^3 {{A,B},B}), processed by their corrector of order 11 (a_i = i sqrt(7/40), b_i from f(x) = (x/2)/sinh(x/2), exact); c = -1/24 and the corrector's bracket term derived with vigen check",
  description = "Wisdom-Holman drift-kick-drift map with the modified kick exp(h eps B - (1/24) eps^2 h^3 {{A,B},B}), processed by the order-11 Wisdom-Holman-Touma corrector with a bracket term: generalized order (12,4), error O(eps h^12 + eps^2 h^4).",
  flows = { "kepler", "interaction", "interaction_gradient" },
  brackets = { interaction_gradient = { "kepler", "interaction", "interaction" } },
  perturbation = "interaction",
  splitting = {
    { "kepler", "1/2" },
    { "interaction", "1/2" },
    { "interaction_gradient", "-1/24" },
    { "interaction", "1/2" },
    { "kepler", "1/2" },
  },
  corrector = {
    { "kepler", "5*sqrt(7/40)" }, { "interaction", "(-2798927/16429754880)/sqrt(7/40)" }, { "kepler", "-2*5*sqrt(7/40)" }, { "interaction", "-(-2798927/16429754880)/sqrt(7/40)" }, { "kepler", "5*sqrt(7/40)" },
    { "kepler", "4*sqrt(7/40)" }, { "interaction", "(329447/167650560)/sqrt(7/40)" }, { "kepler", "-2*4*sqrt(7/40)" }, { "interaction", "-(329447/167650560)/sqrt(7/40)" }, { "kepler", "4*sqrt(7/40)" },
    { "kepler", "3*sqrt(7/40)" }, { "interaction", "(-895249/86929920)/sqrt(7/40)" }, { "kepler", "-2*3*sqrt(7/40)" }, { "interaction", "-(-895249/86929920)/sqrt(7/40)" }, { "kepler", "3*sqrt(7/40)" },
    { "kepler", "2*sqrt(7/40)" }, { "interaction", "(14556229/456382080)/sqrt(7/40)" }, { "kepler", "-2*2*sqrt(7/40)" }, { "interaction", "-(14556229/456382080)/sqrt(7/40)" }, { "kepler", "2*sqrt(7/40)" },
    { "kepler", "sqrt(7/40)" }, { "interaction", "(-3394141/55883520)/sqrt(7/40)" }, { "kepler", "-2*sqrt(7/40)" }, { "interaction", "-(-3394141/55883520)/sqrt(7/40)" }, { "kepler", "sqrt(7/40)" },
    { "interaction_gradient", "3892997393283437/642706774802104320/sqrt(7/40)" },
  },
}
