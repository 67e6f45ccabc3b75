-- Lagrange polynomials at the 3 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 4)
return {
  name = "gauss_lobatto_s3",
  description = "Lagrange polynomials at the 3 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 4)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.2.2",
  basis = "lagrange",
  nodes = gauss_lobatto(3),
}
