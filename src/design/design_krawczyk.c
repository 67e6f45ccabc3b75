/* design_krawczyk.c — the proof that an exact root exists near a computed
 * one: Newton in arb, then the Krawczyk test (Krawczyk 1969; Moore 1977;
 * Neumaier, Interval Methods for Systems of Equations, 1990, Thm 5.1.7).
 *
 * For F: R^k -> R^k, a box X = m +- r, Y any matrix and J(X) an interval
 * matrix enclosing the Jacobian over X, the Krawczyk operator is
 *     K(X) = m - Y F(m) + (I - Y J(X)) (X - m).
 * If K(X) lies in the interior of X, F has exactly one root in X, and it lies
 * in K(X).  F(m) and J(X) are evaluated in ball arithmetic from the exact
 * rational coefficients of the conditions, so the inclusion is certified;
 * Y (an approximate inverse of J(m)) need not be.
 */
#include "design/design_internal.h"

/* J over the balls x (k x k, the rows of the subsystem). */
static void jacobian(arb_mat_t J, const design_system *sys, const slong *rows, arb_srcptr x, slong prec)
{
    for (slong i = 0; i < sys->k; i++)
        for (slong j = 0; j < sys->k; j++)
            design_poly_eval_arb(arb_mat_entry(J, i, j), &sys->dcond[rows[i] * sys->k + j], x, prec);
}

static void values(arb_mat_t f, const design_system *sys, const slong *rows, arb_srcptr x, slong prec)
{
    for (slong i = 0; i < sys->k; i++) design_poly_eval_arb(arb_mat_entry(f, i, 0), &sys->cond[rows[i]], x, prec);
}

int design_krawczyk_test(arb_ptr out, const design_system *sys, const slong *rows, arb_srcptr mid, const mag_t rad,
                         slong prec)
{
    slong k = sys->k;
    arb_ptr m = _arb_vec_init(k), X = _arb_vec_init(k);
    arb_mat_t f, Jm, Y, JX, M, d, Kv, t;
    arb_mat_init(f, k, 1);
    arb_mat_init(Jm, k, k);
    arb_mat_init(Y, k, k);
    arb_mat_init(JX, k, k);
    arb_mat_init(M, k, k);
    arb_mat_init(d, k, 1);
    arb_mat_init(Kv, k, 1);
    arb_mat_init(t, k, 1);
    for (slong j = 0; j < k; j++) {
        arf_set(arb_midref(m + j), arb_midref(mid + j));
        arf_set(arb_midref(X + j), arb_midref(mid + j));
        mag_set(arb_radref(X + j), rad);
        arb_zero(arb_mat_entry(d, j, 0));
        mag_set(arb_radref(arb_mat_entry(d, j, 0)), rad);   /* X - m = [-r, r] */
    }
    values(f, sys, rows, m, prec);
    jacobian(Jm, sys, rows, m, prec);
    arb_mat_get_mid(Jm, Jm);
    int ok = arb_mat_approx_inv(Y, Jm, prec);
    if (ok) {
        arb_mat_get_mid(Y, Y);
        jacobian(JX, sys, rows, X, prec);
        arb_mat_mul(M, Y, JX, prec);
        arb_mat_neg(M, M);
        for (slong j = 0; j < k; j++) arb_add_ui(arb_mat_entry(M, j, j), arb_mat_entry(M, j, j), 1, prec);
        arb_mat_mul(Kv, M, d, prec);            /* (I - Y J(X)) (X - m) */
        arb_mat_mul(t, Y, f, prec);             /* Y F(m) */
        arb_mat_sub(Kv, Kv, t, prec);
        for (slong j = 0; j < k && ok; j++) {
            arb_add(out + j, m + j, arb_mat_entry(Kv, j, 0), prec);
            ok = arb_is_finite(out + j) && arb_contains_interior(X + j, out + j);
        }
    }
    arb_mat_clear(f);
    arb_mat_clear(Jm);
    arb_mat_clear(Y);
    arb_mat_clear(JX);
    arb_mat_clear(M);
    arb_mat_clear(d);
    arb_mat_clear(Kv);
    arb_mat_clear(t);
    _arb_vec_clear(m, k);
    _arb_vec_clear(X, k);
    return ok;
}

/* Newton steps at prec on the midpoints of x, until the step is below
 * 2^-(prec - 16) of x or iterations run out; 0 when a step fails. */
static int refine(arb_ptr x, const design_system *sys, const slong *rows, slong prec)
{
    slong k = sys->k;
    arb_mat_t f, J, dx;
    arb_mat_init(f, k, 1);
    arb_mat_init(J, k, k);
    arb_mat_init(dx, k, 1);
    int ok = 1;
    for (int it = 0; it < 64 && ok; it++) {
        values(f, sys, rows, x, prec);
        jacobian(J, sys, rows, x, prec);
        arb_mat_get_mid(f, f);
        arb_mat_get_mid(J, J);
        ok = arb_mat_approx_solve(dx, J, f, prec);
        if (!ok) break;
        int small = 1;
        for (slong j = 0; j < k; j++) {
            arb_sub(x + j, x + j, arb_mat_entry(dx, j, 0), prec);
            arb_get_mid_arb(x + j, x + j);
            if (!arf_is_zero(arb_midref(arb_mat_entry(dx, j, 0))) &&
                arf_cmpabs_2exp_si(arb_midref(arb_mat_entry(dx, j, 0)), -(prec - 16)) > 0)
                small = 0;
        }
        if (small) break;
    }
    arb_mat_clear(f);
    arb_mat_clear(J);
    arb_mat_clear(dx);
    return ok;
}

int design_krawczyk_prove(arb_ptr box, const design_system *sys, const slong *rows, const double *x0, slong prec)
{
    slong k = sys->k;
    arb_ptr x = _arb_vec_init(k);
    for (slong j = 0; j < k; j++) arb_set_d(x + j, x0[j]);
    int ok = refine(x, sys, rows, prec);
    /* the smallest box first: the proof then encloses the root most tightly */
    static const double fraction[] = {1.0, 0.75, 0.5, 0.25};
    mag_t rad;
    mag_init(rad);
    int proved = 0;
    for (int i = 0; ok && !proved && i < 4; i++) {
        slong e = (slong)((double)prec * fraction[i]) - 24;
        if (e < 8) e = 8;
        mag_one(rad);
        mag_mul_2exp_si(rad, rad, -e);
        proved = design_krawczyk_test(box, sys, rows, x, rad, prec);
    }
    mag_clear(rad);
    _arb_vec_clear(x, k);
    return proved;
}
