-- Lobatto IIIA-IIIB pair, s = 3, order 4.
-- E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
-- Springer 1996, Sect. IV.5 (Lobatto IIIA and IIIB methods, Ehle 1969); E.
-- Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed.,
-- Springer 2006, Sect. II.2.2 "Lobatto IIIA-IIIB pairs" and Theorem VI.4.6
-- (symplectic PRK); L. Jay, SIAM J. Numer. Anal. 33 (1996) 368-387; Sun Geng,
-- J. Comput. Math. 11 (1993) 365-372.
return {
  name = "lobatto_iiia_iiib_3",
  s = 3,
  order = 4,
  symplectic = true,
  source = "E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed., Springer 1996, Sect. IV.5 (Lobatto IIIA and IIIB methods, Ehle 1969); E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Sect. II.2.2 \"Lobatto IIIA-IIIB pairs\" and Theorem VI.4.6 (symplectic PRK); L. Jay, SIAM J. Numer. Anal. 33 (1996) 368-387; Sun Geng, J. Comput. Math. 11 (1993) 365-372",
  description = "3-stage Lobatto IIIA-IIIB pair of order 4: A = Lobatto IIIA (q), A~ = Lobatto IIIB (p). Exact entries.",
  nodes = 'gauss_lobatto(3)',
  basis = '"lagrange"',
  c = { "0", "1/2", "1" },
  A = {
    { "0", "0", "0" },
    { "5/24", "1/3", "-1/24" },
    { "1/6", "2/3", "1/6" },
  },
  b = { "1/6", "2/3", "1/6" },
  ct = { "0", "1/2", "1" },
  At = {
    { "1/6", "-1/6", "0" },
    { "1/6", "1/3", "0" },
    { "1/6", "5/6", "0" },
  },
}
