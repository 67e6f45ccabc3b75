-- pcall inside pcall inside xpcall, each wanting to carry on
for i = 1, 1e9 do
  xpcall(pcall, function() while true do end end, pcall, function() while true do end end)
end
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
