-- Implicit midpoint rule, the 1-stage Gauss method (order 2).
return {
  name = "midpoint", s = 1,
  c = { "1/2" }, A = { { "1/2" } }, b = { "1" },
  order = 2, symplectic = true,
}
