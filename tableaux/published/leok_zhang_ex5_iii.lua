-- Leok-Zhang Example 5 (iii), as printed.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 5 (iii): Lagrange basis at the
-- Chebyshev quadrature nodes (roots of G_3 = (2x^3-x)/2), s = 3.
-- Transcribed exactly as printed in the paper, misprints included: this file
-- is a test input for `vigen check`. The recomputed closed forms are in
-- tests/data/leok_zhang/leok_zhang_ex5_iii.lua and the misprints are listed
-- in docs/published.md.
-- PRK convention (docs/math.md): (c, A, b) for dH/dp (q-equation), (c~, A~,
-- b) for -dH/dq (p-equation).
return {
  name = "leok_zhang_ex5_iii",
  s = 3,
  order = 4,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 5 (iii): Lagrange basis at the Chebyshev quadrature nodes (roots of G_3 = (2x^3-x)/2), s = 3",
  description = "Three-stage, fourth-order method of Example 5. Transcribed as printed, including the misprinted a_33 = 1/6 - 5*sqrt(2)/48 (correct: 1/6 - sqrt(2)/48).",
  nodes = 'chebyshev_quadrature(3)',
  basis = '"lagrange"',
  c = { "1/2-sqrt(2)/4", "1/2", "1/2+sqrt(2)/4" },
  A = {
    { "1/6+sqrt(2)/48", "1/6-sqrt(2)/6", "1/6-5*sqrt(2)/48" },
    { "1/6+sqrt(2)/8", "1/6", "1/6-sqrt(2)/8" },
    { "1/6+5*sqrt(2)/48", "1/6+sqrt(2)/6", "1/6-5*sqrt(2)/48" },
  },
  b = { "1/3", "1/3", "1/3" },
  ct = { "1/2-sqrt(2)/4", "1/2", "1/2+sqrt(2)/4" },
  At = {
    { "1/6-sqrt(2)/48", "1/6-sqrt(2)/8", "1/6-5*sqrt(2)/48" },
    { "1/6+sqrt(2)/6", "1/6", "1/6-sqrt(2)/6" },
    { "1/6+5*sqrt(2)/48", "1/6+sqrt(2)/8", "1/6+sqrt(2)/48" },
  },
}
