-- Candy-Rozmus (1991) fourth-order method.
-- Candy-Rozmus fourth-order method: for i = 1..4, p -= b_i h V'(q), then q +=
-- a_i h T'(p); b1 = 0, so it starts with a drift. Written with the authors'
-- coefficient expressions; mathematically the same method as forest_ruth_4.
-- As a PRK tableau it has s = 6 stages (4 drifts and 3 kicks per step; s =
-- drifts + kicks - 1).
-- J. Candy, W. Rozmus, "A symplectic integration algorithm for separable
-- Hamiltonian functions", J. Comput. Phys. 92 (1991) 230-256: a1 = a4 = (2 +
-- 2^(1/3) + 2^(-1/3))/6, a2 = a3 = (1 - 2^(1/3) - 2^(-1/3))/6, b1 = 0, b2 =
-- b4 = 1/(2 - 2^(1/3)), b3 = 1/(1 - 2^(2/3)).
--
-- Written as published: the kicks (p <- p - coef h dV/dq) and drifts
-- (q <- q + coef h dT/dp) in order of application; vigen converts them
-- exactly to a PRK tableau with bt = b (substeps - 1 stages), symplectic
-- for every H and, for separable H, explicit and equal to the splitting.
local a1 = "((2 + 2^(1/3) + 2^(-1/3))/6)"
local a2 = "((1 - 2^(1/3) - 2^(-1/3))/6)"
local b2 = "(1/(2 - 2^(1/3)))"
local b3 = "(1/(1 - 2^(2/3)))"
return {
  name = "candy_rozmus_4",
  order = 4,
  symplectic = true,
  source = "J. Candy, W. Rozmus, \"A symplectic integration algorithm for separable Hamiltonian functions\", J. Comput. Phys. 92 (1991) 230-256: a1 = a4 = (2 + 2^(1/3) + 2^(-1/3))/6, a2 = a3 = (1 - 2^(1/3) - 2^(-1/3))/6, b1 = 0, b2 = b4 = 1/(2 - 2^(1/3)), b3 = 1/(1 - 2^(2/3))",
  description = "Candy-Rozmus fourth-order method: for i = 1..4, p -= b_i h V'(q), then q += a_i h T'(p); b1 = 0, so it starts with a drift. Written with the authors' coefficient expressions; mathematically the same method as forest_ruth_4.",
  splitting = {
    { "drift", a1 },
    { "kick", b2 },
    { "drift", a2 },
    { "kick", b3 },
    { "drift", a2 },
    { "kick", b2 },
    { "drift", a1 },
  },
}
