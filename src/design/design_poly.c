/* design_poly.c — the conditions of a family as polynomials: evaluated in
 * double (the search) and in arb (the proof: exact rational coefficients,
 * so that a ball of unknowns gives a ball containing every value). */
#include <stdlib.h>
#include "design/design_internal.h"

void design_poly_clear(design_poly *p)
{
    if (p->coef) _fmpq_vec_clear(p->coef, p->nterms > 0 ? p->nterms : 1);
    free(p->coef_d);
    free(p->exp);
    p->coef = NULL;
    p->coef_d = NULL;
    p->exp = NULL;
    p->nterms = 0;
}

double design_poly_eval_d(const design_poly *p, const double *x)
{
    double sum = 0;
    for (slong t = 0; t < p->nterms; t++) {
        double term = p->coef_d[t];
        for (slong j = 0; j < p->k; j++)
            for (slong e = 0; e < p->exp[t * p->k + j]; e++) term *= x[j];
        sum += term;
    }
    return sum;
}

void design_poly_eval_arb(arb_t out, const design_poly *p, arb_srcptr x, slong prec)
{
    arb_t term, pw;
    arb_init(term);
    arb_init(pw);
    arb_zero(out);
    for (slong t = 0; t < p->nterms; t++) {
        arb_set_fmpq(term, p->coef + t, prec);
        for (slong j = 0; j < p->k; j++) {
            slong e = p->exp[t * p->k + j];
            if (e == 0) continue;
            arb_pow_ui(pw, x + j, (ulong)e, prec);
            arb_mul(term, term, pw, prec);
        }
        arb_add(out, out, term, prec);
    }
    arb_clear(term);
    arb_clear(pw);
}

void design_system_clear(design_system *sys)
{
    for (slong i = 0; i < sys->n; i++) {
        design_poly_clear(&sys->cond[i]);
        for (slong j = 0; j < sys->k; j++) design_poly_clear(&sys->dcond[i * sys->k + j]);
        free(sys->what[i]);
    }
    free(sys->cond);
    free(sys->dcond);
    free(sys->what);
    free(sys->h_degree);
    sys->cond = sys->dcond = NULL;
    sys->what = NULL;
    sys->h_degree = NULL;
    sys->n = 0;
}

void design_eval_d(double *f, double *jac, const design_system *sys, const slong *rows, slong m, const double *x)
{
    for (slong r = 0; r < m; r++) {
        slong i = rows ? rows[r] : r;
        if (f) f[r] = design_poly_eval_d(&sys->cond[i], x);
        if (jac)
            for (slong j = 0; j < sys->k; j++) jac[r * sys->k + j] = design_poly_eval_d(&sys->dcond[i * sys->k + j], x);
    }
}
