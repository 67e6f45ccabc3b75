return { name = "\27[31mred", nodes = gauss_legendre(2), basis = {"1", "t", "t^2"} }
