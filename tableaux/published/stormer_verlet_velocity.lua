-- stormer verlet velocity: Stormer-Verlet, p-first ("velocity Verlet",
-- kick-drift-kick): p_{1/2} = p0 - h/2 dH/dq(q0, p_{1/2}), q1 = q0 + h/2
-- (dH/dp(q0, p_{1/2}) + dH/dp(q1, p_{1/2})), p1 = p_{1/2} - h/2 dH/dq(q1,
-- p_{1/2}). A = Lobatto IIIA, A~ = Lobatto IIIB (s = 2).
-- E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed.,
-- Springer 2006, Sect. VI.3 "First examples of symplectic integrators"
-- (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods); E. Hairer, C.
-- Lubich, G. Wanner, Acta Numerica 12 (2003) 399-450, Sect. 1.
--
-- Written as a splitting (drifts q <- q + coef h dT/dp, kicks p <- p - coef
-- h dV/dq, in order of application); vigen converts it exactly to the PRK
-- tableau above (tests/data/published_prk/ keeps the transcription).
return {
  name = "stormer_verlet_velocity",
  order = 2,
  symplectic = true,
  source = "E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Sect. VI.3 \"First examples of symplectic integrators\" (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods); E. Hairer, C. Lubich, G. Wanner, Acta Numerica 12 (2003) 399-450, Sect. 1",
  description = "Stormer-Verlet, p-first (\"velocity Verlet\", kick-drift-kick): p_{1/2} = p0 - h/2 dH/dq(q0, p_{1/2}), q1 = q0 + h/2 (dH/dp(q0, p_{1/2}) + dH/dp(q1, p_{1/2})), p1 = p_{1/2} - h/2 dH/dq(q1, p_{1/2}). A = Lobatto IIIA, A~ = Lobatto IIIB (s = 2).",
  splitting = { { "kick", "1/2" }, { "drift", "1" }, { "kick", "1/2" } },
}
