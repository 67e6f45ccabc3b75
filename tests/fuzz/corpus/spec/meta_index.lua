return setmetatable({ name = "m" }, { __index = function(t, k) return gauss_legendre(2) end })
