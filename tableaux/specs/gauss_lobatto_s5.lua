-- Lagrange polynomials at the 5 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 8)
return {
  name = "gauss_lobatto_s5",
  description = "Lagrange polynomials at the 5 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 8)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.2.2",
  basis = "lagrange",
  nodes = gauss_lobatto(5),
}
