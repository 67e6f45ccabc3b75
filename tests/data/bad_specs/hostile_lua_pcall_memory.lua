-- pcall swallowing the memory cap, over and over
for i = 1, 1e9 do pcall(string.rep, 'x', 1 << 30) end
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
