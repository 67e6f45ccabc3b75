-- Leok-Zhang Example 5 (ii), as printed.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 5 (ii): Lagrange basis at the
-- Chebyshev quadrature nodes (roots of G_2 = (3x^2-1)/3), s = 2.
-- Transcribed exactly as printed in the paper, misprints included: this file
-- is a test input for `vigen check`. The recomputed closed forms are in
-- tests/data/leok_zhang/leok_zhang_ex5_ii.lua and the misprints are listed in
-- docs/published.md.
-- PRK convention (docs/math.md): (c, A, b) for dH/dp (q-equation), (c~, A~,
-- b) for -dH/dq (p-equation).
return {
  name = "leok_zhang_ex5_ii",
  s = 2,
  order = 4,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 5 (ii): Lagrange basis at the Chebyshev quadrature nodes (roots of G_2 = (3x^2-1)/3), s = 2",
  description = "Two-stage, fourth-order method of Example 5 (the 2-stage Gauss method, A~ = A). Transcribed as printed.",
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
