return { name = "x", s = 1, c = { "1/2" }, A = { { "cosh(1)" } }, b = { "1" } }
