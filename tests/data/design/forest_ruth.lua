-- Symmetric splittings with three kicks (drift, kick, ..., kick, drift),
-- order 4 for separable H: Forest and Ruth's method (Physica D 43 (1990)
-- 105), the triple jump of position Verlet written as kicks and drifts.
return { name = "fr", design = "splitting", stages = 3, order = 4, symmetric = true, solutions = "all" }
