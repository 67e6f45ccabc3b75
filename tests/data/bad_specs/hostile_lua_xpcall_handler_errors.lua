-- a handler that raises again at each call, inside a loop
for i = 1, 1e9 do xpcall(function() while true do end end, function(m) error(m) end) end
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
