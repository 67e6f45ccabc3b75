-- the handler turns the cap's error into a table whose __tostring never returns
local hang = setmetatable({}, {__tostring = function() while true do end end})
local ok, e = xpcall(function() while true do end end, function() return hang end)
error(e)
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
