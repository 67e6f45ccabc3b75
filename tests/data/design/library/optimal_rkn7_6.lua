-- Symmetric RKN splittings with seven kicks (7 force evaluations per step,
-- the cost of Yoshida's sixth order), order 6 for Nystrom H = p^2/2 + V(q):
-- every real root found, each proved; the library's optimal_rkn7_6 is the
-- one of order 6 for Nystrom H only with the second-smallest Nystrom error
-- constant (docs/design.md, "New methods", says why not the smallest).
-- Unknowns: drifts a1..a4, kicks b1..b4.
return { name = "rkn7", design = "rkn", stages = 7, order = 6, symmetric = true, solutions = "all" }
