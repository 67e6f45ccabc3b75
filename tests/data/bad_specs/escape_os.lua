os.execute("touch /tmp/vigen-escape")
return { name = "escape_os", basis = "lagrange", nodes = gauss_legendre(1) }
