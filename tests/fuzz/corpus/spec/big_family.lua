return { name = "big", nodes = gauss_legendre(100000), basis = "lagrange" }
