-- Lagrange polynomials at the 6 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 10)
return {
  name = "gauss_lobatto_s6",
  description = "Lagrange polynomials at the 6 Gauss-Lobatto nodes: the Lobatto IIIA-IIIB pair (order 10)",
  source = "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. II.2.2",
  basis = "lagrange",
  nodes = gauss_lobatto(6),
}
