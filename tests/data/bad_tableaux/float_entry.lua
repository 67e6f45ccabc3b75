return { name = "x", s = 1, c = { 0.5 }, A = { { "1/2" } }, b = { "1" } }
