-- symplectic euler p first: Symplectic Euler, p-first variant: p1 = p0 - h
-- dH/dq(q0, p1), q1 = q0 + h dH/dp(q0, p1) (kick then drift for separable H).
-- Same as Leok-Zhang Example 2 (i).
-- E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed.,
-- Springer 2006, Sect. VI.3 "First examples of symplectic integrators"
-- (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods).
return {
  name = "symplectic_euler_p_first",
  s = 1,
  order = 1,
  symplectic = true,
  source = "E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, Sect. VI.3 \"First examples of symplectic integrators\" (Theorems 3.3 and 3.4) and Sect. II.2.1 (as PRK methods)",
  description = "Symplectic Euler, p-first variant: p1 = p0 - h dH/dq(q0, p1), q1 = q0 + h dH/dp(q0, p1) (kick then drift for separable H). Same as Leok-Zhang Example 2 (i).",
  c = { "0" },
  A = {
    { "0" },
  },
  b = { "1" },
  ct = { "1" },
  At = {
    { "1" },
  },
}
