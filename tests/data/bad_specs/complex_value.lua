return { name = "complex_value", basis = { "1", "sqrt(t - 2)" }, nodes = { "0", "1" } }
