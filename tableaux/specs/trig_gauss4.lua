-- Trigonometric basis {1, cos(pi t), sin(pi t), cos(2 pi t)} at the 4 Gauss-Legendre nodes
return {
  name = "trig_gauss4",
  description = "Trigonometric basis {1, cos(pi t), sin(pi t), cos(2 pi t)} at the 4 Gauss-Legendre nodes",
  source = "vigen example of a non-polynomial Galerkin space",
  basis = trig(4),
  nodes = gauss_legendre(4),
}
