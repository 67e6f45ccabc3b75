-- Lagrange polynomials at the 8 Gauss-Legendre nodes: the 8-stage Gauss method (order 16, At = A)
return {
  name = "gauss_legendre_s8",
  description = "Lagrange polynomials at the 8 Gauss-Legendre nodes: the 8-stage Gauss method (order 16, At = A)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.1.3; Leok & Zhang sec. 4.5",
  basis = "lagrange",
  nodes = gauss_legendre(8),
}
