-- Gauss method, s = 3, order 6, as a partitioned RK method with A~ = A.
-- E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
-- Springer 1996, Sect. IV.5, Table 5.2 (Gauss method of order 6; Kuntzmann
-- 1961, Butcher 1964); E. Hairer, C. Lubich, G. Wanner, Geometric Numerical
-- Integration, 2nd ed., Springer 2006, Theorem VI.4.3 (symplectic).
return {
  name = "gauss_3",
  s = 3,
  order = 6,
  symplectic = true,
  source = "E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed., Springer 1996, Sect. IV.5, Table 5.2 (Gauss method of order 6; Kuntzmann 1961, Butcher 1964); E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Theorem VI.4.3 (symplectic)",
  description = "3-stage Gauss(-Legendre) collocation method of order 6 used as a PRK method with A~ = A (the same Runge-Kutta method for q and p). Exact entries.",
  nodes = 'gauss_legendre(3)',
  basis = '"lagrange"',
  c = { "1/2 - sqrt(15)/10", "1/2", "1/2 + sqrt(15)/10" },
  A = {
    { "5/36", "2/9 - sqrt(15)/15", "5/36 - sqrt(15)/30" },
    { "5/36 + sqrt(15)/24", "2/9", "5/36 - sqrt(15)/24" },
    { "5/36 + sqrt(15)/30", "2/9 + sqrt(15)/15", "5/36" },
  },
  b = { "5/18", "4/9", "5/18" },
  ct = { "1/2 - sqrt(15)/10", "1/2", "1/2 + sqrt(15)/10" },
  At = {
    { "5/36", "2/9 - sqrt(15)/15", "5/36 - sqrt(15)/30" },
    { "5/36 + sqrt(15)/24", "2/9", "5/36 - sqrt(15)/24" },
    { "5/36 + sqrt(15)/30", "2/9 + sqrt(15)/15", "5/36" },
  },
}
