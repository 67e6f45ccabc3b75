-- Blanes and Moan's S6 (J. Comput. Appl. Math. 142 (2002) 313, Table 2):
-- symmetric splittings with six kicks, order 4 for separable H, three free
-- parameters.  The paper's criterion for choosing them could not be
-- reproduced here (the printed point is not a stationary point of the error
-- norms vigen computes: docs/published.md), so the method is re-derived as
-- the member of the family nearest to the printed coefficients: a1, a2, a3,
-- a4 = 1 - 2(a1 + a2 + a3) (drifts), b1, b2, b3 = 1/2 - (b1 + b2) (kicks),
-- each taken exactly as printed (a4 and b3 exact from the printed ones).
return { name = "bm6", design = "splitting", stages = 6, order = 4, symmetric = true,
         nearest = { "0.0792036964311957", "0.353172906049774", "-0.0420650803577195", "0.2193769557534996",
                     "0.209515106613362", "-0.143851773179818", "0.434336666566456" } }
