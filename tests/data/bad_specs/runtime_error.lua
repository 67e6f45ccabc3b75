local n = 2
error("this spec fails on purpose")
return { name = "runtime_error", basis = "lagrange", nodes = gauss_legendre(n) }
