-- Gauss method, s = 1, order 2, as a partitioned RK method with A~ = A.
-- E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
-- Springer 1996, Sect. IV.5 (the implicit midpoint rule, Gauss method with s
-- = 1); E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd
-- ed., Springer 2006, Sect. II.1.3 and Theorem VI.4.3 (symplectic).
return {
  name = "gauss_1",
  s = 1,
  order = 2,
  symplectic = true,
  source = "E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed., Springer 1996, Sect. IV.5 (the implicit midpoint rule, Gauss method with s = 1); E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Sect. II.1.3 and Theorem VI.4.3 (symplectic)",
  description = "1-stage Gauss(-Legendre) collocation method of order 2 used as a PRK method with A~ = A (the same Runge-Kutta method for q and p). Exact entries.",
  nodes = 'gauss_legendre(1)',
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
