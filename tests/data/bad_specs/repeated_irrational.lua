-- equal but not exactly representable: the balls never separate
return { name = "repeated_irrational", basis = { "1", "t" }, nodes = { "1/3", "sqrt(1/9)" } }
