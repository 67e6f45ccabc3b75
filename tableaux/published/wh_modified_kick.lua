-- The Wisdom-Holman map in its drift-kick-drift form (Kepler h/2,
-- interaction h, Kepler h/2) with a modified kick, in the style of the
-- kernel method of Wisdom, Holman & Touma (1996) and Wisdom (2006): the
-- kick is exp(h eps B + c eps^2 h^3 {{A,B},B}), written as the interaction
-- for h/2, the bracket flow "interaction_gradient" ({{kepler, interaction},
-- interaction}; for B = B(q) and A = T(p) + ... it is sum_i |dB/dq_i|^2/m_i,
-- a function of q that commutes with B, so that the split kick is the
-- modified kick) for c h^3, and the interaction for h/2.
-- c = -1/12 removes the eps^2 h^2 term: the drift-kick-drift map's
-- logarithm is h(A + eps B) - (1/24) eps h^3 [A,[A,B]] + (1/12) eps^2 h^3
-- [[A,B],B] + O(h^5) (the symmetric BCH formula), and exp(c W), W =
-- [[A,B],B], adds c eps^2 h^3 W (vigen check derives and certifies it:
-- generalized order (2,4), against (2,2) for the plain map).  The eps h^2
-- term is a corrector's business: wh_modified_kick_corrected.
-- J. Wisdom, M. Holman, J. Touma, "Symplectic correctors", Fields Inst.
-- Commun. 10 (1996) 217-244; J. Wisdom, Astron. J. 131 (2006) 2294-2298.
return {
  name = "wh_modified_kick",
  generalized_order = {2, 4},
  symplectic = true,
  source = "kernel method of J. Wisdom, M. Holman, J. Touma, \"Symplectic correctors\", Fields Inst. Commun. 10 (1996) 217-244, and J. Wisdom, Astron. J. 131 (2006) 2294: the Wisdom-Holman map (Kepler h/2, interaction h, Kepler h/2) whose kick is exp(h eps B + c eps^2 h^3 {{A,B},B}); c = -1/12 derived with vigen check (it removes the eps^2 h^2 term)",
  description = "Wisdom-Holman drift-kick-drift map with the modified kick exp(h eps B - (1/12) eps^2 h^3 {{A,B},B}): generalized order (2,4), error O(eps h^2 + eps^2 h^4).",
  flows = { "kepler", "interaction", "interaction_gradient" },
  brackets = { interaction_gradient = { "kepler", "interaction", "interaction" } },
  perturbation = "interaction",
  splitting = {
    { "kepler", "1/2" },
    { "interaction", "1/2" },
    { "interaction_gradient", "-1/12" },
    { "interaction", "1/2" },
    { "kepler", "1/2" },
  },
}
