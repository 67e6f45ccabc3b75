-- Lagrange polynomials at the 6 Gauss-Legendre nodes: the 6-stage Gauss method (order 12, At = A)
return {
  name = "gauss_legendre_s6",
  description = "Lagrange polynomials at the 6 Gauss-Legendre nodes: the 6-stage Gauss method (order 12, At = A)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.1.3; Leok & Zhang sec. 4.5",
  basis = "lagrange",
  nodes = gauss_legendre(6),
}
