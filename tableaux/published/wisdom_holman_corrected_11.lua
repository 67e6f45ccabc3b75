-- The Wisdom-Holman drift-kick-drift map (Kepler h/2, interaction h,
-- Kepler h/2) processed by the symplectic corrector of order 11 of Wisdom,
-- Holman & Touma (1996), with exact coefficients: generalized order (12,2),
-- error O(eps h^12 + eps^2 h^2).  The corrector is the runtime's
-- (runtime/nbody/correctors.c, docs/splitting.md "Symplectic correctors"),
-- in the form written first in the step (true state -> kernel's):
--   for i = 5..1:  Kepler(a_i h) interaction(b_i h) Kepler(-2 a_i h)
--                  interaction(-b_i h) Kepler(a_i h),
-- a_i = i sqrt(7/40), b_i = r_i / sqrt(7/40), r_i rational: the solution of
-- sum_i 2 b_i a_i^k / k! = [x^k] (f(x) - 1)/x for k = 1, 3, ..., 9,
-- f(x) = (x/2)/sinh(x/2) (the runtime's 17-digit b_i are these rounded).
-- J. Wisdom, M. Holman, J. Touma, "Symplectic correctors", Fields Inst.
-- Commun. 10 (1996) 217-244; the orders 3..17 of WHFast, H. Rein, D. Tamayo,
-- MNRAS 452 (2015) 376.
return {
  name = "wisdom_holman_corrected_11",
  order = 2,
  generalized_order = {12, 2},
  symplectic = true,
  source = "J. Wisdom, M. Holman, J. Touma, \"Symplectic correctors\", Fields Inst. Commun. 10 (1996) 217-244: the corrector of order 11 for the drift-kick-drift kernel, a_i = i sqrt(7/40), b_i from f(x) = (x/2)/sinh(x/2) (exact rationals over sqrt(7/40))",
  description = "The Wisdom-Holman map (Kepler h/2, interaction h, Kepler h/2) processed by the order-11 Wisdom-Holman-Touma corrector, exact coefficients: generalized order (12,2), error O(eps h^12 + eps^2 h^2).",
  flows = { "kepler", "interaction" },
  perturbation = "interaction",
  splitting = {
    { "kepler", "1/2" },
    { "interaction", "1" },
    { "kepler", "1/2" },
  },
  corrector = {
    { "kepler", "5*sqrt(7/40)" }, { "interaction", "(-2798927/16429754880)/sqrt(7/40)" }, { "kepler", "-2*5*sqrt(7/40)" }, { "interaction", "-(-2798927/16429754880)/sqrt(7/40)" }, { "kepler", "5*sqrt(7/40)" },
    { "kepler", "4*sqrt(7/40)" }, { "interaction", "(329447/167650560)/sqrt(7/40)" }, { "kepler", "-2*4*sqrt(7/40)" }, { "interaction", "-(329447/167650560)/sqrt(7/40)" }, { "kepler", "4*sqrt(7/40)" },
    { "kepler", "3*sqrt(7/40)" }, { "interaction", "(-895249/86929920)/sqrt(7/40)" }, { "kepler", "-2*3*sqrt(7/40)" }, { "interaction", "-(-895249/86929920)/sqrt(7/40)" }, { "kepler", "3*sqrt(7/40)" },
    { "kepler", "2*sqrt(7/40)" }, { "interaction", "(14556229/456382080)/sqrt(7/40)" }, { "kepler", "-2*2*sqrt(7/40)" }, { "interaction", "-(14556229/456382080)/sqrt(7/40)" }, { "kepler", "2*sqrt(7/40)" },
    { "kepler", "sqrt(7/40)" }, { "interaction", "(-3394141/55883520)/sqrt(7/40)" }, { "kepler", "-2*sqrt(7/40)" }, { "interaction", "-(-3394141/55883520)/sqrt(7/40)" }, { "kepler", "sqrt(7/40)" },
  },
}
