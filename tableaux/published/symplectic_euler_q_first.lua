-- symplectic euler q first: Symplectic Euler, q-first variant (the adjoint):
-- q1 = q0 + h dH/dp(q1, p0), p1 = p0 - h dH/dq(q1, p0) (drift then kick for
-- separable H). Same as Leok-Zhang Example 2 (iii).
-- E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed.,
-- Springer 2006, Sect. VI.3 "First examples of symplectic integrators"
-- (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods).
--
-- Written as a splitting (drifts q <- q + coef h dT/dp, kicks p <- p - coef
-- h dV/dq, in order of application); vigen converts it exactly to the PRK
-- tableau above (tests/data/published_prk/ keeps the transcription).
return {
  name = "symplectic_euler_q_first",
  order = 1,
  symplectic = true,
  source = "E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Sect. VI.3 \"First examples of symplectic integrators\" (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods)",
  description = "Symplectic Euler, q-first variant (the adjoint): q1 = q0 + h dH/dp(q1, p0), p1 = p0 - h dH/dq(q1, p0) (drift then kick for separable H). Same as Leok-Zhang Example 2 (iii).",
  splitting = { { "drift", "1" }, { "kick", "1" } },
}
