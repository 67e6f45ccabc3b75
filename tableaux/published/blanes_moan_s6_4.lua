-- Blanes-Moan (2002) S6, order 4.
-- Blanes-Moan symmetric 6-stage fourth-order splitting method: drift a1, kick
-- b1, drift a2, kick b2, drift a3, kick b3, drift a4, kick b3, drift a3, kick
-- b2, drift a2, kick b1, drift a1 (flow of the kinetic part T with the a_i,
-- potential part V with the b_i). As a PRK tableau it has s = 12 stages (7
-- drifts and 6 kicks per step; s = drifts + kicks - 1).
-- S. Blanes, P. C. Moan, "Practical symplectic partitioned Runge-Kutta and
-- Runge-Kutta-Nystrom methods", J. Comput. Appl. Math. 142 (2002) 313-330,
-- Table 2 (PRK method S6 of order 4, six stages), printed as a1 =
-- 0.0792036964311957, a2 = 0.353172906049774, a3 = -0.0420650803577195, a4 =
-- 1 - 2(a1+a2+a3), b1 = 0.209515106613362, b2 = -0.143851773179818, b3 = 1/2
-- - (b1+b2).
--
-- The printed coefficients satisfy the order conditions to 2e-17 only. The
-- 40 digits below are those of the member of the family (symmetric, six
-- kicks, order 4 for separable H) nearest to the printed point, proved to
-- exist by the Krawczyk operator and rounded with every digit certified:
-- `vigen design tests/data/design/library/blanes_moan_s6_4.lua`
-- (docs/design.md). Every printed digit is the correct rounding of this
-- method's coefficient (docs/published.md); the paper's own criterion for
-- its three free parameters was not reproduced. Each decimal is read as the
-- ball of half a unit in its last digit.
local a1 = "0.07920369643119567419764962376313816651194"
local a2 = "0.3531729060497740368186655573031425943496"
local a3 = "-0.04206508035771952921517158087661579516925"
local a4 = "0.2193769557534996363977127996206700686154"
local b1 = "0.2095151066133620529724499860936093178064"
local b2 = "-0.1438517731798180379640962992327095997669"
local b3 = "0.4343366665664559849916463131391002819605"
return {
  name = "blanes_moan_s6_4",
  order = 4,
  symplectic = true,
  source = "S. Blanes, P. C. Moan, \"Practical symplectic partitioned Runge-Kutta and Runge-Kutta-Nystrom methods\", J. Comput. Appl. Math. 142 (2002) 313-330, Table 2 (PRK method S6 of order 4, six stages); 40 certified digits of the exact member of the family nearest to the printed coefficients (vigen design tests/data/design/library/blanes_moan_s6_4.lua)",
  description = "Blanes-Moan symmetric 6-stage fourth-order splitting method: drift a1, kick b1, drift a2, kick b2, drift a3, kick b3, drift a4, kick b3, drift a3, kick b2, drift a2, kick b1, drift a1 (flow of the kinetic part T with the a_i, potential part V with the b_i). Printed: a1 = 0.0792036964311957, a2 = 0.353172906049774, a3 = -0.0420650803577195, a4 = 1 - 2(a1+a2+a3), b1 = 0.209515106613362, b2 = -0.143851773179818, b3 = 1/2 - (b1+b2); the file holds 40 certified digits of the exact order-4 member of the family nearest to them.",
  splitting = {
    { "drift", a1 }, { "kick", b1 }, { "drift", a2 }, { "kick", b2 }, { "drift", a3 }, { "kick", b3 },
    { "drift", a4 },
    { "kick", b3 }, { "drift", a3 }, { "kick", b2 }, { "drift", a2 }, { "kick", b1 }, { "drift", a1 },
  },
}
