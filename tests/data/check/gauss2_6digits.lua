-- Gauss-2 rounded to 6 digits (test fixture for vigen check): every entry
-- stands for the ball of half a unit in its last digit.  The conditions of
-- order <= 4 hold within the precision of the data (their balls contain 0);
-- those of order 5 fail by far more than the data's radii (Gauss-2 has order
-- exactly 4).
return {
  name = "gauss2_6digits",
  s = 2,
  c = { "0.211325", "0.788675" },
  A = {
    { "0.250000", "-0.0386751" },
    { "0.538675", "0.250000" },
  },
  b = { "0.500000", "0.500000" },
}
