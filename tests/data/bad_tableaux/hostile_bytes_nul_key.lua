-- a field "A\0x" is not the field "A": an unknown field
return { name = "nul key", s = 1, c = { "1/2" }, A = { { "1/2" } }, b = { "1" }, ["A\0x"] = { { "1" } } }
