-- Symmetric RKN splittings with seven kicks, order 6 for Nystrom H
-- (T = p^2/2): 8 conditions in 8 unknowns, where separable H asks 10.
return { name = "rkn6", design = "rkn", stages = 7, order = 6, symmetric = true, solutions = "all" }
