-- McLachlan and Atela's optimal three-stage third-order method (Nonlinearity
-- 5 (1992) 541, Table 2): kick, drift, kick, drift, kick, drift (the first
-- drift of the splitting family is 0), order 3 for separable H, one free
-- parameter, chosen to minimise the norm of the principal error (its
-- coefficients on a basis of the brackets of degree 4).
return { name = "ma3", design = "splitting", stages = 3, order = 3, first = "kick",
         stationary = "error_norm", starts = 400 }
