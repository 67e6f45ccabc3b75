-- Lobatto IIIA-IIIB pair, s = 4, order 6.
-- E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
-- Springer 1996, Sect. IV.5 (Lobatto IIIA and IIIB methods, Ehle 1969); E.
-- Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed.,
-- Springer 2006, Sect. II.2.2 "Lobatto IIIA-IIIB pairs" and Theorem VI.4.6
-- (symplectic PRK); L. Jay, SIAM J. Numer. Anal. 33 (1996) 368-387; Sun Geng,
-- J. Comput. Math. 11 (1993) 365-372.
return {
  name = "lobatto_iiia_iiib_4",
  s = 4,
  order = 6,
  symplectic = true,
  source = "E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed., Springer 1996, Sect. IV.5 (Lobatto IIIA and IIIB methods, Ehle 1969); E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Sect. II.2.2 \"Lobatto IIIA-IIIB pairs\" and Theorem VI.4.6 (symplectic PRK); L. Jay, SIAM J. Numer. Anal. 33 (1996) 368-387; Sun Geng, J. Comput. Math. 11 (1993) 365-372",
  description = "4-stage Lobatto IIIA-IIIB pair of order 6: A = Lobatto IIIA (q), A~ = Lobatto IIIB (p). Exact entries.",
  nodes = 'gauss_lobatto(4)',
  basis = '"lagrange"',
  c = { "0", "1/2 - sqrt(5)/10", "1/2 + sqrt(5)/10", "1" },
  A = {
    { "0", "0", "0", "0" },
    { "(11 + sqrt(5))/120", "(25 - sqrt(5))/120", "(25 - 13*sqrt(5))/120", "(-1 + sqrt(5))/120" },
    { "(11 - sqrt(5))/120", "(25 + 13*sqrt(5))/120", "(25 + sqrt(5))/120", "(-1 - sqrt(5))/120" },
    { "1/12", "5/12", "5/12", "1/12" },
  },
  b = { "1/12", "5/12", "5/12", "1/12" },
  ct = { "0", "1/2 - sqrt(5)/10", "1/2 + sqrt(5)/10", "1" },
  At = {
    { "1/12", "(-1 - sqrt(5))/24", "(-1 + sqrt(5))/24", "0" },
    { "1/12", "(25 + sqrt(5))/120", "(25 - 13*sqrt(5))/120", "0" },
    { "1/12", "(25 + 13*sqrt(5))/120", "(25 - sqrt(5))/120", "0" },
    { "1/12", "(11 - sqrt(5))/24", "(11 + sqrt(5))/24", "0" },
  },
}
