io.open("/tmp/vigen-escape", "w")
return { name = "escape_io", basis = "lagrange", nodes = gauss_legendre(1) }
