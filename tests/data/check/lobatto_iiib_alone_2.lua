-- Lobatto IIIB, s = 2, alone as a Runge-Kutta method, with the Lobatto nodes
-- as its c (E. Hairer, G. Wanner, Solving ODEs II, sec. IV.5, Table 5.9;
-- GNI sec. II.1.4): its rows of A are equal, so its two stages are one, and
-- the method is the implicit midpoint rule written with two stages.  Its
-- row sums (1/2, 1/2) are not its c, and it is not symplectic as a tableau
-- (b_i a_ij + b_j a_ji = b_i b_j fails), yet on q'' = -omega^2 q its step
-- has det R = 1 for every h omega and is stable for every h omega.
return {
  name = "lobatto_iiib_alone_2",
  s = 2,
  c = { "0", "1" },
  A = {
    { "1/2", "0" },
    { "1/2", "0" },
  },
  b = { "1/2", "1/2" },
}
