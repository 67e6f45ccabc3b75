return { name = "bad_order_claim", order = "four", nodes = gauss_legendre(2), basis = "lagrange" }
