-- a node outside [0, 1] is allowed with a warning
return { name = "node_outside", basis = { "1", "t" }, nodes = { "0", "3/2" } }
