-- The classical Runge-Kutta method of order 4 applied to q and p alike (no
-- At: the same tableau for both parts).  Not symplectic: b_i a_ij + b_j a_ji
-- = b_i b_j fails (e.g. i = j = 1: 2 b_1 a_11 = 0 but b_1^2 = 1/36), so its
-- energy error drifts on Hamiltonian problems, which tests/cli/cli_try.sh
-- uses as the counterpart of a symplectic method.
-- E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential
-- Equations I, 2nd ed., Springer 1993, Sect. II.1, Table 1.2 (Kutta 1901).
return {
  name = "rk4",
  s = 4,
  order = 4,
  c = { "0", "1/2", "1/2", "1" },
  A = {
    { "0", "0", "0", "0" },
    { "1/2", "0", "0", "0" },
    { "0", "1/2", "0", "0" },
    { "0", "0", "1", "0" },
  },
  b = { "1/6", "1/3", "1/3", "1/6" },
}
