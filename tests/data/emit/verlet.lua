-- Stormer-Verlet as the 2-stage Lobatto IIIA-IIIB pair (order 2).
-- GNI, Table II.2.1: q-part Lobatto IIIA, p-part Lobatto IIIB.
return {
  name = "stormer_verlet", s = 2,
  c = { "0", "1" },
  A = { { "0", "0" }, { "1/2", "1/2" } },
  b = { "1/2", "1/2" },
  At = { { "1/2", "0" }, { "1/2", "0" } },
  ct = { "1/2", "1/2" },
  bt = { "1/2", "1/2" },
  order = 2, symplectic = true,
  description = "Stormer-Verlet (Lobatto IIIA-IIIB)",
}
