-- A symmetric RKN splitting with seven kicks (the cost of Yoshida's sixth
-- order, 7 force evaluations per step) of order 6 for Nystrom H =
-- p^2/2 + V(q), found by vigen design.
-- Drift a1, kick b1, drift a2, kick b2, drift a3, kick b3, drift a4, kick b4,
-- drift a4, kick b3, drift a3, kick b2, drift a2, kick b1, drift a1.
-- The order conditions of this family for Nystrom H (8 in 8 unknowns, where
-- separable H asks 10) have 15 real roots found and proved (Newton from 2000
-- starts, the Krawczyk operator; completeness not established): three are
-- Yoshida's A, B, C (yoshida_6 is A), twelve are of order 6 for Nystrom H
-- only. This one has Nystrom error constant 0.000289228 against 0.0102308
-- for yoshida_6 (35 times smaller; 0.000194 and 0.000425 for the next
-- roots, docs/design.md "New methods"); it is of order 4 for separable and
-- general H, so it is a method for T = p^2/2 only.
-- Each decimal is read as the ball of half a unit in its last digit; the
-- exact root lies within half a unit of the last digit of each (vigen design
-- tests/data/design/library/optimal_rkn7_6.lua, solution 4).
local a1 = "0.1857418724756142162817079493626068502510"
local a2 = "-0.02125278212788644574619658159281977872325"
local a3 = "-0.2960051269995097282742605629326333395518"
local a4 = "0.6315160366517819577387491951628462680241"
local b1 = "-0.4038299302348250150400914429423929618658"
local b2 = "0.6931251224917301969693568764720303669811"
local b3 = "0.008838140048402304494847306085318163670546"
local b4 = "0.4037333353893850271517745207700888624284"
return {
  name = "optimal_rkn7_6",
  order = 4,
  order_separable = 4,
  order_nystrom = 6,
  symplectic = true,
  source = "vigen design tests/data/design/library/optimal_rkn7_6.lua: a root of the order-6 conditions for Nystrom H of the symmetric seven-kick splittings",
  description = "Symmetric RKN splitting with seven kicks, drift a1, kick b1, ..., kick b4, ..., kick b1, drift a1, of order 6 for Nystrom H = p^2/2 + V(q) (order 4 for separable and general H), Nystrom error constant 0.000289228 against 0.0102308 for Yoshida's sixth order at the same 7 force evaluations per step.",
  splitting = {
    { "drift", a1 }, { "kick", b1 }, { "drift", a2 }, { "kick", b2 }, { "drift", a3 }, { "kick", b3 },
    { "drift", a4 }, { "kick", b4 }, { "drift", a4 },
    { "kick", b3 }, { "drift", a3 }, { "kick", b2 }, { "drift", a2 }, { "kick", b1 }, { "drift", a1 },
  },
}
