-- Gauss-2 (Hairer & Wanner II, Table IV.5.1) with A[1][2] = 1/4 - sqrt(3)/6
-- written as 1/4 - sqrt(6)/(6*sqrt(2)) (test fixture for vigen check): the
-- same exact tableau (sqrt(6)/sqrt(2) = sqrt(3)), of order 4 and symplectic,
-- but its text mixes square roots of 2, 3 and 6, so no single quadratic field
-- is recognised and the holds are decided by the numeric rule.
return {
  name = "gauss2_sqrt2_sqrt3",
  s = 2,
  order = 4,
  symplectic = true,
  c = { "1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6" },
  A = {
    { "1/4", "1/4 - sqrt(6)/(6*sqrt(2))" },
    { "1/4 + sqrt(3)/6", "1/4" },
  },
  b = { "1/2", "1/2" },
}
