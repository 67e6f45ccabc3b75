-- psi = {1, cos(pi t)}, c = {0, 1}: Stormer-Verlet
return {
  name = "leok_zhang_ex3",
  description = "psi = {1, cos(pi t)}, c = {0, 1}: Stormer-Verlet",
  source = "Leok & Zhang, Discrete Hamiltonian variational integrators, IMA J. Numer. Anal. 31 (2011), sec. 4.5, Example 3",
  basis = { "1", "cos(pi*t)" },
  nodes = { "0", "1" },
}
