-- Leok-Zhang Example 3, recomputed closed forms.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 3: basis psi = {1, cos(pi*t)},
-- quadrature points c = {0, 1}.
-- Every entry recomputed with sympy from the construction of docs/math.md (Theorem 3 of Leok & Zhang)
-- (M_ij = psi_i(c_j), B_i = int_0^1 psi_i, Apsi_ij = int_0^c_i psi_j, b =
-- M^-1 B, A = Apsi M^-T, at_ij = (b_i b_j - b_j a_ji)/b_i, ct_i = sum_j
-- at_ij). Reference values for the test suite. Entries that differ from the
-- paper carry a comment.
return {
  name = "leok_zhang_ex3",
  s = 2,
  order = 2,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 3: basis psi = {1, cos(pi*t)}, quadrature points c = {0, 1}",
  description = "Corrected closed forms of Leok-Zhang Example 3 (Stormer-Verlet = Lobatto IIIA-IIIB, s = 2). The paper prints A~ = [[0,0],[1/2,1/2]]; at_ij = (b_i b_j - b_j a_ji)/b_i with b = (1/2,1/2), A = [[0,0],[1/2,1/2]] gives A~ = [[1/2,0],[1/2,0]] (Lobatto IIIB).",
  nodes = '{"0", "1"}',
  basis = '{"1", "cos(pi*t)"}',
  c = { "0", "1" },
  A = {
    { "0", "0" },
    { "1/2", "1/2" },
  },
  b = { "1/2", "1/2" },
  ct = {
    "1/2", -- not printed; row sum of the printed A~ would be 0
    "1/2", -- not printed; row sum of the printed A~ would be 1
  },
  At = {
    { -- row 1
      "1/2", -- paper prints 0; (b1*b1 - b1*a11)/b1 = b1 - a11 = 1/2
      "0", -- paper prints 0; (b1*b2 - b2*a21)/b1 = 1/2 - 1/2 = 0 (agrees)
    },
    { -- row 2
      "1/2", -- paper prints 1/2; (b2*b1 - b1*a12)/b2 = 1/2 - 0 = 1/2 (agrees)
      "0", -- paper prints 1/2; (b2*b2 - b2*a22)/b2 = b2 - a22 = 0
    },
  },
}
