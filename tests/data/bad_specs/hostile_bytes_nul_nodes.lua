-- a NUL byte after a node family name
return { name = "nul nodes", nodes = "gauss_legendre\0junk", basis = "lagrange" }
