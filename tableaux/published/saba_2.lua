-- Laskar & Robutel (2001) SABA_2 for H = A + eps B (A integrable, here the
-- Kepler part): c1 = 1/2 - sqrt(3)/6, c2 = sqrt(3)/3, d1 = 1/2; the
-- remainder is O(eps h^4 + eps^2 h^2): generalized order (4,2) (Laskar &
-- Robutel 2001, Table 1).
-- J. Laskar, P. Robutel, "High order symplectic integrators for perturbed
-- Hamiltonian systems", Celest. Mech. Dyn. Astron. 80 (2001) 39-62, Sect. 3.
local c1, c2 = "1/2 - sqrt(3)/6", "sqrt(3)/3"
return {
  name = "saba_2",
  order = 2,
  generalized_order = {4, 2},
  symplectic = true,
  source = "J. Laskar, P. Robutel, \"High order symplectic integrators for perturbed Hamiltonian systems\", Celest. Mech. Dyn. Astron. 80 (2001) 39-62, Sect. 3 and Table 1: SABA_2, c1 = 1/2 - sqrt(3)/6, c2 = sqrt(3)/3, d1 = 1/2",
  description = "SABA_2 of Laskar & Robutel for H = A + eps B: A c1 h, B h/2, A c2 h, B h/2, A c1 h; generalized order (4,2), error O(eps h^4 + eps^2 h^2).",
  flows = { "kepler", "interaction" },
  perturbation = "interaction",
  splitting = {
    { "kepler", c1 },
    { "interaction", "1/2" },
    { "kepler", c2 },
    { "interaction", "1/2" },
    { "kepler", c1 },
  },
}
