-- Lagrange polynomials at Chebyshev's equal-weight quadrature nodes, s = 3 (order 4)
return {
  name = "leok_zhang_ex5_s3",
  description = "Lagrange polynomials at Chebyshev's equal-weight quadrature nodes, s = 3 (order 4)",
  source = "Leok & Zhang, Discrete Hamiltonian variational integrators, IMA J. Numer. Anal. 31 (2011), sec. 4.5, Example 5",
  basis = "lagrange",
  nodes = chebyshev_quadrature(3),
}
