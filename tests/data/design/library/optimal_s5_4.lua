-- Five symmetric steps of position Verlet, order 4: one free parameter,
-- chosen to minimise the checker's error constant (general H).  Suzuki's
-- fractal composition (the library's suzuki_4, gamma_1 = gamma_2 =
-- 1/(4 - 4^(1/3))) is a member of the family; the minimum found is the
-- library's optimal_s5_4.
return { name = "s5", design = "composition", base = "stormer_verlet_position",
         stages = 5, order = 4, symmetric = true, minimize = "error_constant" }
