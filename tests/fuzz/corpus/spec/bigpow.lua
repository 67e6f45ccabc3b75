return { name = "p", nodes = {"0", "2^100000000"}, basis = "lagrange" }
