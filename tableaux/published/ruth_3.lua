-- Ruth (1983) third-order method.
-- Ruth's third-order explicit symplectic method: for i = 1..3, p += -c_i h
-- V'(q), then q += d_i h T'(p). As a PRK tableau it has s = 5 stages (3
-- drifts and 3 kicks per step; s = drifts + kicks - 1).
-- R. D. Ruth, "A canonical integration technique", IEEE Trans. Nucl. Sci.
-- NS-30(4) (1983) 2669-2671: third-order method with c = (7/24, 3/4, -1/24)
-- (momentum steps) and d = (2/3, -2/3, 1) (position steps).
--
-- Written as published: the kicks (p <- p - coef h dV/dq) and drifts
-- (q <- q + coef h dT/dp) in order of application; vigen converts them
-- exactly to a PRK tableau with bt = b (substeps - 1 stages), symplectic
-- for every H and, for separable H, explicit and equal to the splitting.
return {
  name = "ruth_3",
  order = 3,
  symplectic = true,
  source = "R. D. Ruth, \"A canonical integration technique\", IEEE Trans. Nucl. Sci. NS-30(4) (1983) 2669-2671: third-order method with c = (7/24, 3/4, -1/24) (momentum steps) and d = (2/3, -2/3, 1) (position steps)",
  description = "Ruth's third-order explicit symplectic method: for i = 1..3, p += -c_i h V'(q), then q += d_i h T'(p).",
  splitting = {
    { "kick", "7/24" },
    { "drift", "2/3" },
    { "kick", "3/4" },
    { "drift", "-2/3" },
    { "kick", "-1/24" },
    { "drift", "1" },
  },
}
