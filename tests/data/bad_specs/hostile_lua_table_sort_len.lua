-- a table that claims 2^31 - 2 elements (__len), made up in C (__index = rawlen):
-- table.sort does ~2^36 comparisons without running one Lua instruction
table.sort(setmetatable({}, {__len = function() return (1 << 31) - 2 end, __index = rawlen, __newindex = rawequal}))
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
