-- a NUL byte in a basis expression
return { name = "nul basis", nodes = { "0", "1" }, basis = { "1", "t\0junk" } }
