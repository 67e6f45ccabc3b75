return { name = "bad_expression", basis = { "1", "cosh(t)" }, nodes = { "0", "1" } }
