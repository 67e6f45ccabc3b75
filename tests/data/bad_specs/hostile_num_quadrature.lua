-- exp(t^2) has no closed-form integral: its quadrature costs about the cube
-- of the precision, so --digits 100000 used to run for hours.  vigen caps
-- quadrature at 1/16 of --max-prec (exit 3).
return { name = "hostile_num_quadrature", nodes = { "0", "1" }, basis = { "1", "exp(t^2)" } }
