-- Lagrange polynomials at the 4 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 6)
return {
  name = "gauss_lobatto_s4",
  description = "Lagrange polynomials at the 4 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 6)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.2.2",
  basis = "lagrange",
  nodes = gauss_lobatto(4),
}
