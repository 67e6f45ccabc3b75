-- Lagrange polynomials at Chebyshev's equal-weight quadrature nodes, s = 1 (order 2)
return {
  name = "leok_zhang_ex5_s1",
  description = "Lagrange polynomials at Chebyshev's equal-weight quadrature nodes, s = 1 (order 2)",
  source = "Leok & Zhang, Discrete Hamiltonian variational integrators, IMA J. Numer. Anal. 31 (2011), sec. 4.5, Example 5",
  basis = "lagrange",
  nodes = chebyshev_quadrature(1),
}
