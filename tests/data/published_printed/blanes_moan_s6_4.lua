-- Blanes-Moan (2002) S6, order 4.
-- Blanes-Moan symmetric 6-stage fourth-order splitting method: drift a1, kick
-- b1, drift a2, kick b2, drift a3, kick b3, drift a4, kick b3, drift a3, kick
-- b2, drift a2, kick b1, drift a1 (flow of the kinetic part T with the a_i,
-- potential part V with the b_i). As a PRK tableau it has s = 12 stages (7
-- drifts and 6 kicks per step; s = drifts + kicks - 1).
-- S. Blanes, P. C. Moan, "Practical symplectic partitioned Runge-Kutta and
-- Runge-Kutta-Nystrom methods", J. Comput. Appl. Math. 142 (2002) 313-330,
-- Table 2 (PRK method S6 of order 4, six stages).
--
-- Written as published: the free coefficients as the paper prints them
-- (rounded decimals, cross-checked with the Principia and other public
-- implementations) and the dependent ones by the paper's formulas a4 =
-- 1 - 2(a1+a2+a3), b3 = 1/2 - (b1+b2). Every decimal, bare or inside those
-- formulas, is read as the ball of half a unit in its last digit, so the
-- dependent coefficients carry the radii of the printed ones; vigen converts
-- the substeps exactly to a PRK tableau with bt = b (substeps - 1 stages),
-- symplectic for every H and, for separable H, explicit and equal to the
-- splitting.
local a1, a2, a3 = "0.0792036964311957", "0.353172906049774", "-0.0420650803577195"
local b1, b2 = "0.209515106613362", "-0.143851773179818"
local a4 = "1 - 2*(" .. a1 .. " + " .. a2 .. " + (" .. a3 .. "))"
local b3 = "1/2 - (" .. b1 .. " + (" .. b2 .. "))"
return {
  name = "blanes_moan_s6_4",
  order = 4,
  symplectic = true,
  source = "S. Blanes, P. C. Moan, \"Practical symplectic partitioned Runge-Kutta and Runge-Kutta-Nystrom methods\", J. Comput. Appl. Math. 142 (2002) 313-330, Table 2 (PRK method S6 of order 4, six stages)",
  description = "Blanes-Moan symmetric 6-stage fourth-order splitting method: drift a1, kick b1, drift a2, kick b2, drift a3, kick b3, drift a4, kick b3, drift a3, kick b2, drift a2, kick b1, drift a1 (flow of the kinetic part T with the a_i, potential part V with the b_i). Coefficients printed in the paper as rounded decimals: a1 = 0.0792036964311957, a2 = 0.353172906049774, a3 = -0.0420650803577195, a4 = 1 - 2(a1+a2+a3), b1 = 0.209515106613362, b2 = -0.143851773179818, b3 = 1/2 - (b1+b2).",
  splitting = {
    { "drift", a1 }, { "kick", b1 }, { "drift", a2 }, { "kick", b2 }, { "drift", a3 }, { "kick", b3 },
    { "drift", a4 },
    { "kick", b3 }, { "drift", a3 }, { "kick", b2 }, { "drift", a2 }, { "kick", b1 }, { "drift", a1 },
  },
}
