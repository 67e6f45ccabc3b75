/* design_pin.c — free parameters held fixed: a condition x_j - t = 0 per
 * free unknown, appended to the conditions of a family, so that the
 * conditions and the pins make a square system that the search and the
 * Krawczyk proof treat like any other.  t is a double, taken exactly (a
 * binary fraction), so the root proved is an exact member of the family. */
#include <stdlib.h>
#include <string.h>
#include "design/design_internal.h"
#include "support/strbuf.h"

slong design_system_add_pin(design_system *sys, slong j)
{
    slong k = sys->k, n = sys->n;
    sys->cond = realloc(sys->cond, (size_t)(n + 1) * sizeof(design_poly));
    sys->dcond = realloc(sys->dcond, (size_t)((n + 1) * k) * sizeof(design_poly));
    sys->what = realloc(sys->what, (size_t)(n + 1) * sizeof(char *));
    sys->h_degree = realloc(sys->h_degree, (size_t)(n + 1) * sizeof(int));
    design_poly *p = &sys->cond[n];
    memset(p, 0, sizeof *p);
    p->k = k;
    p->nterms = 2;
    p->coef = _fmpq_vec_init(2);
    p->coef_d = calloc(2, sizeof(double));
    p->exp = calloc((size_t)(2 * k), sizeof(slong));
    p->degree = 1;
    fmpq_one(p->coef + 0);
    p->coef_d[0] = 1;
    p->exp[j] = 1;                  /* x_j - t (t = 0 until set) */
    for (slong l = 0; l < k; l++) {
        design_poly *d = &sys->dcond[n * k + l];
        memset(d, 0, sizeof *d);
        d->k = k;
        d->nterms = l == j;
        d->coef = _fmpq_vec_init(1);
        d->coef_d = calloc(1, sizeof(double));
        d->exp = calloc((size_t)k, sizeof(slong));
        fmpq_one(d->coef);
        d->coef_d[0] = 1;
    }
    sys->what[n] = NULL;
    sys->h_degree[n] = 0;
    sys->n = n + 1;
    return n;
}

void design_system_set_pin(design_system *sys, slong row, double t)
{
    design_poly *p = &sys->cond[row];
    arf_t a;
    fmpz_t m, e;
    arf_init(a);
    fmpz_init(m);
    fmpz_init(e);
    arf_set_d(a, -t);
    arf_get_fmpz_2exp(m, e, a);    /* -t = m 2^e exactly */
    fmpz_set(fmpq_numref(p->coef + 1), m);
    fmpz_one(fmpq_denref(p->coef + 1));
    if (fmpz_sgn(e) >= 0) fmpq_mul_2exp(p->coef + 1, p->coef + 1, fmpz_get_ui(e));
    else fmpq_div_2exp(p->coef + 1, p->coef + 1, -fmpz_get_si(e));
    p->coef_d[1] = -t;
    arf_clear(a);
    fmpz_clear(m);
    fmpz_clear(e);
}

slong design_system_copy_pin(design_system *dst, const design_system *src, slong row)
{
    const design_poly *p = &src->cond[row];
    slong j = 0;
    while (j < src->k && p->exp[j] != 1) j++;
    slong r = design_system_add_pin(dst, j);
    fmpq_set(dst->cond[r].coef + 1, p->coef + 1);
    dst->cond[r].coef_d[1] = p->coef_d[1];
    return r;
}

/* the condition of row `row` moved to the front: the square subsystem takes
 * the conditions in order */
static void to_front(design_system *sys, slong row)
{
    slong k = sys->k;
    design_poly c = sys->cond[row];
    char *w = sys->what[row];
    memmove(sys->cond + 1, sys->cond, (size_t)row * sizeof *sys->cond);
    memmove(sys->what + 1, sys->what, (size_t)row * sizeof *sys->what);
    memmove(sys->h_degree + 1, sys->h_degree, (size_t)row * sizeof *sys->h_degree);
    sys->cond[0] = c;
    sys->what[0] = w;
    sys->h_degree[0] = 0;
    design_poly *dc = malloc((size_t)k * sizeof *dc);
    memcpy(dc, sys->dcond + row * k, (size_t)k * sizeof *dc);
    memmove(sys->dcond + k, sys->dcond, (size_t)(row * k) * sizeof *dc);
    memcpy(sys->dcond, dc, (size_t)k * sizeof *dc);
    free(dc);
}

/* the name of unknown j as design files write it: gamma3, a2, b1 */
static char *unknown_name(const vigen_design_spec *d, long j)
{
    if (d->base != NULL) return vigen_strdup_printf("gamma%ld", j + 1);
    long drifts = d->symmetric ? (d->stages + 2) / 2 : d->stages + 1;
    return j < drifts ? vigen_strdup_printf("a%ld", j + 1) : vigen_strdup_printf("b%ld", j - drifts + 1);
}

/* x_i - x_j = 0: a pin x_i - t whose constant term becomes -x_j */
static void add_equal(design_system *sys, slong i, slong j, const char *what)
{
    slong k = sys->k, row = design_system_add_pin(sys, i);
    design_poly *p = &sys->cond[row];
    fmpq_set_si(p->coef + 1, -1, 1);
    p->coef_d[1] = -1;
    p->exp[k + j] = 1;
    design_poly *dj = &sys->dcond[row * k + j];
    dj->nterms = 1;
    fmpq_set_si(dj->coef, -1, 1);
    dj->coef_d[0] = -1;
    sys->what[row] = vigen_strdup(what);
    to_front(sys, row);
}

int design_system_fix(design_system *sys, const vigen_design_spec *d)
{
    for (long e = d->nequal - 1; e >= 0; e--) {
        char *a = unknown_name(d, d->equal_unknown[2 * e]), *b = unknown_name(d, d->equal_unknown[2 * e + 1]);
        char *what = vigen_strdup_printf("%s = %s", a, b);
        free(a);
        free(b);
        add_equal(sys, d->equal_unknown[2 * e], d->equal_unknown[2 * e + 1], what);
        free(what);
    }
    for (long i = d->nfix - 1; i >= 0; i--) {
        fmpq_t v;
        fmpq_init(v);
        if (fmpq_set_str(v, d->fix_value[i], 10) != 0 || fmpz_is_zero(fmpq_denref(v))) {
            fmpq_clear(v);
            return VIGEN_E_SPEC;
        }
        fmpq_canonicalise(v);
        slong row = design_system_add_pin(sys, d->fix_unknown[i]);
        design_poly *p = &sys->cond[row];
        fmpq_neg(p->coef + 1, v);                  /* x_j - v, exactly */
        p->coef_d[1] = -fmpq_get_d(v);
        fmpq_clear(v);
        sys->what[row] = vigen_strdup_printf("%s = %s", d->fix_name[i], d->fix_value[i]);
        to_front(sys, row);
    }
    return VIGEN_OK;
}
