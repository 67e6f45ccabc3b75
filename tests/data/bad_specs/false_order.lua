-- The 2-stage Gauss method (Lagrange basis at the Gauss-Legendre nodes) has
-- order 4 (Hairer, Lubich & Wanner, GNI sec. II.1.3), not 5: the claim is
-- refused when the tableau is generated, naming the bushy tree of order 5.
return { name = "false_order", order = 5, nodes = gauss_legendre(2), basis = "lagrange" }
