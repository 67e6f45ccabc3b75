-- A symmetric kernel with two kicks (drift a1, kick 1/2, drift 1 - 2 a1,
-- kick 1/2, drift a1) of effective order 4 for separable H: its condition at
-- h^3, a1^2/2 - a1/4 + 1/24 = 0 up to a factor, has no real root.
return { name = "pk2", design = "processed", kernel = "splitting", stages = 2, order = 4, symmetric = true,
         solutions = "all" }
