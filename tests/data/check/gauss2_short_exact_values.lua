-- Gauss-2 (Hairer & Wanner II, Table IV.5.1) as a user review wrote it (test
-- fixture for vigen check): the irrational entries 1/2 -+ sqrt(3)/6 and
-- 1/4 -+ sqrt(3)/6 as 16-digit decimals, but the exact values b = 1/2 and
-- a11 = a22 = 1/4 as the short decimals "0.5" and "0.25".  Those are read as
-- the balls 0.5 +/- 0.05 and 0.25 +/- 0.005, far too wide to decide anything:
-- the claim below (false: no 2-stage Runge-Kutta method has order 5, an
-- s-stage method has order <= 2s) must not be reported as holding, and the
-- order must not be reported as 5.  The checker names the short entries and
-- suggests the fractions 1/2 and 1/4.
return {
  name = "gauss2_short_exact_values",
  s = 2,
  order = 5,
  c = { "0.2113248654051871", "0.7886751345948129" },
  A = {
    { "0.25", "-0.03867513459481288" },
    { "0.5386751345948129", "0.25" },
  },
  b = { "0.5", "0.5" },
}
