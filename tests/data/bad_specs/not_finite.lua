return { name = "not_finite", basis = { "1", "1/t" }, nodes = { "0", "1" } }
