-- Blanes-Moan (2002) S10, order 6.
-- Blanes-Moan symmetric 10-stage sixth-order splitting method: drift a1, kick
-- b1, ..., drift a5, kick b5, drift a6, kick b5, drift a5, ..., kick b1,
-- drift a1 (kinetic part with the a_i, potential part with the b_i). As a PRK
-- tableau it has s = 20 stages (11 drifts and 10 kicks per step; s = drifts +
-- kicks - 1).
-- S. Blanes, P. C. Moan, "Practical symplectic partitioned Runge-Kutta and
-- Runge-Kutta-Nystrom methods", J. Comput. Appl. Math. 142 (2002) 313-330,
-- Table 2 (PRK method S10 of order 6, ten stages), printed as a1 =
-- 0.0502627644003922, a2 = 0.413514300428344, a3 = 0.0450798897943977, a4 =
-- -0.188054853819569, a5 = 0.541960678450780, a6 = 1 - 2(a1+...+a5), b1 =
-- 0.148816447901042, b2 = -0.132385865767784, b3 = 0.067307604692185, b4 =
-- 0.432666402578175, b5 = 1/2 - (b1+...+b4).
--
-- The printed coefficients satisfy the order conditions to 7e-17 only. The
-- 40 digits below are those of the member of the family (symmetric, ten
-- kicks, order 6 for separable H) nearest to the printed point, proved to
-- exist by the Krawczyk operator and rounded with every digit certified:
-- `vigen design tests/data/design/library/blanes_moan_s10_6.lua`
-- (docs/design.md). Six of the nine printed free coefficients differ from
-- it in their last digit (docs/published.md); the paper's own criterion for
-- the free parameter was not reproduced. Each decimal is read as the ball of
-- half a unit in its last digit.
local a = { "0.05026276440039272276463501706551157802999", "0.4135143004283434774541367150491272930119",
            "0.04507988979439811148986108449994759793866", "-0.1880548538195686184904252832565255703991",
            "0.5419606784507800123668921918616562122025" }
local a6 = "-0.7255255585086914111701994504394342215678"
local b = { "0.1488164479010432804573382503624305490099", "-0.1323858657677837561493469658764191817796",
            "0.06730760469218439924077148588987427738938", "0.4326664025781737116335833140130967131357",
            "-0.01640458940361763518234608438898235775534" }
local splitting = {}
for i = 1, 5 do
  splitting[#splitting + 1] = { "drift", a[i] }
  splitting[#splitting + 1] = { "kick", b[i] }
end
splitting[#splitting + 1] = { "drift", a6 }
for i = 5, 1, -1 do
  splitting[#splitting + 1] = { "kick", b[i] }
  splitting[#splitting + 1] = { "drift", a[i] }
end
return {
  name = "blanes_moan_s10_6",
  order = 6,
  symplectic = true,
  source = "S. Blanes, P. C. Moan, \"Practical symplectic partitioned Runge-Kutta and Runge-Kutta-Nystrom methods\", J. Comput. Appl. Math. 142 (2002) 313-330, Table 2 (PRK method S10 of order 6, ten stages); 40 certified digits of the exact member of the family nearest to the printed coefficients (vigen design tests/data/design/library/blanes_moan_s10_6.lua)",
  description = "Blanes-Moan symmetric 10-stage sixth-order splitting method: drift a1, kick b1, ..., drift a5, kick b5, drift a6, kick b5, drift a5, ..., kick b1, drift a1 (kinetic part with the a_i, potential part with the b_i). Printed: a1 = 0.0502627644003922, a2 = 0.413514300428344, a3 = 0.0450798897943977, a4 = -0.188054853819569, a5 = 0.541960678450780, a6 = 1 - 2(a1+...+a5), b1 = 0.148816447901042, b2 = -0.132385865767784, b3 = 0.067307604692185, b4 = 0.432666402578175, b5 = 1/2 - (b1+...+b4); the file holds 40 certified digits of the exact order-6 member of the family nearest to them.",
  splitting = splitting,
}
