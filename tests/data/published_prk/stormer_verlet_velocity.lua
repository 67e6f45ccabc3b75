-- stormer verlet velocity: Stormer-Verlet, p-first ("velocity Verlet",
-- kick-drift-kick): p_{1/2} = p0 - h/2 dH/dq(q0, p_{1/2}), q1 = q0 + h/2
-- (dH/dp(q0, p_{1/2}) + dH/dp(q1, p_{1/2})), p1 = p_{1/2} - h/2 dH/dq(q1,
-- p_{1/2}). A = Lobatto IIIA, A~ = Lobatto IIIB (s = 2).
-- E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed.,
-- Springer 2006, Sect. VI.3 "First examples of symplectic integrators"
-- (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods); E. Hairer, C.
-- Lubich, G. Wanner, Acta Numerica 12 (2003) 399-450, Sect. 1.
return {
  name = "stormer_verlet_velocity",
  s = 2,
  order = 2,
  symplectic = true,
  source = "E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Sect. VI.3 \"First examples of symplectic integrators\" (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods); E. Hairer, C. Lubich, G. Wanner, Acta Numerica 12 (2003) 399-450, Sect. 1",
  description = "Stormer-Verlet, p-first (\"velocity Verlet\", kick-drift-kick): p_{1/2} = p0 - h/2 dH/dq(q0, p_{1/2}), q1 = q0 + h/2 (dH/dp(q0, p_{1/2}) + dH/dp(q1, p_{1/2})), p1 = p_{1/2} - h/2 dH/dq(q1, p_{1/2}). A = Lobatto IIIA, A~ = Lobatto IIIB (s = 2).",
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
