-- Leok-Zhang Example 5 (ii), recomputed closed forms.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 5 (ii): Lagrange basis at the
-- Chebyshev quadrature nodes (roots of G_2 = (3x^2-1)/3), s = 2.
-- Every entry recomputed with sympy from the construction of docs/math.md (Theorem 3 of Leok & Zhang)
-- (M_ij = psi_i(c_j), B_i = int_0^1 psi_i, Apsi_ij = int_0^c_i psi_j, b =
-- M^-1 B, A = Apsi M^-T, at_ij = (b_i b_j - b_j a_ji)/b_i, ct_i = sum_j
-- at_ij). Reference values for the test suite. Entries that differ from the
-- paper carry a comment.
return {
  name = "leok_zhang_ex5_ii",
  s = 2,
  order = 4,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 5 (ii): Lagrange basis at the Chebyshev quadrature nodes (roots of G_2 = (3x^2-1)/3), s = 2",
  description = "Two-stage, fourth-order method of Example 5 (the 2-stage Gauss method, A~ = A). Transcribed as printed. Recomputed: every printed entry is correct.",
  nodes = 'chebyshev_quadrature(2)',
  basis = '"lagrange"',
  c = { "1/2-sqrt(3)/6", "1/2+sqrt(3)/6" },
  A = {
    { "1/4", "1/4-sqrt(3)/6" },
    { "1/4+sqrt(3)/6", "1/4" },
  },
  b = { "1/2", "1/2" },
  ct = { "1/2-sqrt(3)/6", "1/2+sqrt(3)/6" },
  At = {
    { "1/4", "1/4-sqrt(3)/6" },
    { "1/4+sqrt(3)/6", "1/4" },
  },
}
