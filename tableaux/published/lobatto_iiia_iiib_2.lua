-- Lobatto IIIA-IIIB pair, s = 2, order 2.
-- E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
-- Springer 1996, Sect. IV.5 (Lobatto IIIA and IIIB methods, Ehle 1969); E.
-- Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed.,
-- Springer 2006, Sect. II.2.2 "Lobatto IIIA-IIIB pairs" and Theorem VI.4.6
-- (symplectic PRK); L. Jay, SIAM J. Numer. Anal. 33 (1996) 368-387; Sun Geng,
-- J. Comput. Math. 11 (1993) 365-372.
return {
  name = "lobatto_iiia_iiib_2",
  s = 2,
  order = 2,
  symplectic = true,
  source = "E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed., Springer 1996, Sect. IV.5 (Lobatto IIIA and IIIB methods, Ehle 1969); E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Sect. II.2.2 \"Lobatto IIIA-IIIB pairs\" and Theorem VI.4.6 (symplectic PRK); L. Jay, SIAM J. Numer. Anal. 33 (1996) 368-387; Sun Geng, J. Comput. Math. 11 (1993) 365-372",
  description = "2-stage Lobatto IIIA-IIIB pair of order 2: A = Lobatto IIIA (q), A~ = Lobatto IIIB (p). For s = 2 this is the Stormer-Verlet method (p-first, velocity form). Exact entries.",
  nodes = 'gauss_lobatto(2)',
  basis = '"lagrange"',
  c = { "0", "1" },
  A = {
    { "0", "0" },
    { "1/2", "1/2" },
  },
  b = { "1/2", "1/2" },
  ct = { "1/2", "1/2" },
  At = {
    { "1/2", "0" },
    { "1/2", "0" },
  },
}
