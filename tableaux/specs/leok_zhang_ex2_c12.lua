-- One stage, psi = {1}, c = 1/2: the midpoint rule
return {
  name = "leok_zhang_ex2_c12",
  description = "One stage, psi = {1}, c = 1/2: the midpoint rule",
  source = "Leok & Zhang, Discrete Hamiltonian variational integrators, IMA J. Numer. Anal. 31 (2011), sec. 4.5, Example 2 (ii)",
  basis = { "1" },
  nodes = { "1/2" },
}
