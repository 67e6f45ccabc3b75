-- each string.byte returns a million values
local s = string.rep('x', 999000)
for i = 1, 1e9 do local n = select('#', s:byte(1, -1)) end
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
