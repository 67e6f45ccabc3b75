-- Suzuki (1990) fourth-order fractal composition.
-- Suzuki's fourth-order five-fold symmetric composition of the q-first
-- (position, drift-kick-drift) Stormer-Verlet step, p = 1/(4 - 4^(1/3)). As a
-- PRK tableau it has s = 10 stages (6 drifts and 5 kicks per step; s = drifts
-- + kicks - 1).
-- M. Suzuki, "Fractal decomposition of exponential operators with
-- applications to many-body theories and Monte Carlo simulations", Phys.
-- Lett. A 146 (1990) 319-323: S4(h) = S2(p h)^2 S2((1-4p) h) S2(p h)^2, p =
-- 1/(4 - 4^(1/3)).
--
-- Written as published: the kicks (p <- p - coef h dV/dq) and drifts
-- (q <- q + coef h dT/dp) in order of application; vigen converts them
-- exactly to a PRK tableau with bt = b (substeps - 1 stages), symplectic
-- for every H and, for separable H, explicit and equal to the splitting.
local p = "(1/(4 - 4^(1/3)))"
return {
  name = "suzuki_4",
  order = 4,
  symplectic = true,
  source = "M. Suzuki, \"Fractal decomposition of exponential operators with applications to many-body theories and Monte Carlo simulations\", Phys. Lett. A 146 (1990) 319-323: S4(h) = S2(p h)^2 S2((1-4p) h) S2(p h)^2, p = 1/(4 - 4^(1/3))",
  description = "Suzuki's fourth-order five-fold symmetric composition of the q-first (position, drift-kick-drift) Stormer-Verlet step, p = 1/(4 - 4^(1/3)).",
  splitting = {
    { "drift", p .. "/2" },
    { "kick", p },
    { "drift", p },
    { "kick", p },
    { "drift", "1/2 - 3*" .. p .. "/2" },
    { "kick", "1 - 4*" .. p },
    { "drift", "1/2 - 3*" .. p .. "/2" },
    { "kick", p },
    { "drift", p },
    { "kick", p },
    { "drift", p .. "/2" },
  },
}
