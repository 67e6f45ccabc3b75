-- One stage, psi = {1}, c = 0: symplectic Euler
return {
  name = "leok_zhang_ex2_c0",
  description = "One stage, psi = {1}, c = 0: symplectic Euler",
  source = "Leok & Zhang, Discrete Hamiltonian variational integrators, IMA J. Numer. Anal. 31 (2011), sec. 4.5, Example 2 (i)",
  basis = { "1" },
  nodes = { "0" },
}
