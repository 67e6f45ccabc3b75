-- a NUL byte at the end of A[1][1]
return { name = "nul matrix", s = 1, c = { "1/2" }, A = { { "1/2\0" } }, b = { "1" } }
