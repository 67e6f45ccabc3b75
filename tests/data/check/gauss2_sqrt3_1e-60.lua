-- Gauss-2 (Hairer & Wanner II, Table IV.5.1) with exact entries in Q(sqrt 3),
-- A[1][1] changed from 1/4 to 1/4 + sqrt(3)/10^60, an irrational of the same
-- field (test fixture for vigen check): row 1 of A no longer sums to c_1 and
-- the pair (1, 1) of symplecticity fails, each by exactly sqrt(3)/10^60; on
-- the conjugate tableau by -sqrt(3)/10^60.  The claims no longer hold.
return {
  name = "gauss2_sqrt3_1e-60",
  s = 2,
  order = 4,
  symplectic = true,
  c = { "1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6" },
  A = {
    { "1/4 + sqrt(3)/10^60", "1/4 - sqrt(3)/6" },
    { "1/4 + sqrt(3)/6", "1/4" },
  },
  b = { "1/2", "1/2" },
}
