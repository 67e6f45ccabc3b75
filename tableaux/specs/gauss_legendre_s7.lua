-- Lagrange polynomials at the 7 Gauss-Legendre nodes: the 7-stage Gauss method (order 14, At = A)
return {
  name = "gauss_legendre_s7",
  description = "Lagrange polynomials at the 7 Gauss-Legendre nodes: the 7-stage Gauss method (order 14, At = A)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.1.3; Leok & Zhang sec. 4.5",
  basis = "lagrange",
  nodes = gauss_legendre(7),
}
