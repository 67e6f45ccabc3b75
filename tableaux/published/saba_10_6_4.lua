-- Blanes, Casas, Farres, Laskar, Makazaga & Murua (2013): the ABA method of
-- generalized order (10,6,4) for H = A + eps B (A integrable, here the
-- Kepler part), 9 steps of A and 8 of B, symmetric: error O(eps h^10 +
-- eps^2 h^6 + eps^3 h^4); classical order 4.  The coefficients are those
-- published with 40 digits, as decimals (rounded: the checker reads each
-- as the ball of half a unit in its last digit); a5 = 1 - 2(a1+a2+a3+a4)
-- and b4 = 1/2 - (b1+b2+b3) to those digits.
-- S. Blanes, F. Casas, A. Farres, J. Laskar, J. Makazaga, A. Murua, "New
-- families of symplectic splitting methods for numerical integration in
-- dynamical astronomy", Appl. Numer. Math. 68 (2013) 58-72; the 40-digit
-- coefficients: A. Farres, J. Laskar, S. Blanes, F. Casas, J. Makazaga,
-- A. Murua, "High precision symplectic integrators for the Solar System",
-- Celest. Mech. Dyn. Astron. 116 (2013) 141-174, Table 3, ABA(10,6,4).
local a1 = "0.03809449742241219545697532230863756534060"
local a2 = "0.1452987161169137492940200726606637497442"
local a3 = "0.2076276957255412507162056113249882065158"
local a4 = "0.4359097036515261592231548624010651844006"
local a5 = "-0.6538612258327867093807117373907094120024"
local b1 = "0.09585888083707521061077150377145884776921"
local b2 = "0.2044461531429987806805077839164344779763"
local b3 = "0.2170703479789911017143385924306336714532"
local b4 = "-0.01737538195906509300561788011852699719871"
return {
  name = "saba_10_6_4",
  order = 4,
  generalized_order = {10, 6, 4},
  symplectic = true,
  source = "S. Blanes, F. Casas, A. Farres, J. Laskar, J. Makazaga, A. Murua, \"New families of symplectic splitting methods for numerical integration in dynamical astronomy\", Appl. Numer. Math. 68 (2013) 58-72: ABA(10,6,4); 40-digit coefficients as in A. Farres et al., \"High precision symplectic integrators for the Solar System\", Celest. Mech. Dyn. Astron. 116 (2013) 141-174",
  description = "The ABA(10,6,4) method of Blanes et al. for H = A + eps B: a1 b1 a2 b2 a3 b3 a4 b4 a5 b4 a4 b3 a3 b2 a2 b1 a1 (A the Kepler flow, B the interaction); generalized order (10,6,4), error O(eps h^10 + eps^2 h^6 + eps^3 h^4), classical order 4.",
  flows = { "kepler", "interaction" },
  perturbation = "interaction",
  splitting = {
    { "kepler", a1 }, { "interaction", b1 },
    { "kepler", a2 }, { "interaction", b2 },
    { "kepler", a3 }, { "interaction", b3 },
    { "kepler", a4 }, { "interaction", b4 },
    { "kepler", a5 },
    { "interaction", b4 }, { "kepler", a4 },
    { "interaction", b3 }, { "kepler", a3 },
    { "interaction", b2 }, { "kepler", a2 },
    { "interaction", b1 }, { "kepler", a1 },
  },
}
