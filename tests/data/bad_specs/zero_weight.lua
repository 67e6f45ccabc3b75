-- Lagrange at 1/2 -+ sqrt(3)/6 and 1/2: the middle weight is int (t-1/2)^2 - 1/12 = 0
return { name = "zero_weight", basis = "lagrange", nodes = { "1/2 - sqrt(3)/6", "1/2", "1/2 + sqrt(3)/6" } }
