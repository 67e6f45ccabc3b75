-- McLachlan-Atela (1992) optimal second-order method.
-- McLachlan-Atela optimal 2-stage second-order method: kick 1-1/sqrt(2),
-- drift 1/sqrt(2), kick 1/sqrt(2), drift 1-1/sqrt(2). As a PRK tableau it has
-- s = 3 stages (2 drifts and 2 kicks per step; s = drifts + kicks - 1).
-- R. I. McLachlan, P. Atela, "The accuracy of symplectic integrators",
-- Nonlinearity 5 (1992) 541-562, Table 2 (optimal two-stage second-order
-- method, coefficients 1 - 1/sqrt(2) and 1/sqrt(2); same closed form in
-- SUNDIALS ARKODE_SPRK_MCLACHLAN_2_2).
--
-- Written as published: the kicks (p <- p - coef h dV/dq) and drifts
-- (q <- q + coef h dT/dp) in order of application; vigen converts them
-- exactly to a PRK tableau with bt = b (substeps - 1 stages), symplectic
-- for every H and, for separable H, explicit and equal to the splitting.
return {
  name = "mclachlan_atela_2",
  order = 2,
  symplectic = true,
  source = "R. I. McLachlan, P. Atela, \"The accuracy of symplectic integrators\", Nonlinearity 5 (1992) 541-562, Table 2 (optimal two-stage second-order method, coefficients 1 - 1/sqrt(2) and 1/sqrt(2); same closed form in SUNDIALS ARKODE_SPRK_MCLACHLAN_2_2)",
  description = "McLachlan-Atela optimal 2-stage second-order method: kick 1-1/sqrt(2), drift 1/sqrt(2), kick 1/sqrt(2), drift 1-1/sqrt(2).",
  splitting = {
    { "kick", "1 - sqrt(2)/2" },
    { "drift", "sqrt(2)/2" },
    { "kick", "sqrt(2)/2" },
    { "drift", "1 - sqrt(2)/2" },
  },
}
