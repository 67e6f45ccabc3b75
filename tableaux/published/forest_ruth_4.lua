-- Forest-Ruth (1990) fourth-order method.
-- Forest-Ruth fourth-order method (position form): drift theta/2, kick theta,
-- drift (1-theta)/2, kick 1-2 theta, drift (1-theta)/2, kick theta, drift
-- theta/2, theta = 1/(2 - 2^(1/3)). The same method as Yoshida's triple jump
-- of position Verlet and as Candy-Rozmus (1991). As a PRK tableau it has s =
-- 6 stages (4 drifts and 3 kicks per step; s = drifts + kicks - 1).
-- E. Forest, R. D. Ruth, "Fourth-order symplectic integration", Physica D 43
-- (1990) 105-117 (theta = 1/(2 - 2^(1/3))).
--
-- Written as published: the kicks (p <- p - coef h dV/dq) and drifts
-- (q <- q + coef h dT/dp) in order of application; vigen converts them
-- exactly to a PRK tableau with bt = b (substeps - 1 stages), symplectic
-- for every H and, for separable H, explicit and equal to the splitting.
local theta = "(1/(2 - 2^(1/3)))"
return {
  name = "forest_ruth_4",
  order = 4,
  symplectic = true,
  source = "E. Forest, R. D. Ruth, \"Fourth-order symplectic integration\", Physica D 43 (1990) 105-117 (theta = 1/(2 - 2^(1/3)))",
  description = "Forest-Ruth fourth-order method (position form): drift theta/2, kick theta, drift (1-theta)/2, kick 1-2 theta, drift (1-theta)/2, kick theta, drift theta/2, theta = 1/(2 - 2^(1/3)). The same method as Yoshida's triple jump of position Verlet and as Candy-Rozmus (1991).",
  splitting = {
    { "drift", theta .. "/2" },
    { "kick", theta },
    { "drift", "1/2 - " .. theta .. "/2" },
    { "kick", "1 - 2*" .. theta },
    { "drift", "1/2 - " .. theta .. "/2" },
    { "kick", theta },
    { "drift", theta .. "/2" },
  },
}
