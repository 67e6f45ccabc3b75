-- A symmetric six-kick splitting of order 4 (the cost of Blanes-Moan S6)
-- with a smaller Nystrom error constant than S6 (vigen design).
-- Drift a1, kick b1, drift a2, kick b2, drift a3, kick b3, drift a4, kick b3,
-- drift a3, kick b2, drift a2, kick b1, drift a1: the family of
-- blanes_moan_s6_4 (three free parameters), at a local minimum of the
-- checker's error constant for Nystrom H = p^2/2 + V(q) (0.000252669 against
-- S6's 0.000316071; for separable H 0.00135 against 0.000428, for general H
-- 0.0418 against 0.00795: a method for T = p^2/2). As a PRK tableau it has
-- s = 12 stages; 6 force evaluations per step.
-- The free parameters come from a Nelder-Mead descent from S6 on the
-- checker's Nystrom error constant (outside vigen; the minimum is local, and
-- found to about 8 digits); `vigen design
-- tests/data/design/library/optimal_s6_4.lua` then proves the exact member
-- of the family nearest that point (Krawczyk) and certifies every digit
-- below (the exact coefficient lies within half a unit of the last digit).
-- Each decimal is read as the ball of half a unit in its last digit.
local a1 = "0.07812885551517680430587392624417444268041"
local a2 = "0.3026414274260884556338244789980489412440"
local a3 = "-0.003968351146629537881668264676614225368479"
local a4 = "0.2463961364107285558839397188687816828881"
local b1 = "0.2049862381100851246169821160750618207433"
local b2 = "-0.7344173898404890373041424011907704992818"
local b3 = "1.029431151730403912687160285115708678539"
return {
  name = "optimal_s6_4",
  order = 4,
  symplectic = true,
  source = "vigen design tests/data/design/library/optimal_s6_4.lua: the symmetric six-kick splitting of order 4 (Blanes and Moan's S6 family) at a local minimum of the Nystrom error constant",
  description = "Symmetric six-kick splitting of order 4 for separable H, drift a1, kick b1, ..., drift a4, ..., kick b1, drift a1, with the three free parameters at a local minimum of the principal error constant for Nystrom H = p^2/2 + V(q): 0.000252669 against 0.000316071 for Blanes-Moan S6 at the same 6 force evaluations per step (but larger constants for general and separable H).",
  splitting = {
    { "drift", a1 }, { "kick", b1 }, { "drift", a2 }, { "kick", b2 }, { "drift", a3 }, { "kick", b3 },
    { "drift", a4 },
    { "kick", b3 }, { "drift", a3 }, { "kick", b2 }, { "drift", a2 }, { "kick", b1 }, { "drift", a1 },
  },
}
