-- Leok-Zhang Example 5 (iii), recomputed closed forms.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 5 (iii): Lagrange basis at the
-- Chebyshev quadrature nodes (roots of G_3 = (2x^3-x)/2), s = 3.
-- Every entry recomputed with sympy from the construction of docs/math.md (Theorem 3 of Leok & Zhang)
-- (M_ij = psi_i(c_j), B_i = int_0^1 psi_i, Apsi_ij = int_0^c_i psi_j, b =
-- M^-1 B, A = Apsi M^-T, at_ij = (b_i b_j - b_j a_ji)/b_i, ct_i = sum_j
-- at_ij). Reference values for the test suite. Entries that differ from the
-- paper carry a comment.
return {
  name = "leok_zhang_ex5_iii",
  s = 3,
  order = 4,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 5 (iii): Lagrange basis at the Chebyshev quadrature nodes (roots of G_3 = (2x^3-x)/2), s = 3",
  description = "Corrected closed forms of Leok-Zhang Example 5 (iii). The paper prints a_33 = 1/6 - 5*sqrt(2)/48; the construction gives a_33 = int_0^c3 phi_3 = 1/6 - sqrt(2)/48 (then row 3 of A sums to c_3 and b_3 at_33 + b_3 a_33 = b_3^2 holds). All other printed entries are correct.",
  nodes = 'chebyshev_quadrature(3)',
  basis = '"lagrange"',
  c = { "1/2-sqrt(2)/4", "1/2", "1/2+sqrt(2)/4" },
  A = {
    { "1/6+sqrt(2)/48", "1/6-sqrt(2)/6", "1/6-5*sqrt(2)/48" },
    { "1/6+sqrt(2)/8", "1/6", "1/6-sqrt(2)/8" },
    { -- row 3
      "1/6+5*sqrt(2)/48", "1/6+sqrt(2)/6",
      "1/6-sqrt(2)/48", -- paper prints 1/6-5*sqrt(2)/48: row 3 would sum to 1/2+sqrt(2)/6, not c3 = 1/2+sqrt(2)/4, and b3*at33 + b3*a33 - b3^2 = sqrt(2)/36 != 0; int_0^c3 phi_3 = 1/6-sqrt(2)/48
    },
  },
  b = { "1/3", "1/3", "1/3" },
  ct = { "1/2-sqrt(2)/4", "1/2", "1/2+sqrt(2)/4" },
  At = {
    { "1/6-sqrt(2)/48", "1/6-sqrt(2)/8", "1/6-5*sqrt(2)/48" },
    { "1/6+sqrt(2)/6", "1/6", "1/6-sqrt(2)/6" },
    { "1/6+5*sqrt(2)/48", "1/6+sqrt(2)/8", "1/6+sqrt(2)/48" },
  },
}
