-- Lagrange polynomials at the 4 Gauss-Legendre nodes: the 4-stage Gauss method (order 8, At = A)
return {
  name = "gauss_legendre_s4",
  description = "Lagrange polynomials at the 4 Gauss-Legendre nodes: the 4-stage Gauss method (order 8, At = A)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.1.3; Leok & Zhang sec. 4.5",
  basis = "lagrange",
  nodes = gauss_legendre(4),
}
