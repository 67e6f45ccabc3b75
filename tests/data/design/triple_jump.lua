-- The triple jump: three steps of velocity Verlet, symmetric, order 4
-- (Yoshida 1990; Suzuki 1990; Creutz and Gocksch 1989).
return { name = "tj", design = "composition", base = "stormer_verlet_velocity",
         stages = 3, order = 4, symmetric = true, solutions = "all" }
