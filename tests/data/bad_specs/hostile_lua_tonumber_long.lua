-- tonumber scans a 64 MiB string each time
local s = string.rep('0', 1 << 26)
for i = 1, 1e9 do local x = tonumber(s) end
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
