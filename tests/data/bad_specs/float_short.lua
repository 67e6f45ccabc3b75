-- a short Lua float inside a basis function: the message suggests that exact value
return { name = "float_short", basis = { "1", function(t) return t + 0.5 end }, nodes = { "0", "1" } }
