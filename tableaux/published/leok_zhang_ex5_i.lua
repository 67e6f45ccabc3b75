-- Leok-Zhang Example 5 (i), as printed.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 5 (i): Lagrange basis at the
-- Chebyshev equal-weight quadrature node (root of G_1 = x), s = 1.
-- Transcribed exactly as printed in the paper, misprints included: this file
-- is a test input for `vigen check`. The recomputed closed forms are in
-- tests/data/leok_zhang/leok_zhang_ex5_i.lua and the misprints are listed in
-- docs/published.md.
-- PRK convention (docs/math.md): (c, A, b) for dH/dp (q-equation), (c~, A~,
-- b) for -dH/dq (p-equation).
return {
  name = "leok_zhang_ex5_i",
  s = 1,
  order = 2,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 5 (i): Lagrange basis at the Chebyshev equal-weight quadrature node (root of G_1 = x), s = 1",
  description = "One-stage, second-order method of Example 5 (the midpoint rule). Transcribed as printed.",
  nodes = 'chebyshev_quadrature(1)',
  basis = '"lagrange"',
  c = { "1/2" },
  A = {
    { "1/2" },
  },
  b = { "1" },
  ct = { "1/2" },
  At = {
    { "1/2" },
  },
}
