-- a NUL byte in the name: refused, not shown as "gauss"
return { name = "gauss\0hidden", s = 1, c = { "1/2" }, A = { { "1/2" } }, b = { "1" } }
