return { name = "f", nodes = gauss_legendre(2), basis = { "1", function(t) return t * t end } }
