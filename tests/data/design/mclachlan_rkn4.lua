-- McLachlan's symmetric RKN method of order 4 with five kicks (SIAM J. Sci.
-- Comput. 16 (1995) 151, type SB3A; the library's mclachlan_rkn_4): the
-- kicks b1 = -3/73, b2 = 17/59 as he chose them, the drifts a1, a2, a3 and
-- the middle kick b3 from the order conditions for Nystrom H.
return { name = "mrkn4", design = "rkn", stages = 5, order = 4, symmetric = true, solutions = "all",
         fix = { b1 = "-3/73", b2 = "17/59" } }
