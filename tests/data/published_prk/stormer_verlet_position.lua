-- stormer verlet position: Stormer-Verlet, q-first ("position Verlet",
-- drift-kick-drift): q_{1/2} = q0 + h/2 dH/dp(q_{1/2}, p0), p1 = p0 - h/2
-- (dH/dq(q_{1/2}, p0) + dH/dq(q_{1/2}, p1)), q1 = q_{1/2} + h/2
-- dH/dp(q_{1/2}, p1). A = Lobatto IIIB, A~ = Lobatto IIIA (s = 2).
-- E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed.,
-- Springer 2006, Sect. VI.3 "First examples of symplectic integrators"
-- (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods); E. Hairer, C.
-- Lubich, G. Wanner, Acta Numerica 12 (2003) 399-450, Sect. 1.
return {
  name = "stormer_verlet_position",
  s = 2,
  order = 2,
  symplectic = true,
  source = "E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Sect. VI.3 \"First examples of symplectic integrators\" (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods); E. Hairer, C. Lubich, G. Wanner, Acta Numerica 12 (2003) 399-450, Sect. 1",
  description = "Stormer-Verlet, q-first (\"position Verlet\", drift-kick-drift): q_{1/2} = q0 + h/2 dH/dp(q_{1/2}, p0), p1 = p0 - h/2 (dH/dq(q_{1/2}, p0) + dH/dq(q_{1/2}, p1)), q1 = q_{1/2} + h/2 dH/dp(q_{1/2}, p1). A = Lobatto IIIB, A~ = Lobatto IIIA (s = 2).",
  c = { "1/2", "1/2" },
  A = {
    { "1/2", "0" },
    { "1/2", "0" },
  },
  b = { "1/2", "1/2" },
  ct = { "0", "1" },
  At = {
    { "0", "0" },
    { "1/2", "1/2" },
  },
}
