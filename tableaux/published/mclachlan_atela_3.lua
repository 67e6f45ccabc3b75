-- McLachlan-Atela (1992) optimal third-order method.
-- McLachlan-Atela optimal 3-stage third-order method: kicks (a3, a2, a1),
-- drifts (a1, a2, a3), kick first, where a1 is the root near 0.9197 of 12 x^4
-- - 24 x^2 + 16 x - 3 (closed form by Ferrari: a1 = sqrt(4/(9(1+v^2)) + v/2 +
-- sqrt(1+v^2)/2) - 2/(3 sqrt(1+v^2)), v = (2 + (2-sqrt(3))^(1/3) +
-- (2+sqrt(3))^(1/3))/3), a2 = 1/(4 a1) - a1/2, a3 = 1 - a1 - a2. The closed
-- form agrees with the 18 printed digits. As a PRK tableau it has s = 5
-- stages (3 drifts and 3 kicks per step; s = drifts + kicks - 1).
-- R. I. McLachlan, P. Atela, "The accuracy of symplectic integrators",
-- Nonlinearity 5 (1992) 541-562, Table 2 (optimal three-stage third-order
-- method, printed as a1 = 0.919661523017399857, a2 = -0.187991618799159782,
-- a3 = 0.268330095781759925, b = (a3, a2, a1)); closed form as in SUNDIALS
-- ARKODE (ARKODE_SPRK_MCLACHLAN_3_3).
--
-- Written as published: the kicks (p <- p - coef h dV/dq) and drifts
-- (q <- q + coef h dT/dp) in order of application; vigen converts them
-- exactly to a PRK tableau with bt = b (substeps - 1 stages), symplectic
-- for every H and, for separable H, explicit and equal to the splitting.
local a1 = "(sqrt(4/(9*(1 + ((2 + (2 - sqrt(3))^(1/3) + (2 + sqrt(3))^(1/3))/3)^2)) + ((2 + (2 - sqrt(3))^(1/3) + (2 + sqrt(3))^(1/3))/3)/2 + sqrt(1 + ((2 + (2 - sqrt(3))^(1/3) + (2 + sqrt(3))^(1/3))/3)^2)/2) - 2/(3*sqrt(1 + ((2 + (2 - sqrt(3))^(1/3) + (2 + sqrt(3))^(1/3))/3)^2)))"
return {
  name = "mclachlan_atela_3",
  order = 3,
  symplectic = true,
  source = "R. I. McLachlan, P. Atela, \"The accuracy of symplectic integrators\", Nonlinearity 5 (1992) 541-562, Table 2 (optimal three-stage third-order method, printed as a1 = 0.919661523017399857, a2 = -0.187991618799159782, a3 = 0.268330095781759925, b = (a3, a2, a1)); closed form as in SUNDIALS ARKODE (ARKODE_SPRK_MCLACHLAN_3_3)",
  description = "McLachlan-Atela optimal 3-stage third-order method: kicks (a3, a2, a1), drifts (a1, a2, a3), kick first, where a1 is the root near 0.9197 of 12 x^4 - 24 x^2 + 16 x - 3 (closed form by Ferrari: a1 = sqrt(4/(9(1+v^2)) + v/2 + sqrt(1+v^2)/2) - 2/(3 sqrt(1+v^2)), v = (2 + (2-sqrt(3))^(1/3) + (2+sqrt(3))^(1/3))/3), a2 = 1/(4 a1) - a1/2, a3 = 1 - a1 - a2. The closed form agrees with the 18 printed digits.",
  splitting = {
    { "kick", "-" .. a1 .. "/2 + 1 - 1/(4*" .. a1 .. ")" },
    { "drift", a1 },
    { "kick", "-" .. a1 .. "/2 + 1/(4*" .. a1 .. ")" },
    { "drift", "-" .. a1 .. "/2 + 1/(4*" .. a1 .. ")" },
    { "kick", a1 },
    { "drift", "-" .. a1 .. "/2 + 1 - 1/(4*" .. a1 .. ")" },
  },
}
