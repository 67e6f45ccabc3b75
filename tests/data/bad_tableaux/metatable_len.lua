return { name = "x", s = 1, c = setmetatable({}, { __len = function() while true do end end }), A = { { "1/2" } }, b = { "1" } }
