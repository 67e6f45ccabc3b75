-- table.remove at position 1 shifts #t elements: __len claims 2^40
table.remove(setmetatable({}, {__len = function() return 1 << 40 end}), 1)
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
