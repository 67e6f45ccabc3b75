return { name = "repeated_nodes", basis = { "1", "t" }, nodes = { "1/2", "2/4" } }
