-- Leok-Zhang Example 4, recomputed closed forms.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 4: basis psi = {1, cos(pi*t),
-- sin(pi*t)}, quadrature points c = {0, 1/2, 1}.
-- Every entry recomputed with sympy from the construction of docs/math.md (Theorem 3 of Leok & Zhang)
-- (M_ij = psi_i(c_j), B_i = int_0^1 psi_i, Apsi_ij = int_0^c_i psi_j, b =
-- M^-1 B, A = Apsi M^-T, at_ij = (b_i b_j - b_j a_ji)/b_i, ct_i = sum_j
-- at_ij). Reference values for the test suite. Entries that differ from the
-- paper carry a comment.
return {
  name = "leok_zhang_ex4",
  s = 3,
  order = 2,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 4: basis psi = {1, cos(pi*t), sin(pi*t)}, quadrature points c = {0, 1/2, 1}",
  description = "Closed forms of Leok-Zhang Example 4 recomputed from the construction with sympy: every printed entry (c, A, b, c~, A~) is correct; this file equals the printed one.",
  nodes = '{"0", "1/2", "1"}',
  basis = '{"1", "cos(pi*t)", "sin(pi*t)"}',
  c = { "0", "1/2", "1" },
  A = {
    { "0", "0", "0" },
    { "1/4", "1/pi", "(pi-4)/(4*pi)" },
    { "(pi-2)/(2*pi)", "2/pi", "(pi-2)/(2*pi)" },
  },
  b = { "(pi-2)/(2*pi)", "2/pi", "(pi-2)/(2*pi)" },
  ct = { "(pi^2-2*pi-4)/(2*pi^2-4*pi)", "1/2", "(pi^2-2*pi+4)/(2*pi^2-4*pi)" },
  At = {
    { "(pi-2)/(2*pi)", "(pi-4)/(pi^2-2*pi)", "0" },
    { "(pi-2)/(2*pi)", "1/pi", "0" },
    { "(pi-2)/(2*pi)", "1/(pi-2)", "0" },
  },
}
