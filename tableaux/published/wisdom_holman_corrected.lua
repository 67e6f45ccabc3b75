-- The Wisdom-Holman kernel with the symplectic corrector of Wisdom, Holman
-- & Touma (1996): a processed method.  The kernel K is the map in its
-- drift-kick-drift form (the Kepler flow for h/2, the interaction for h,
-- the Kepler flow for h/2), for which the correctors were derived; the
-- corrector C = X(alpha, beta) X(-alpha, -beta), X(a, b) = the Kepler flow
-- for -a h, the interaction for b h, the Kepler flow for a h, with
-- alpha = sqrt(7/40) and beta = 1/(48 alpha).  One step is C, K, C^-1 (C
-- maps the real coordinates to the kernel's; over many steps C is applied
-- once at the start and C^-1 at each output).  The corrector removes the
-- eps h^2 error term of the kernel: generalized order (4,2), error
-- O(eps h^4 + eps^2 h^2), against (2,2) for the uncorrected map.
-- J. Wisdom, M. Holman, J. Touma, "Symplectic correctors", in Integration
-- Algorithms and Classical Mechanics, Fields Inst. Commun. 10 (1996)
-- 217-244: the corrector built from X(a, b) with a = +-alpha, alpha =
-- sqrt(7/40), beta = 1/(48 alpha).
local al = "sqrt(7/40)"
local be = "1/(48*sqrt(7/40))"
return {
  name = "wisdom_holman_corrected",
  order = 2,
  generalized_order = {4, 2},
  symplectic = true,
  source = "J. Wisdom, M. Holman, J. Touma, \"Symplectic correctors\", Fields Inst. Commun. 10 (1996) 217-244: corrector X(alpha, beta) X(-alpha, -beta), X(a, b) = Kepler(-a h) interaction(b h) Kepler(a h), alpha = sqrt(7/40), beta = 1/(48 alpha); kernel Kepler h/2, interaction h, Kepler h/2",
  description = "The Wisdom-Holman map (Kepler h/2, interaction h, Kepler h/2) processed by the Wisdom-Holman-Touma corrector with alpha = sqrt(7/40), beta = 1/(48 alpha): C once before the first step, C^-1 at every output. Generalized order (4,2): error O(eps h^4 + eps^2 h^2).",
  flows = { "kepler", "interaction" },
  perturbation = "interaction",
  splitting = {
    { "kepler", "1/2" },
    { "interaction", "1" },
    { "kepler", "1/2" },
  },
  corrector = {
    { "kepler", "-" .. al }, { "interaction", be }, { "kepler", al },
    { "kepler", al }, { "interaction", "-" .. be }, { "kepler", "-" .. al },
  },
}
