-- Spec (test fixture for vigen check): the Leok-Zhang method for the
-- polynomial basis 1, t, t^2 at the nodes 0, 1e-15, 1.  Two nodes 1e-15 apart
-- make the entries of size 1e14 with large cancellations; the method is
-- symplectic by construction (Leok & Zhang, Theorem 3), and its generated
-- decimal tableau must be found so within the precision of its digits.
return {
  name = "near_nodes",
  basis = { "1", "t", "t^2" },
  nodes = { "0", "1e-15", "1" },
}
