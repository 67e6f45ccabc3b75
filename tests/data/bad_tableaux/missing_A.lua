return { name = "x", s = 1, c = { "1/2" }, b = { "1" } }
