-- table.insert at position 1 shifts #t elements: __len claims 2^40
table.insert(setmetatable({}, {__len = function() return 1 << 40 end}), 1, 'x')
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
