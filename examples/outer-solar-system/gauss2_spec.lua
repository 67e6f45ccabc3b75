-- Lagrange polynomials at the 2 Gauss-Legendre nodes: the 2-stage Gauss method (order 4, At = A)
return {
  name = "gauss_legendre_s2",
  description = "Lagrange polynomials at the 2 Gauss-Legendre nodes: the 2-stage Gauss method (order 4, At = A)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.1.3; Leok & Zhang sec. 4.5",
  basis = "lagrange",
  nodes = gauss_legendre(2),
}
