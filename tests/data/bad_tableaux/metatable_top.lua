return setmetatable({ name = "x", s = 1, c = { "1/2" }, A = { { "1/2" } }, b = { "1" } }, { __index = function() error("boom") end })
