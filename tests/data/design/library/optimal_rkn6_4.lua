-- Symmetric RKN splittings with seven kicks that start and end with a kick
-- (first same as last: 6 force evaluations per step, the cost of Blanes and
-- Moan's S6), order 4 for Nystrom H = p^2/2 + V(q): the family of Blanes and
-- Moan's SRKN_6^b, three free parameters.  The best point found by the
-- checker's Nystrom error constant: 200 random points screened (each
-- descended on the Lyndon norm of the principal error, cheap), then
-- Nelder-Mead on the checker's constant from the best of them.  The seed
-- fixes every draw: the run is reproducible.
-- Unknowns: drifts a1 (= 0) .. a4, kicks b1 .. b4.
return { name = "rkn6", design = "rkn", stages = 7, order = 4, symmetric = true, first = "kick",
         minimize = "error_constant_nystrom", screen = 200, starts = 1 }
