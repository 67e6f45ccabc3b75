-- table.move over 2^40 elements: one instruction, a loop in C
table.move({}, 1, 1 << 40, 2)
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
