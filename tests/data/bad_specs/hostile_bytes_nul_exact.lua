-- a NUL byte in an expression string of a Lua basis function
return { name = "nul exact", nodes = { "0", "1" }, basis = { "1", function(t) return t * exact("1\0junk") end } }
