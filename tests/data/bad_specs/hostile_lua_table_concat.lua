-- table.concat over 2^40 positions whose values __index makes up in C
table.concat(setmetatable({}, {__index = rawlen}), '', 1, 1 << 40)
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
