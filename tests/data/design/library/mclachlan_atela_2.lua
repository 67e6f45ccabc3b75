-- McLachlan and Atela's optimal two-stage second-order method (Nonlinearity
-- 5 (1992) 541, Table 2): kick, drift, kick, drift (the first drift of the
-- splitting family is 0), order 2 for separable H, one free parameter,
-- chosen to minimise the norm of the principal error (its coefficients on a
-- basis of the brackets of degree 3).
return { name = "ma2", design = "splitting", stages = 2, order = 2, first = "kick",
         stationary = "error_norm", starts = 200 }
