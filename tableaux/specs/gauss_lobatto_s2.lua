-- Lagrange polynomials at the 2 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 2)
return {
  name = "gauss_lobatto_s2",
  description = "Lagrange polynomials at the 2 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 2)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.2.2",
  basis = "lagrange",
  nodes = gauss_lobatto(2),
}
