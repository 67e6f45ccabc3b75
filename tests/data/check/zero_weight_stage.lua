-- The explicit Euler method written with a second stage of weight 0 that no
-- stage uses (column 2 of A is 0): the stage does nothing, and the method
-- is explicit Euler (order 1; on q'' = -omega^2 q its step has
-- det R = 1 + (h omega)^2 > 1, unstable for every h omega > 0).
return {
  name = "zero_weight_stage",
  s = 2,
  c = { "0", "1/3" },
  A = {
    { "0", "0" },
    { "1/3", "0" },
  },
  b = { "1", "0" },
}
