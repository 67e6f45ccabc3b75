-- Yoshida (1990) fourth-order triple jump of velocity Verlet.
-- Yoshida's fourth-order triple jump applied to the p-first (velocity,
-- kick-drift-kick) Stormer-Verlet step: kick x1/2, drift x1, kick (x0+x1)/2,
-- drift x0, kick (x0+x1)/2, drift x1, kick x1/2. (The triple jump of the
-- q-first step is forest_ruth_4.) As a PRK tableau it has s = 6 stages (3
-- drifts and 4 kicks per step; s = drifts + kicks - 1).
-- H. Yoshida, "Construction of higher order symplectic integrators", Phys.
-- Lett. A 150 (1990) 262-268, Sect. 4: S4(h) = S2(x1 h) S2(x0 h) S2(x1 h), x1
-- = 1/(2 - 2^(1/3)), x0 = -2^(1/3)/(2 - 2^(1/3)) = 1 - 2 x1.
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
-- coef*h*V'(q)): kick x1/2; drift x1; kick 1/2 - x1/2; drift 1 - 2*x1; kick
-- 1/2 - x1/2; drift x1; kick x1/2, where x1 = 1/(2 - 2^(1/3)).
return {
  name = "yoshida_4",
  s = 6,
  order = 4,
  symplectic = true,
  source = "H. Yoshida, \"Construction of higher order symplectic integrators\", Phys. Lett. A 150 (1990) 262-268, Sect. 4: S4(h) = S2(x1 h) S2(x0 h) S2(x1 h), x1 = 1/(2 - 2^(1/3)), x0 = -2^(1/3)/(2 - 2^(1/3)) = 1 - 2 x1",
  description = "Yoshida's fourth-order triple jump applied to the p-first (velocity, kick-drift-kick) Stormer-Verlet step: kick x1/2, drift x1, kick (x0+x1)/2, drift x0, kick (x0+x1)/2, drift x1, kick x1/2. (The triple jump of the q-first step is forest_ruth_4.) As a PRK tableau it has s = 6 stages (3 drifts and 4 kicks per step; s = drifts + kicks - 1). Exact entries.",
  c = {
    "0", "(1/(2 - 2^(1/3)))", "(1/(2 - 2^(1/3)))", "1 - (1/(2 - 2^(1/3)))", "1 - (1/(2 - 2^(1/3)))",
    "1",
  },
  A = {
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
  b = {
    "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2 - (1/(2 - 2^(1/3)))",
    "1/2 - (1/(2 - 2^(1/3)))", "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2",
  },
  ct = {
    "(1/(2 - 2^(1/3)))/2", "(1/(2 - 2^(1/3)))/2", "1/2", "1/2", "1 - (1/(2 - 2^(1/3)))/2",
    "1 - (1/(2 - 2^(1/3)))/2",
  },
  At = {
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
}
