-- Forest-Ruth (1990) fourth-order method.
-- Forest-Ruth fourth-order method (position form): drift theta/2, kick theta,
-- drift (1-theta)/2, kick 1-2 theta, drift (1-theta)/2, kick theta, drift
-- theta/2, theta = 1/(2 - 2^(1/3)). The same method as Yoshida's triple jump
-- of position Verlet and as Candy-Rozmus (1991). As a PRK tableau it has s =
-- 6 stages (4 drifts and 3 kicks per step; s = drifts + kicks - 1).
-- E. Forest, R. D. Ruth, "Fourth-order symplectic integration", Physica D 43
-- (1990) 105-117 (theta = 1/(2 - 2^(1/3))).
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
-- coef*h*V'(q)): drift theta/2; kick theta; drift 1/2 - theta/2; kick 1 -
-- 2*theta; drift 1/2 - theta/2; kick theta; drift theta/2, where theta = 1/(2
-- - 2^(1/3)).
return {
  name = "forest_ruth_4",
  s = 6,
  order = 4,
  symplectic = true,
  source = "E. Forest, R. D. Ruth, \"Fourth-order symplectic integration\", Physica D 43 (1990) 105-117 (theta = 1/(2 - 2^(1/3)))",
  description = "Forest-Ruth fourth-order method (position form): drift theta/2, kick theta, drift (1-theta)/2, kick 1-2 theta, drift (1-theta)/2, kick theta, drift theta/2, theta = 1/(2 - 2^(1/3)). The same method as Yoshida's triple jump of position Verlet and as Candy-Rozmus (1991). As a PRK tableau it has s = 6 stages (4 drifts and 3 kicks per step; s = drifts + kicks - 1). Exact entries.",
  c = {
    "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2", "1/2", "1 - (1/(2 - 2^(1/3)))/2",
    "1 - (1/(2 - 2^(1/3)))/2",
  },
  A = {
    { "(1/(2 - 2^(1/3)))/2", "0", "0", "0", "0", "0" },
    { "(1/(2 - 2^(1/3)))/2", "0", "0", "0", "0", "0" },
    { "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2 - (1/(2 - 2^(1/3)))", "0", "0", "0" },
    { "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2 - (1/(2 - 2^(1/3)))", "0", "0", "0" },
    { -- row 5
      "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2 - (1/(2 - 2^(1/3)))",
      "1/2 - (1/(2 - 2^(1/3)))", "(1/(2 - 2^(1/3)))/2", "0",
    },
    { -- row 6
      "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2 - (1/(2 - 2^(1/3)))",
      "1/2 - (1/(2 - 2^(1/3)))", "(1/(2 - 2^(1/3)))/2", "0",
    },
  },
  b = {
    "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2 - (1/(2 - 2^(1/3)))",
    "1/2 - (1/(2 - 2^(1/3)))", "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2",
  },
  ct = {
    "0", "(1/(2 - 2^(1/3)))", "(1/(2 - 2^(1/3)))", "1 - (1/(2 - 2^(1/3)))", "1 - (1/(2 - 2^(1/3)))",
    "1",
  },
  At = {
    { "0", "0", "0", "0", "0", "0" },
    { "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "0", "0", "0", "0" },
    { "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "0", "0", "0", "0" },
    { -- row 4
      "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2 - (1/(2 - 2^(1/3)))",
      "1/2 - (1/(2 - 2^(1/3)))", "0", "0",
    },
    { -- row 5
      "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2 - (1/(2 - 2^(1/3)))",
      "1/2 - (1/(2 - 2^(1/3)))", "0", "0",
    },
    { -- row 6
      "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2 - (1/(2 - 2^(1/3)))",
      "1/2 - (1/(2 - 2^(1/3)))", "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2",
    },
  },
}
