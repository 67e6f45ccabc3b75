-- Yoshida (1990) sixth-order composition, solution A.
-- Yoshida's sixth-order seven-fold symmetric composition (solution A) of the
-- q-first (position, drift-kick-drift) Stormer-Verlet step: S6(h) = S2(w3 h)
-- S2(w2 h) S2(w1 h) S2(w0 h) S2(w1 h) S2(w2 h) S2(w3 h), w0 = 1 - 2(w1 + w2 +
-- w3). As a PRK tableau it has s = 14 stages.
-- H. Yoshida, "Construction of higher order symplectic integrators", Phys.
-- Lett. A 150 (1990) 262-268, Table 1, solution A.
--
-- Written as published, a composition of the base method with steps w_i h.
-- Yoshida prints w1 = -1.17767998417887, w2 = 0.235573213359357, w3 =
-- 0.784513610477560; these printed digits are not all correct (w2 and w3 are
-- off by 1.1e-15 and 2.7e-15: docs/published.md), so the values used here
-- were recomputed to 50 digits by Newton iteration on the sixth-order
-- conditions started from the printed ones (they agree with the 40-digit
-- values in SUNDIALS ARKODE_SPRK_YOSHIDA_6_8). Each decimal, bare or inside
-- the formula for w0, is read as the ball of half a unit in its last digit.
local w1 = "-1.1776799841788710069464156809643157346392692526346"
local w2 = "0.23557321335935813368479318297853460168646808210340"
local w3 = "0.78451361047755726381949763386634987577682441745149"
local w0 = "1 - 2*((" .. w1 .. ") + " .. w2 .. " + " .. w3 .. ")"
return {
  name = "yoshida_6",
  order = 6,
  symplectic = true,
  source = "H. Yoshida, \"Construction of higher order symplectic integrators\", Phys. Lett. A 150 (1990) 262-268, Table 1, solution A: S6(h) = S2(w3 h) S2(w2 h) S2(w1 h) S2(w0 h) S2(w1 h) S2(w2 h) S2(w3 h)",
  description = "Yoshida's sixth-order seven-fold symmetric composition (solution A) of the q-first (position, drift-kick-drift) Stormer-Verlet step. Yoshida prints w1 = -1.17767998417887, w2 = 0.235573213359357, w3 = 0.784513610477560 (w0 = 1 - 2(w1+w2+w3)); the printed w2 and w3 are off by 1.1e-15 and 2.7e-15, and the values used are recomputed to 50 digits from the sixth-order conditions.",
  composition = { base = "stormer_verlet_position", gamma = { w3, w2, w1, w0, w1, w2, w3 } },
}
