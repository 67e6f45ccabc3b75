-- Symplectic Euler as a 1-stage PRK (order 1):
-- q1 = q0 + h dH/dp(q1, p0),  p1 = p0 - h dH/dq(q1, p0).
return {
  name = "symplectic_euler", s = 1,
  c = { "1" }, A = { { "1" } }, b = { "1" },
  At = { { "0" } }, ct = { "0" }, bt = { "1" },
  order = 1, symplectic = true,
}
