-- Stormer-Verlet as the Lobatto IIIA-IIIB pair (order 2, symplectic):
-- explicit for separable H, one force evaluation per step.
return {
  name = "stormer_verlet", s = 2, order = 2, symplectic = true,
  c  = { "0", "1" },
  A  = { { "0", "0" }, { "1/2", "1/2" } },
  b  = { "1/2", "1/2" },
  At = { { "1/2", "0" }, { "1/2", "0" } },
  ct = { "1/2", "1/2" },
  bt = { "1/2", "1/2" },
}
