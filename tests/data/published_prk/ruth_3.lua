-- Ruth (1983) third-order method.
-- Ruth's third-order explicit symplectic method: for i = 1..3, p += -c_i h
-- V'(q), then q += d_i h T'(p). As a PRK tableau it has s = 5 stages (3
-- drifts and 3 kicks per step; s = drifts + kicks - 1).
-- R. D. Ruth, "A canonical integration technique", IEEE Trans. Nucl. Sci.
-- NS-30(4) (1983) 2669-2671: third-order method with c = (7/24, 3/4, -1/24)
-- (momentum steps) and d = (2/3, -2/3, 1) (position steps).
--
-- Splitting method for separable H = T(p) + V(q) written as a PRK method with
-- b~ = b: the drift q += a h T'(p) and kick p -= b h V'(q) substeps are cut
-- into stages (one stage per pair of overlapping drift/kick pieces), so that
-- A_ij = w_j when the drift of stage j precedes the kick of stage i and A~_ij
-- = w_j when the kick of stage j precedes the drift of stage i, b = b~ = w.
-- The tableau satisfies b_i at_ij + b_j a_ji = b_i b_j exactly (symplectic
-- for every H); for separable H it is explicit and one PRK step equals one
-- step of the splitting scheme.
--
-- Scheme (in order of application; drift: q += coef*h*T'(p), kick: p -=
-- coef*h*V'(q)): kick 7/24; drift 2/3; kick 3/4; drift -2/3; kick -1/24;
-- drift 1.
return {
  name = "ruth_3",
  s = 5,
  order = 3,
  symplectic = true,
  source = "R. D. Ruth, \"A canonical integration technique\", IEEE Trans. Nucl. Sci. NS-30(4) (1983) 2669-2671: third-order method with c = (7/24, 3/4, -1/24) (momentum steps) and d = (2/3, -2/3, 1) (position steps)",
  description = "Ruth's third-order explicit symplectic method: for i = 1..3, p += -c_i h V'(q), then q += d_i h T'(p). As a PRK tableau it has s = 5 stages (3 drifts and 3 kicks per step; s = drifts + kicks - 1). Exact entries.",
  c = { "0", "2/3", "2/3", "0", "0" },
  A = {
    { "0", "0", "0", "0", "0" },
    { "7/24", "3/8", "0", "0", "0" },
    { "7/24", "3/8", "0", "0", "0" },
    { "7/24", "3/8", "3/8", "-25/24", "0" },
    { "7/24", "3/8", "3/8", "-25/24", "0" },
  },
  b = { "7/24", "3/8", "3/8", "-25/24", "1" },
  ct = { "7/24", "7/24", "25/24", "25/24", "1" },
  At = {
    { "7/24", "0", "0", "0", "0" },
    { "7/24", "0", "0", "0", "0" },
    { "7/24", "3/8", "3/8", "0", "0" },
    { "7/24", "3/8", "3/8", "0", "0" },
    { "7/24", "3/8", "3/8", "-25/24", "1" },
  },
}
