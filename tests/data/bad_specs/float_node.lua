return { name = "float_node", basis = { "1", "t" }, nodes = { 0, 1/3 } }
