-- each table.unpack moves a million values made up in C
local t = setmetatable({}, {__index = rawlen})
for i = 1, 1e9 do local n = select('#', table.unpack(t, 1, 999000)) end
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
