-- Symmetric splittings with six kicks, order 4 for separable H (the family of
-- Blanes and Moan's S6): the member nearest to a local minimum of the
-- checker's Nystrom error constant found by a Nelder-Mead descent from S6
-- over the three free parameters (a1, a2, b1; a3, b2 from the order
-- conditions), outside vigen: the point the descent stopped at, given to
-- 17 digits, is projected onto the order conditions and proved.
-- Unknowns: drifts a1..a4, kicks b1..b3.
return { name = "s6n", design = "splitting", stages = 6, order = 4, symmetric = true,
         nearest = { "0.0781288555151768", "0.30264142742608846", "-0.0039683511466295379", "0.24639613641072856",
                     "0.20498623811008512", "-0.73441738984048905", "1.0294311517304039" } }
