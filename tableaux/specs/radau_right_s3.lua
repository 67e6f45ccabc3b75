-- Lagrange polynomials at the 3 right Radau nodes: A is Radau IIA, At its symplectic partner
return {
  name = "radau_right_s3",
  description = "Lagrange polynomials at the 3 right Radau nodes: A is Radau IIA, At its symplectic partner",
  source = "Hairer & Wanner, Solving ODEs II, sec. IV.5 (Radau IIA nodes)",
  basis = "lagrange",
  nodes = radau_right(3),
}
