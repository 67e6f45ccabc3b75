-- Gauss-2 rounded to 6 digits (test fixture for vigen check): the conditions
-- that hold can only be certified to about 1e-6, which is not enough to call
-- them holding (radius <= 2^-30): they are undecided, whatever the precision.
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
