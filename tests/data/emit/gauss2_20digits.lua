-- Gauss-2 with entries rounded to 20 significant digits: enough to round
-- correctly to double (53 bits), not to float128 (113 bits need about 35
-- digits); for long double (64 bits) it depends on the entry.
return {
  name = "gauss2_20digits", s = 2,
  c = { "0.21132486540518711775", "0.78867513459481288225" },
  A = { { "1/4", "-0.038675134594812882255" },
        { "0.53867513459481288225", "1/4" } },
  b = { "1/2", "1/2" },
  order = 4, symplectic = true,
}
