-- Gauss method, s = 2, order 4, as a partitioned RK method with A~ = A.
-- E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
-- Springer 1996, Sect. IV.5, Table 5.1 (Gauss method of order 4; Hammer &
-- Hollingsworth 1955); E. Hairer, C. Lubich, G. Wanner, Geometric Numerical
-- Integration, 2nd ed., Springer 2006, Theorem VI.4.3 (symplectic).
return {
  name = "gauss_2",
  s = 2,
  order = 4,
  symplectic = true,
  source = "E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed., Springer 1996, Sect. IV.5, Table 5.1 (Gauss method of order 4; Hammer & Hollingsworth 1955); E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Theorem VI.4.3 (symplectic)",
  description = "2-stage Gauss(-Legendre) collocation method of order 4 used as a PRK method with A~ = A (the same Runge-Kutta method for q and p). Exact entries.",
  nodes = 'gauss_legendre(2)',
  basis = '"lagrange"',
  c = { "1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6" },
  A = {
    { "1/4", "1/4 - sqrt(3)/6" },
    { "1/4 + sqrt(3)/6", "1/4" },
  },
  b = { "1/2", "1/2" },
  ct = { "1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6" },
  At = {
    { "1/4", "1/4 - sqrt(3)/6" },
    { "1/4 + sqrt(3)/6", "1/4" },
  },
}
