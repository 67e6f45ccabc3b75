-- 2-stage Gauss-Legendre collocation method (order 4), exact closed forms.
-- Hairer, Lubich, Wanner, Geometric Numerical Integration, Table II.1.1.
return {
  name = "gauss2", s = 2,
  c = { "1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6" },
  A = { { "1/4", "1/4 - sqrt(3)/6" },
        { "1/4 + sqrt(3)/6", "1/4" } },
  b = { "1/2", "1/2" },
  order = 4, symplectic = true,
  description = "Gauss-Legendre, 2 stages",
}
