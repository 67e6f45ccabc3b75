-- sum b = 1 with cancellation (3 - 2) and one short decimal: the ball of
-- b[1] + b[2] - 1 has radius 0.00005 + 0.005 = 0.00505, below 2^-10 of the
-- size of its terms (|3| + |-2| + 1 = 6: 0.00586) but above 2^-10 of
-- |sum| + 1 = 2.  The row-sum check and the order-1 tree are one condition
-- and must give one verdict (holds within the precision of the data).
return {
  name = "short_among_long",
  s = 2,
  c = { "0", "0" },
  A = { { "0", "0" }, { "0", "0" } },
  b = { "3.0000", "-2.00" },
}
