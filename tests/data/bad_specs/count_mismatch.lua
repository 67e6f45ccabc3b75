return { name = "count_mismatch", basis = { "1", "t" }, nodes = { "0" } }
