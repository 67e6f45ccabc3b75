-- Blanes-Moan (2002) S10, order 6.
-- Blanes-Moan symmetric 10-stage sixth-order splitting method: drift a1, kick
-- b1, ..., drift a5, kick b5, drift a6, kick b5, drift a5, ..., kick b1,
-- drift a1 (kinetic part with the a_i, potential part with the b_i). As a PRK
-- tableau it has s = 20 stages (11 drifts and 10 kicks per step; s = drifts +
-- kicks - 1).
-- S. Blanes, P. C. Moan, "Practical symplectic partitioned Runge-Kutta and
-- Runge-Kutta-Nystrom methods", J. Comput. Appl. Math. 142 (2002) 313-330,
-- Table 2 (PRK method S10 of order 6, ten stages).
--
-- Written as published: the free coefficients as the paper prints them
-- (rounded decimals) and the dependent ones by the paper's formulas a6 =
-- 1 - 2(a1+...+a5), b5 = 1/2 - (b1+...+b4). Every decimal, bare or inside
-- those formulas, is read as the ball of half a unit in its last digit, so
-- the dependent coefficients carry the radii of the printed ones; vigen
-- converts the substeps exactly to a PRK tableau with bt = b.
local a = { "0.0502627644003922", "0.413514300428344", "0.0450798897943977", "-0.188054853819569",
            "0.541960678450780" }
local b = { "0.148816447901042", "-0.132385865767784", "0.067307604692185", "0.432666402578175" }
local a6 = "1 - 2*(" .. table.concat(a, " + ") .. ")"
local b5 = "1/2 - (" .. table.concat(b, " + ") .. ")"
local kicks = { b[1], b[2], b[3], b[4], b5 }
local splitting = {}
for i = 1, 5 do
  splitting[#splitting + 1] = { "drift", a[i] }
  splitting[#splitting + 1] = { "kick", kicks[i] }
end
splitting[#splitting + 1] = { "drift", a6 }
for i = 5, 1, -1 do
  splitting[#splitting + 1] = { "kick", kicks[i] }
  splitting[#splitting + 1] = { "drift", a[i] }
end
return {
  name = "blanes_moan_s10_6",
  order = 6,
  symplectic = true,
  source = "S. Blanes, P. C. Moan, \"Practical symplectic partitioned Runge-Kutta and Runge-Kutta-Nystrom methods\", J. Comput. Appl. Math. 142 (2002) 313-330, Table 2 (PRK method S10 of order 6, ten stages)",
  description = "Blanes-Moan symmetric 10-stage sixth-order splitting method: drift a1, kick b1, ..., drift a5, kick b5, drift a6, kick b5, drift a5, ..., kick b1, drift a1 (kinetic part with the a_i, potential part with the b_i). Coefficients printed in the paper as rounded decimals: a1 = 0.0502627644003922, a2 = 0.413514300428344, a3 = 0.0450798897943977, a4 = -0.188054853819569, a5 = 0.541960678450780, a6 = 1 - 2(a1+...+a5), b1 = 0.148816447901042, b2 = -0.132385865767784, b3 = 0.067307604692185, b4 = 0.432666402578175, b5 = 1/2 - (b1+...+b4).",
  splitting = splitting,
}
