-- xpcall swallows the memory cap (memory errors skip the handler) and the file carries on
xpcall(function() local t = {} for i = 1, 1e9 do t[i] = {i} end end, function(m) return 1 end)
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
