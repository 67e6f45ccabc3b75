-- Laskar & Robutel (2001) SABA_3 for H = A + eps B (A integrable, here the
-- Kepler part): c1 = 1/2 - sqrt(15)/10, c2 = sqrt(15)/10, d1 = 5/18,
-- d2 = 4/9; the remainder is O(eps h^6 + eps^2 h^2): generalized order
-- (6,2) (Laskar & Robutel 2001, Table 1).
-- J. Laskar, P. Robutel, "High order symplectic integrators for perturbed
-- Hamiltonian systems", Celest. Mech. Dyn. Astron. 80 (2001) 39-62, Sect. 3.
local c1, c2, d1, d2 = "1/2 - sqrt(15)/10", "sqrt(15)/10", "5/18", "4/9"
return {
  name = "saba_3",
  order = 2,
  generalized_order = {6, 2},
  symplectic = true,
  source = "J. Laskar, P. Robutel, \"High order symplectic integrators for perturbed Hamiltonian systems\", Celest. Mech. Dyn. Astron. 80 (2001) 39-62, Sect. 3 and Table 1: SABA_3, c1 = 1/2 - sqrt(15)/10, c2 = sqrt(15)/10, d1 = 5/18, d2 = 4/9",
  description = "SABA_3 of Laskar & Robutel for H = A + eps B: A c1 h, B d1 h, A c2 h, B d2 h, A c2 h, B d1 h, A c1 h; generalized order (6,2), error O(eps h^6 + eps^2 h^2).",
  flows = { "kepler", "interaction" },
  perturbation = "interaction",
  splitting = {
    { "kepler", c1 },
    { "interaction", d1 },
    { "kepler", c2 },
    { "interaction", d2 },
    { "kepler", c2 },
    { "interaction", d1 },
    { "kepler", c1 },
  },
}
