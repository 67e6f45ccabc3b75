-- Yoshida (1990) fourth-order triple jump of velocity Verlet.
-- Yoshida's fourth-order triple jump applied to the p-first (velocity,
-- kick-drift-kick) Stormer-Verlet step: kick x1/2, drift x1, kick (x0+x1)/2,
-- drift x0, kick (x0+x1)/2, drift x1, kick x1/2. (The triple jump of the
-- q-first step is forest_ruth_4.) As a PRK tableau it has s = 6 stages (3
-- drifts and 4 kicks per step; s = drifts + kicks - 1).
-- H. Yoshida, "Construction of higher order symplectic integrators", Phys.
-- Lett. A 150 (1990) 262-268, Sect. 4: S4(h) = S2(x1 h) S2(x0 h) S2(x1 h), x1
-- = 1/(2 - 2^(1/3)), x0 = -2^(1/3)/(2 - 2^(1/3)) = 1 - 2 x1.
--
-- Written as published: the kicks (p <- p - coef h dV/dq) and drifts
-- (q <- q + coef h dT/dp) in order of application; vigen converts them
-- exactly to a PRK tableau with bt = b (substeps - 1 stages), symplectic
-- for every H and, for separable H, explicit and equal to the splitting.
local x1 = "(1/(2 - 2^(1/3)))"
return {
  name = "yoshida_4",
  order = 4,
  symplectic = true,
  source = "H. Yoshida, \"Construction of higher order symplectic integrators\", Phys. Lett. A 150 (1990) 262-268, Sect. 4: S4(h) = S2(x1 h) S2(x0 h) S2(x1 h), x1 = 1/(2 - 2^(1/3)), x0 = -2^(1/3)/(2 - 2^(1/3)) = 1 - 2 x1",
  description = "Yoshida's fourth-order triple jump applied to the p-first (velocity, kick-drift-kick) Stormer-Verlet step: kick x1/2, drift x1, kick (x0+x1)/2, drift x0, kick (x0+x1)/2, drift x1, kick x1/2. (The triple jump of the q-first step is forest_ruth_4.)",
  splitting = {
    { "kick", x1 .. "/2" },
    { "drift", x1 },
    { "kick", "1/2 - " .. x1 .. "/2" },
    { "drift", "1 - 2*" .. x1 },
    { "kick", "1/2 - " .. x1 .. "/2" },
    { "drift", x1 },
    { "kick", x1 .. "/2" },
  },
}
