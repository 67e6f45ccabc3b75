-- McLachlan-Atela (1992) optimal second-order method.
-- McLachlan-Atela optimal 2-stage second-order method: kick 1-1/sqrt(2),
-- drift 1/sqrt(2), kick 1/sqrt(2), drift 1-1/sqrt(2). As a PRK tableau it has
-- s = 3 stages (2 drifts and 2 kicks per step; s = drifts + kicks - 1).
-- R. I. McLachlan, P. Atela, "The accuracy of symplectic integrators",
-- Nonlinearity 5 (1992) 541-562, Table 2 (optimal two-stage second-order
-- method, coefficients 1 - 1/sqrt(2) and 1/sqrt(2); same closed form in
-- SUNDIALS ARKODE_SPRK_MCLACHLAN_2_2).
--
-- Splitting method for separable H = T(p) + V(q) written as a PRK method with
-- b~ = b: the drift q += a h T'(p) and kick p -= b h V'(q) substeps are cut
-- into stages (one stage per pair of overlapping drift/kick pieces), so that
-- A_ij = w_j when the drift of stage j precedes the kick of stage i and A~_ij
-- = w_j when the kick of stage j precedes the drift of stage i, b = b~ = w.
-- The tableau satisfies b_i at_ij + b_j a_ji = b_i b_j exactly (symplectic
-- for every H); for separable H it is explicit and one PRK step equals one
-- step of the splitting scheme.
--
-- Scheme (in order of application; drift: q += coef*h*T'(p), kick: p -=
-- coef*h*V'(q)): kick 1 - sqrt(2)/2; drift sqrt(2)/2; kick sqrt(2)/2; drift 1
-- - sqrt(2)/2.
return {
  name = "mclachlan_atela_2",
  s = 3,
  order = 2,
  symplectic = true,
  source = "R. I. McLachlan, P. Atela, \"The accuracy of symplectic integrators\", Nonlinearity 5 (1992) 541-562, Table 2 (optimal two-stage second-order method, coefficients 1 - 1/sqrt(2) and 1/sqrt(2); same closed form in SUNDIALS ARKODE_SPRK_MCLACHLAN_2_2)",
  description = "McLachlan-Atela optimal 2-stage second-order method: kick 1-1/sqrt(2), drift 1/sqrt(2), kick 1/sqrt(2), drift 1-1/sqrt(2). As a PRK tableau it has s = 3 stages (2 drifts and 2 kicks per step; s = drifts + kicks - 1). Exact entries.",
  c = { "0", "sqrt(2)/2", "sqrt(2)/2" },
  A = {
    { "0", "0", "0" },
    { "1 - sqrt(2)/2", "-1 + sqrt(2)", "0" },
    { "1 - sqrt(2)/2", "-1 + sqrt(2)", "0" },
  },
  b = { "1 - sqrt(2)/2", "-1 + sqrt(2)", "1 - sqrt(2)/2" },
  ct = { "1 - sqrt(2)/2", "1 - sqrt(2)/2", "1" },
  At = {
    { "1 - sqrt(2)/2", "0", "0" },
    { "1 - sqrt(2)/2", "0", "0" },
    { "1 - sqrt(2)/2", "-1 + sqrt(2)", "1 - sqrt(2)/2" },
  },
}
