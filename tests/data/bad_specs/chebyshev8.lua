return { name = "chebyshev8", basis = "lagrange", nodes = chebyshev_quadrature(8) }
