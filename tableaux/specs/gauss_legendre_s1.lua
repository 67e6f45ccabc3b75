-- Lagrange polynomials at the 1 Gauss-Legendre nodes: the 1-stage Gauss method (order 2, At = A)
return {
  name = "gauss_legendre_s1",
  description = "Lagrange polynomials at the 1 Gauss-Legendre nodes: the 1-stage Gauss method (order 2, At = A)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.1.3; Leok & Zhang sec. 4.5",
  basis = "lagrange",
  nodes = gauss_legendre(1),
}
