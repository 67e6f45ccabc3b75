-- Leok-Zhang Example 2 (i), as printed.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 2 (i): one-stage method, basis
-- psi_1 = 1, quadrature point c_1 = 0.
-- Transcribed exactly as printed in the paper, misprints included: this file
-- is a test input for `vigen check`. The recomputed closed forms are in
-- tests/data/leok_zhang/leok_zhang_ex2_i.lua and the misprints are listed in
-- docs/published.md.
-- PRK convention (docs/math.md): (c, A, b) for dH/dp (q-equation), (c~, A~,
-- b) for -dH/dq (p-equation).
return {
  name = "leok_zhang_ex2_i",
  s = 1,
  order = 1,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 2 (i): one-stage method, basis psi_1 = 1, quadrature point c_1 = 0",
  description = "Galerkin SPRK method with psi = {1}, c_1 = 0; the paper identifies it as the symplectic Euler method. Printed: b_1 = 1, a_11 = 0, at_11 = 1 (c~ is not printed: row sum of the printed at_11).",
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
