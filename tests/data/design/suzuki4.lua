-- Suzuki's fractal composition of order 4: five symmetric steps of a
-- second-order method with the first two equal, gamma1 = gamma2 = p,
-- gamma3 = 1 - 4p, 4p^3 + (1 - 4p)^3 = 0 (Suzuki 1990): with the tie the
-- order conditions [Y1], [Y3] leave finitely many solutions.
return { name = "suzuki", design = "composition", base = "stormer_verlet_position", stages = 5, order = 4,
         symmetric = true, equal = { { "gamma1", "gamma2" } }, solutions = "all" }
