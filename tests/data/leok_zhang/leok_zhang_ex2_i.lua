-- Leok-Zhang Example 2 (i), recomputed closed forms.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 2 (i): one-stage method, basis
-- psi_1 = 1, quadrature point c_1 = 0.
-- Every entry recomputed with sympy from the construction of docs/math.md (Theorem 3 of Leok & Zhang)
-- (M_ij = psi_i(c_j), B_i = int_0^1 psi_i, Apsi_ij = int_0^c_i psi_j, b =
-- M^-1 B, A = Apsi M^-T, at_ij = (b_i b_j - b_j a_ji)/b_i, ct_i = sum_j
-- at_ij). Reference values for the test suite. Entries that differ from the
-- paper carry a comment.
return {
  name = "leok_zhang_ex2_i",
  s = 1,
  order = 1,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 2 (i): one-stage method, basis psi_1 = 1, quadrature point c_1 = 0",
  description = "Galerkin SPRK method with psi = {1}, c_1 = 0; the paper identifies it as the symplectic Euler method. Printed: b_1 = 1, a_11 = 0, at_11 = 1 (c~ is not printed: row sum of the printed at_11). Recomputed from the construction (docs/math.md, Theorem 3 of Leok & Zhang): every printed entry is correct.",
  nodes = '{"0"}',
  basis = '{"1"}',
  c = { "0" },
  A = {
    { "0" },
  },
  b = { "1" },
  ct = { "1" },
  At = {
    { "1" },
  },
}
