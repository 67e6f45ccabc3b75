-- A symmetric RKN splitting of order 4 with seven kicks that starts and ends
-- with a kick (first same as last: 6 force evaluations per step, the cost of
-- Blanes-Moan S6), found by vigen design.
-- Kick b1, drift a2, kick b2, drift a3, kick b3, drift a4, kick b4, drift a4,
-- kick b3, drift a3, kick b2, drift a2, kick b1: the family of Blanes and
-- Moan's SRKN_6^b (three free parameters), at the best minimum found of the
-- checker's error constant for Nystrom H = p^2/2 + V(q): 2.40419e-5 against
-- 0.000316071 for Blanes-Moan S6 (for separable H 0.00132 against 0.000428,
-- for general H 0.0108 against 0.00795: a method for T = p^2/2).  As a PRK
-- tableau it has s = 12 stages; the emitted stepper reuses the last force of
-- a step as the first of the next: 6 force evaluations per step.
-- `vigen design tests/data/design/library/optimal_rkn6_4.lua` screens 200
-- random points of the family on the Lyndon norm of the principal error,
-- descends from the best on the checker's Nystrom constant (the minimum is
-- the best found, not proved global), proves the exact member of the family
-- at the free kicks it stops at (Krawczyk) and certifies every digit below
-- (the exact coefficient lies within half a unit of the last digit).
-- Each decimal is read as the ball of half a unit in its last digit.
local a2 = "0.2452333510032332217700191677301557581838"
local a3 = "0.6020404828260650362200514296930881272571"
local a4 = "-0.3472738338292982579900705974232438854409"
local b1 = "0.08287150701548293141307510722981533035636"
local b2 = "0.3957744507936673539205685301567427814007"
local b3 = "-0.03929850189021675405109945700132811907679"
local b4 = "0.1213050881621329374349116392295400146395"
return {
  name = "optimal_rkn6_4",
  order = 4,
  order_separable = 4,
  order_nystrom = 4,
  symplectic = true,
  source = "vigen design tests/data/design/library/optimal_rkn6_4.lua: the symmetric seven-kick RKN splitting of order 4 that starts with a kick (the family of Blanes and Moan's SRKN_6^b) at the best minimum found of the Nystrom error constant",
  description = "Symmetric RKN splitting of order 4 with seven kicks, first same as last (6 force evaluations per step): kick b1, drift a2, kick b2, drift a3, kick b3, drift a4, kick b4, drift a4, ..., drift a2, kick b1, with the three free parameters at the best minimum found of the principal error constant for Nystrom H = p^2/2 + V(q): 2.40419e-5 against 0.000316071 for Blanes-Moan S6 at the same cost (but larger constants for general and separable H).",
  splitting = {
    { "kick", b1 }, { "drift", a2 }, { "kick", b2 }, { "drift", a3 }, { "kick", b3 }, { "drift", a4 },
    { "kick", b4 },
    { "drift", a4 }, { "kick", b3 }, { "drift", a3 }, { "kick", b2 }, { "drift", a2 }, { "kick", b1 },
  },
}
