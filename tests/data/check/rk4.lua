-- The classical Runge-Kutta method (Kutta 1901; Hairer, Norsett & Wanner I,
-- Table II.1.2), one RK method used for both parts: order 4, not symplectic.
return {
  name = "rk4",
  s = 4,
  c = { "0", "1/2", "1/2", "1" },
  A = {
    { "0", "0", "0", "0" },
    { "1/2", "0", "0", "0" },
    { "0", "1/2", "0", "0" },
    { "0", "0", "1", "0" },
  },
  b = { "1/6", "1/3", "1/3", "1/6" },
  order = 4,
}
