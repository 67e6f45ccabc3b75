return { name = "zero_exprs", s = 1, c = { "sin(pi)" }, A = { { "sqrt(2)^2 - 2" } }, b = { "1" } }
