return {
  name = "syntax_error",
  basis = "lagrange"
  nodes = gauss_legendre(2),
}
