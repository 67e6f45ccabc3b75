-- Lagrange polynomials at the 5 Gauss-Legendre nodes: the 5-stage Gauss method (order 10, At = A)
return {
  name = "gauss_legendre_s5",
  description = "Lagrange polynomials at the 5 Gauss-Legendre nodes: the 5-stage Gauss method (order 10, At = A)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.1.3; Leok & Zhang sec. 4.5",
  basis = "lagrange",
  nodes = gauss_legendre(5),
}
