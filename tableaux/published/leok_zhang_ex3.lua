-- Leok-Zhang Example 3, as printed.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 3: basis psi = {1, cos(pi*t)},
-- quadrature points c = {0, 1}.
-- Transcribed exactly as printed in the paper, misprints included: this file
-- is a test input for `vigen check`. The recomputed closed forms are in
-- tests/data/leok_zhang/leok_zhang_ex3.lua and the misprints are listed in
-- docs/published.md.
-- PRK convention (docs/math.md): (c, A, b) for dH/dp (q-equation), (c~, A~,
-- b) for -dH/dq (p-equation).
return {
  name = "leok_zhang_ex3",
  s = 2,
  order = 2,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 3: basis psi = {1, cos(pi*t)}, quadrature points c = {0, 1}",
  description = "Galerkin SPRK method with psi = {1, cos(pi*t)} and c = {0, 1}; the paper says it is the Stormer-Verlet method. Transcribed as printed, including the misprinted A~ = [[0,0],[1/2,1/2]] (which is A itself, i.e. the non-symplectic trapezoidal rule for p). c~ is not printed: row sums of the printed A~.",
  nodes = '{"0", "1"}',
  basis = '{"1", "cos(pi*t)"}',
  c = { "0", "1" },
  A = {
    { "0", "0" },
    { "1/2", "1/2" },
  },
  b = { "1/2", "1/2" },
  ct = { "0", "1" },
  At = {
    { "0", "0" },
    { "1/2", "1/2" },
  },
}
