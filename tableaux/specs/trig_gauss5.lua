-- trig(5) = {1, cos(pi t), sin(pi t), cos(2 pi t), sin(2 pi t)} at the 5
-- Gauss-Legendre nodes.  (trig(4) at 4 symmetric nodes is singular: 1, sin(pi t)
-- and cos(2 pi t) are all symmetric about t = 1/2, and 4 symmetric nodes carry
-- only 2 symmetric values -- vigen says so and names the combination.)
return {
  name = "trig_gauss5",
  description = "Trigonometric basis trig(5) = {1, cos(pi t), sin(pi t), cos(2 pi t), sin(2 pi t)} at the 5 Gauss-Legendre nodes",
  source = "vigen example of a non-polynomial Galerkin space",
  basis = trig(5),
  nodes = gauss_legendre(5),
}
