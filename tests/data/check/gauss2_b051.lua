-- Gauss-2 (Hairer & Wanner II, Table IV.5.1) with b_1 mistyped as the short
-- decimal 0.51 (the ball [0.505, 0.515]) instead of 1/2 (test fixture for
-- vigen check): sum b = 1 and symplecticity fail, and both ask for b[1] = 1/2.
return {
  name = "gauss2_b051",
  s = 2,
  c = { "1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6" },
  A = {
    { "1/4", "1/4 - sqrt(3)/6" },
    { "1/4 + sqrt(3)/6", "1/4" },
  },
  b = { "0.51", "1/2" },
}
