-- string.rep of an empty string loops in C, outside the instruction cap
local s = string.rep("", 1 << 50)
local big = string.rep("x", 1 << 40)
return { name = "rep_hang", basis = "lagrange", nodes = gauss_legendre(2) }
