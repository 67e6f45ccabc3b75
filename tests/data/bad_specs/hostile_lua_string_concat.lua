-- each .. copies 64 MiB and the copy is garbage at once: memory stays under the cap
local s = string.rep('x', 1 << 26)
for i = 1, 1e9 do local t = s .. 'y' end
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
