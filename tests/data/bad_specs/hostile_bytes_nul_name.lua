-- a NUL byte in the name
return { name = "spec\0name", nodes = { "0", "1" }, basis = "lagrange" }
