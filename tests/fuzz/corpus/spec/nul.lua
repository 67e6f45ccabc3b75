return { name = "nul", nodes = {"0", "1\0junk"}, basis = "lagrange" }
