-- pcall in a loop, swallowing the instruction cap each time
local n = 0
while true do n = n + 1; pcall(function() while true do end end) end
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
