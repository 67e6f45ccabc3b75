local function h() return xpcall(h, h) end
xpcall(function() while true do end end, h)
return { name = "x", nodes = gauss_legendre(2), basis = "lagrange" }
