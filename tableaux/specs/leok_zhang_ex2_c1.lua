-- One stage, psi = {1}, c = 1: adjoint symplectic Euler
return {
  name = "leok_zhang_ex2_c1",
  description = "One stage, psi = {1}, c = 1: adjoint symplectic Euler",
  source = "Leok & Zhang, Discrete Hamiltonian variational integrators, IMA J. Numer. Anal. 31 (2011), sec. 4.5, Example 2 (iii)",
  basis = { "1" },
  nodes = { "1" },
}
