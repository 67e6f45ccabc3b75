-- The 2-stage Gauss-Legendre collocation method (order 4, symplectic), with
-- exact entries: vigen emit rounds each one correctly to the target type.
return {
  name = "gauss2", s = 2, order = 4, symplectic = true,
  c  = { "1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6" },
  A  = { { "1/4", "1/4 - sqrt(3)/6" }, { "1/4 + sqrt(3)/6", "1/4" } },
  b  = { "1/2", "1/2" },
  At = { { "1/4", "1/4 - sqrt(3)/6" }, { "1/4 + sqrt(3)/6", "1/4" } },
}
