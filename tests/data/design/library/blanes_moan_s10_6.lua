-- Blanes and Moan's S10 (J. Comput. Appl. Math. 142 (2002) 313, Table 2):
-- symmetric splittings with ten kicks, order 6 for separable H, one free
-- parameter.  The paper's criterion could not be reproduced here
-- (docs/published.md), so the method is re-derived as the member of the
-- family nearest to the printed coefficients: a1..a5, a6 = 1 - 2(a1 + ... +
-- a5) (drifts), b1..b4, b5 = 1/2 - (b1 + ... + b4) (kicks), each taken
-- exactly as printed (a6 and b5 exact from the printed ones).
return { name = "bm10", design = "splitting", stages = 10, order = 6, symmetric = true,
         nearest = { "0.0502627644003922", "0.413514300428344", "0.0450798897943977", "-0.188054853819569",
                     "0.541960678450780", "-0.7255255585086898",
                     "0.148816447901042", "-0.132385865767784", "0.067307604692185", "0.432666402578175",
                     "-0.016404589403618" } }
