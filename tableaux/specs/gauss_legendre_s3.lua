-- Lagrange polynomials at the 3 Gauss-Legendre nodes: the 3-stage Gauss method (order 6, At = A)
return {
  name = "gauss_legendre_s3",
  description = "Lagrange polynomials at the 3 Gauss-Legendre nodes: the 3-stage Gauss method (order 6, At = A)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.1.3; Leok & Zhang sec. 4.5",
  basis = "lagrange",
  nodes = gauss_legendre(3),
}
