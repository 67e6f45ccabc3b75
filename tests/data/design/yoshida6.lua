-- Yoshida's sixth-order family: seven steps of position Verlet, symmetric
-- (H. Yoshida, Phys. Lett. A 150 (1990) 262, Table 1: solutions A, B, C).
return { name = "y6", design = "composition", base = "stormer_verlet_position",
         stages = 7, order = 6, symmetric = true, solutions = "all" }
