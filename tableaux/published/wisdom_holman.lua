-- Wisdom & Holman (1991): the mixed-variable symplectic map of the N-body
-- problem, H = H_Kepler + eps H_interaction: half a step of the interaction
-- (a kick of every body by the mutual forces), a whole step of the Kepler
-- flow (each body on its Kepler orbit, solved exactly), half a step of the
-- interaction.  Generalized order (2,2): the error is O(eps h^2 + eps^2 h^2)
-- (Laskar & Robutel 2001, Sect. 2).
-- J. Wisdom, M. Holman, "Symplectic maps for the N-body problem", Astron. J.
-- 102 (1991) 1528-1538, Sect. 3 (the map as the composition of the Kepler
-- and the interaction flows, in the symmetric form kick h/2, drift h,
-- kick h/2).
return {
  name = "wisdom_holman",
  order = 2,
  generalized_order = {2, 2},
  symplectic = true,
  source = "J. Wisdom, M. Holman, \"Symplectic maps for the N-body problem\", Astron. J. 102 (1991) 1528-1538, Sect. 3: interaction h/2, Kepler h, interaction h/2",
  description = "The Wisdom-Holman map for H = H_Kepler + eps H_interaction: the interaction flow for h/2, the exact Kepler flow for h, the interaction flow for h/2. Generalized order (2,2): energy error O(eps h^2 + eps^2 h^2).",
  flows = { "kepler", "interaction" },
  perturbation = "interaction",
  splitting = {
    { "interaction", "1/2" },
    { "kepler", "1" },
    { "interaction", "1/2" },
  },
}
