return { name = "x", basis = "lagrange" }
