-- psi = {1, cos(pi t), sin(pi t)}, c = {0, 1/2, 1}: a second-order method with entries in pi
return {
  name = "leok_zhang_ex4",
  description = "psi = {1, cos(pi t), sin(pi t)}, c = {0, 1/2, 1}: a second-order method with entries in pi",
  source = "Leok & Zhang, Discrete Hamiltonian variational integrators, IMA J. Numer. Anal. 31 (2011), sec. 4.5, Example 4",
  basis = { "1", "cos(pi*t)", "sin(pi*t)" },
  nodes = { "0", "1/2", "1" },
}
