-- McLachlan (1995) symmetric fourth-order method with five force evaluations.
-- McLachlan's symmetric composition of order 4 for H = T(p) + V(q): drift
-- a1, kick b1, drift a2, kick b2, drift a3, kick b3, drift a3, kick b2, drift
-- a2, kick b1, drift a1 with b1 = -3/73, b2 = 17/59, b3 = 1 - 2(b1+b2), a3 =
-- 1/2 - (a1+a2), where a1, a2 are the root near (0.405, -0.287) of the two
-- fourth-order conditions for these b (one linear and one quadratic in a1,
-- a2): a1 = (1095 sqrt(722025967665) - 229483763)/1729961856, a2 =
-- (315354233 - 1081 sqrt(722025967665))/2100667968. The closed forms agree
-- with all 20 printed digits (a1 = 0.40518861839525227722, a2 =
-- -0.28714404081652408900). As a PRK tableau it has s = 10 stages (6 drifts
-- and 5 kicks per step; s = drifts + kicks - 1); the emitted stepper makes 5
-- force evaluations per step.
-- R. I. McLachlan, "On the numerical integration of ordinary differential
-- equations by symmetric composition methods", SIAM J. Sci. Comput. 16
-- (1995) 151-168 (the symmetric fourth-order method with five force
-- evaluations of type SB3A, for Runge-Kutta-Nystrom problems), coefficients
-- a1 = 0.40518861839525227722, a2 = -0.28714404081652408900, b1 = -3/73, b2
-- = 17/59 as transcribed, in agreement, by Boost.Odeint 1.74
-- (symplectic_rkn_sb3a_mclachlan, which evaluates a sixth force with weight
-- 0) and Principia (McLachlan1995SB3A5); the paper itself was not at hand.
--
-- Written as published: the kicks (p <- p - coef h dV/dq) and drifts
-- (q <- q + coef h dT/dp) in order of application; vigen converts them
-- exactly to a PRK tableau with bt = b (substeps - 1 stages), symplectic
-- for every H and, for separable H, explicit and equal to the splitting.
local a1 = "((1095*sqrt(722025967665) - 229483763)/1729961856)"
local a2 = "((315354233 - 1081*sqrt(722025967665))/2100667968)"
local a3 = "(1/2 - " .. a1 .. " - " .. a2 .. ")"
local b1, b2 = "(-3/73)", "(17/59)"
local b3 = "(1 - 2*" .. b1 .. " - 2*" .. b2 .. ")"
return {
  name = "mclachlan_rkn_4",
  order = 4,
  symplectic = true,
  source = "R. I. McLachlan, \"On the numerical integration of ordinary differential equations by symmetric composition methods\", SIAM J. Sci. Comput. 16 (1995) 151-168 (the symmetric fourth-order method with five force evaluations of type SB3A), coefficients a1 = 0.40518861839525227722, a2 = -0.28714404081652408900, b1 = -3/73, b2 = 17/59 as transcribed by Boost.Odeint 1.74 (symplectic_rkn_sb3a_mclachlan) and Principia (McLachlan1995SB3A5)",
  description = "McLachlan's symmetric composition of order 4 for H = T(p) + V(q): drift a1, kick b1, drift a2, kick b2, drift a3, kick b3, drift a3, kick b2, drift a2, kick b1, drift a1 with b1 = -3/73, b2 = 17/59, b3 = 1 - 2(b1+b2), a3 = 1/2 - (a1+a2), where a1, a2 are the root near (0.405, -0.287) of the two fourth-order conditions for these b: a1 = (1095 sqrt(722025967665) - 229483763)/1729961856, a2 = (315354233 - 1081 sqrt(722025967665))/2100667968. The closed forms agree with all 20 printed digits.",
  splitting = {
    { "drift", a1 },
    { "kick", b1 },
    { "drift", a2 },
    { "kick", b2 },
    { "drift", a3 },
    { "kick", b3 },
    { "drift", a3 },
    { "kick", b2 },
    { "drift", a2 },
    { "kick", b1 },
    { "drift", a1 },
  },
}
