-- a method file must return a table
return "gauss_legendre(2)"
