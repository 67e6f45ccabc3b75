-- Laskar & Robutel (2001) SABA_4 for H = A + eps B (A integrable, here the
-- Kepler part): c1 = 1/2 - sqrt(525 + 70 sqrt(30))/70,
-- c2 = (sqrt(525 + 70 sqrt(30)) - sqrt(525 - 70 sqrt(30)))/70,
-- c3 = sqrt(525 - 70 sqrt(30))/35, d1 = 1/4 - sqrt(30)/72,
-- d2 = 1/4 + sqrt(30)/72; the remainder is O(eps h^8 + eps^2 h^2):
-- generalized order (8,2) (Laskar & Robutel 2001, Table 1).
-- J. Laskar, P. Robutel, "High order symplectic integrators for perturbed
-- Hamiltonian systems", Celest. Mech. Dyn. Astron. 80 (2001) 39-62, Sect. 3.
local c1 = "1/2 - sqrt(525 + 70*sqrt(30))/70"
local c2 = "(sqrt(525 + 70*sqrt(30)) - sqrt(525 - 70*sqrt(30)))/70"
local c3 = "sqrt(525 - 70*sqrt(30))/35"
local d1, d2 = "1/4 - sqrt(30)/72", "1/4 + sqrt(30)/72"
return {
  name = "saba_4",
  order = 2,
  generalized_order = {8, 2},
  symplectic = true,
  source = "J. Laskar, P. Robutel, \"High order symplectic integrators for perturbed Hamiltonian systems\", Celest. Mech. Dyn. Astron. 80 (2001) 39-62, Sect. 3 and Table 1: SABA_4, c1 = 1/2 - sqrt(525 + 70 sqrt(30))/70, c2 = (sqrt(525 + 70 sqrt(30)) - sqrt(525 - 70 sqrt(30)))/70, c3 = sqrt(525 - 70 sqrt(30))/35, d1 = 1/4 - sqrt(30)/72, d2 = 1/4 + sqrt(30)/72",
  description = "SABA_4 of Laskar & Robutel for H = A + eps B: A c1 h, B d1 h, A c2 h, B d2 h, A c3 h, B d2 h, A c2 h, B d1 h, A c1 h; generalized order (8,2), error O(eps h^8 + eps^2 h^2).",
  flows = { "kepler", "interaction" },
  perturbation = "interaction",
  splitting = {
    { "kepler", c1 },
    { "interaction", d1 },
    { "kepler", c2 },
    { "interaction", d2 },
    { "kepler", c3 },
    { "interaction", d2 },
    { "kepler", c2 },
    { "interaction", d1 },
    { "kepler", c1 },
  },
}
