return { name = "float_in_function", basis = { "1", function(t) return (1/3) * t end }, nodes = { "0", "1" } }
