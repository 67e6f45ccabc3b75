-- Order 6 from five symmetric steps: four conditions on three unknowns.
return { name = "s5o6", design = "composition", base = "stormer_verlet_position",
         stages = 5, order = 6, symmetric = true, solutions = "all" }
