-- Spec (test fixture for vigen check): Lagrange polynomials at the 4
-- equispaced nodes 0, 1/3, 2/3, 1.  The Leok-Zhang method of a polynomial
-- basis is the collocation method at its nodes: (c, A, b) satisfies C(4) and
-- B(4) (b = 1/8, 3/8, 3/8, 1/8, Simpson's 3/8 rule, exact for cubics only:
-- sum b_i c_i^4 = 11/54, not 1/5), so B(5) fails and (c, A, b) alone has order
-- 4 (Hairer, Norsett & Wanner I, Thm II.7.8).  Generated with 2 digits it must
-- not be reported as of order 6 or B(>=9).
return {
  name = "equispaced4",
  basis = "lagrange",
  nodes = equispaced(4),
}
