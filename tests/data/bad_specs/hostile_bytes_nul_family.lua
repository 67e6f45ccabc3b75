-- a NUL byte after a basis name: refused, not read as "lagrange"
return { name = "nul family", nodes = { "0", "1" }, basis = "lagrange\0junk" }
