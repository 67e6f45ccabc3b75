-- Leok-Zhang Example 4, as printed.
-- M. Leok, J. Zhang, "Discrete Hamiltonian variational integrators",
-- arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here
-- (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not
-- examined); Section 4.5 "Examples", Example 4: basis psi = {1, cos(pi*t),
-- sin(pi*t)}, quadrature points c = {0, 1/2, 1}.
-- Transcribed exactly as printed in the paper, misprints included: this file
-- is a test input for `vigen check`. The recomputed closed forms are in
-- tests/data/leok_zhang/leok_zhang_ex4.lua and the misprints are listed in
-- docs/published.md.
-- PRK convention (docs/math.md): (c, A, b) for dH/dp (q-equation), (c~, A~,
-- b) for -dH/dq (p-equation).
return {
  name = "leok_zhang_ex4",
  s = 3,
  order = 2,
  symplectic = true,
  source = "M. Leok, J. Zhang, \"Discrete Hamiltonian variational integrators\", arXiv:1001.1408v1 [math.NA] (9 Jan 2010), the version transcribed here (journal version: IMA J. Numer. Anal., 2011, doi:10.1093/imanum/drq027, not examined); Section 4.5 \"Examples\", Example 4: basis psi = {1, cos(pi*t), sin(pi*t)}, quadrature points c = {0, 1/2, 1}",
  description = "Galerkin SPRK method with trigonometric basis psi = {1, cos(pi*t), sin(pi*t)} at c = {0, 1/2, 1}; the paper calls it a new second-order method. Transcribed as printed.",
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
