-- a NUL byte in a node: refused, not read as "1"
return { name = "nul node", nodes = { "0", "1\0junk" }, basis = "lagrange" }
