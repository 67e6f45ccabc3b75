-- the instruction cap is reached inside f; Lua runs the message handler with hooks off,
-- so a handler that never returns would run forever
xpcall(function() while true do end end, function(m) while true do end end)
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
