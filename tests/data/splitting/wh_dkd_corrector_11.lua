-- The Wisdom-Holman drift-kick-drift (Kepler h/2, interaction h, Kepler h/2) kernel processed by the
-- symplectic corrector of order 11 of the runtime (vigen_nbody_corrector_apply,
-- docs/splitting.md "Symplectic correctors"): a_i = i sqrt(7/40) exactly, b_i
-- the runtime's 17-digit values (vigen_nbody_corrector_coefficients).  The
-- corrector as written is the runtime's C^-1 (true state -> kernel's state),
-- applied first in the step C^-1 K C:
--   for i = m..1:  K(a_i h) I(b_i h) K(-2 a_i h) I(-b_i h) K(a_i h).
-- Test data: the checker decides the generalized order of the processed
-- step independently of the runtime's derivation (tests/cli/cli_corrector_orders.sh).
return {
  name = "wh_dkd_corrector_11",
  symplectic = true,
  generalized_order = { 12, 2 },
  flows = { "kepler", "interaction" },
  perturbation = "interaction",
  splitting = {
    { "kepler", "1/2" },
    { "interaction", "1" },
    { "kepler", "1/2" },
  },
  corrector = {
    { "kepler", "5*sqrt(7/40)" }, { "interaction", "-0.00040723159295709302" }, { "kepler", "-2*5*sqrt(7/40)" }, { "interaction", "0.00040723159295709302" }, { "kepler", "5*sqrt(7/40)" },
    { "kepler", "4*sqrt(7/40)" }, { "interaction", "0.0046974430584590708" }, { "kepler", "-2*4*sqrt(7/40)" }, { "interaction", "-0.0046974430584590708" }, { "kepler", "4*sqrt(7/40)" },
    { "kepler", "3*sqrt(7/40)" }, { "interaction", "-0.024618157184039893" }, { "kepler", "-2*3*sqrt(7/40)" }, { "interaction", "0.024618157184039893" }, { "kepler", "3*sqrt(7/40)" },
    { "kepler", "2*sqrt(7/40)" }, { "interaction", "0.076243227362577298" }, { "kepler", "-2*2*sqrt(7/40)" }, { "interaction", "-0.076243227362577298" }, { "kepler", "2*sqrt(7/40)" },
    { "kepler", "sqrt(7/40)" }, { "interaction", "-0.14518678949768549" }, { "kepler", "-2*sqrt(7/40)" }, { "interaction", "0.14518678949768549" }, { "kepler", "sqrt(7/40)" },
  },
}
