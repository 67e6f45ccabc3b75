-- Laskar & Robutel (2001) SABA_1 for H = A + eps B (A integrable, here the
-- Kepler part): A h/2, eps B h, A h/2.  Its remainder is O(eps h^2 + eps^2
-- h^2): generalized order (2,2) (Laskar & Robutel 2001, Table 1).
-- J. Laskar, P. Robutel, "High order symplectic integrators for perturbed
-- Hamiltonian systems", Celest. Mech. Dyn. Astron. 80 (2001) 39-62, Sect. 3:
-- SABA_n = exp(c_1 h L_A) exp(d_1 h L_eps B) ... exp(c_(n+1) h L_A), the d_i
-- the weights and the partial sums of the c_i the nodes of the n-point
-- Gauss-Legendre rule on [0, 1].
return {
  name = "saba_1",
  order = 2,
  generalized_order = {2, 2},
  symplectic = true,
  source = "J. Laskar, P. Robutel, \"High order symplectic integrators for perturbed Hamiltonian systems\", Celest. Mech. Dyn. Astron. 80 (2001) 39-62, Sect. 3 and Table 1: SABA_1, c1 = 1/2, d1 = 1",
  description = "SABA_1 of Laskar & Robutel for H = A + eps B: A (Kepler) h/2, B (interaction) h, A h/2; generalized order (2,2), error O(eps h^2 + eps^2 h^2).",
  flows = { "kepler", "interaction" },
  perturbation = "interaction",
  splitting = {
    { "kepler", "1/2" },
    { "interaction", "1" },
    { "kepler", "1/2" },
  },
}
