-- select is called with 400,000 arguments over and over
local function f(...) for i = 1, 1e9 do local n = select('#', ...) end end
f(string.byte(string.rep('x', 400000), 1, -1))
return { name = "hostile", basis = "lagrange", nodes = gauss_legendre(2) }
