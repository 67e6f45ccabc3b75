-- RK4 with a false claim (test fixture for vigen check): not symplectic.
return {
  name = "rk4_claimed_symplectic",
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
  symplectic = true,
}
