/* design_criterion.c — an optimality criterion solved as equations, so that
 * the optimum is proved like any root: the stationary points of an objective
 * f on the family {g(x) = 0} satisfy the Lagrange conditions
 *     g_i(x) = 0 (i < m),   df/dx_j + sum_i lambda_i dg_i/dx_j = 0 (j < k),
 * a square polynomial system in the k unknowns and the m multipliers
 * (g: m independent order conditions, design_square_rows).  The many-start
 * search, the Krawczyk proof and the checker then treat it as they treat
 * the order conditions (design_run.c); the method written is made of the
 * first k values.  Objectives:
 *   "error_norm"  f = the sum of the squares of the coefficients of the
 *                 Lyndon words of the first degree above the order in the
 *                 logarithm of the method (the principal error; up to
 *                 degree 4 these coefficients are the Lie coordinates on
 *                 the standard bracketings that `vigen check` reports, so f
 *                 is the square of its Lyndon 2-norm), the criterion of
 *                 McLachlan & Atela (Nonlinearity 5 (1992) 541);
 *   nearest       f = |x - x0|^2 / 2 with x0 given decimals, taken exactly:
 *                 the member of the family nearest to printed coefficients
 *                 (the orthogonal projection onto the order conditions).
 * A stationary point is a minimum, a maximum or a saddle of f on the family:
 * the output lists every one found with its error constants. */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_mpoly.h>
#include "design/design_internal.h"
#include "support/strbuf.h"

static void to_mpoly(fmpq_mpoly_t out, const design_poly *p, const fmpq_mpoly_ctx_t ctx)
{
    slong nvars = fmpq_mpoly_ctx_nvars(ctx);
    ulong *e = calloc((size_t)nvars, sizeof(ulong));
    fmpq_mpoly_zero(out, ctx);
    for (slong t = 0; t < p->nterms; t++) {
        for (slong j = 0; j < p->k; j++) e[j] = (ulong)p->exp[t * p->k + j];
        fmpq_mpoly_push_term_fmpq_ui(out, p->coef + t, e, ctx);
    }
    fmpq_mpoly_sort_terms(out, ctx);
    fmpq_mpoly_combine_like_terms(out, ctx);
    free(e);
}

static void from_mpoly(design_poly *d, const fmpq_mpoly_t m, slong k, const fmpq_mpoly_ctx_t ctx)
{
    slong n = fmpq_mpoly_length(m, ctx), alloc = n > 0 ? n : 1;
    d->k = k;
    d->nterms = n;
    d->coef = _fmpq_vec_init(alloc);
    d->coef_d = malloc((size_t)alloc * sizeof(double));
    d->exp = calloc((size_t)(alloc * k), sizeof(slong));
    d->degree = n > 0 ? fmpq_mpoly_total_degree_si(m, ctx) : 0;
    for (slong t = 0; t < n; t++) {
        fmpq_mpoly_get_term_coeff_fmpq(d->coef + t, m, t, ctx);
        d->coef_d[t] = fmpq_get_d(d->coef + t);
        fmpq_mpoly_get_term_exp_si(d->exp + t * k, m, t, ctx);
    }
}

/* A decimal ("-0.0420650803577195", "1e-3") as the exact rational. */
static int decimal_fmpq(fmpq_t out, const char *s)
{
    const char *p = s;
    int neg = 0;
    if (*p == '+' || *p == '-') neg = *p++ == '-';
    vigen_strbuf digits;
    vigen_strbuf_init(&digits);
    long frac = 0, any = 0, point = 0;
    for (; *p && *p != 'e' && *p != 'E'; p++) {
        if (*p == '.' && !point) point = 1;
        else if (*p >= '0' && *p <= '9') {
            vigen_strbuf_printf(&digits, "%c", *p);
            frac += point;
            any = 1;
        } else {
            any = 0;
            break;
        }
    }
    long ex = 0;
    if (any && (*p == 'e' || *p == 'E')) {
        char *end = NULL;
        ex = strtol(p + 1, &end, 10);
        if (end == p + 1 || *end || ex > 1000 || ex < -1000) any = 0;
    } else if (any && *p) {
        any = 0;
    }
    fmpz_t num, ten;
    fmpz_init(num);
    fmpz_init(ten);
    if (any && fmpz_set_str(num, digits.data, 10) == 0) {
        if (neg) fmpz_neg(num, num);
        fmpz_set(fmpq_numref(out), num);
        fmpz_one(fmpq_denref(out));
        ex -= frac;
        fmpz_set_ui(ten, 10);
        fmpz_pow_ui(ten, ten, (ulong)(ex < 0 ? -ex : ex));
        if (ex < 0) fmpq_div_fmpz(out, out, ten);
        else fmpq_mul_fmpz(out, out, ten);
    } else {
        any = 0;
    }
    fmpz_clear(num);
    fmpz_clear(ten);
    free(digits.data);
    return any ? VIGEN_OK : VIGEN_E_SPEC;
}

/* The objective f as a polynomial in the k unknowns. */
static int objective(fmpq_mpoly_t f, const design_system *sys, const vigen_design_spec *d, int q,
                     const fmpq_mpoly_ctx_t ctx, vigen_error *err)
{
    slong k = sys->k;
    fmpq_mpoly_t t;
    fmpq_mpoly_init(t, ctx);
    fmpq_mpoly_zero(f, ctx);
    int rc = VIGEN_OK;
    if (d->nnearest > 0) {
        fmpq_t x0, half;
        fmpq_init(x0);
        fmpq_init(half);
        fmpq_set_si(half, 1, 2);
        for (slong j = 0; j < k && rc == VIGEN_OK; j++) {
            if (decimal_fmpq(x0, d->nearest[j]) != VIGEN_OK) {
                rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: nearest: entry %ld, '%s', is not a decimal", d->path,
                                     (long)j + 1, d->nearest[j]);
                break;
            }
            fmpq_mpoly_gen(t, j, ctx);
            fmpq_mpoly_sub_fmpq(t, t, x0, ctx);
            fmpq_mpoly_mul(t, t, t, ctx);
            fmpq_mpoly_scalar_mul_fmpq(t, t, half, ctx);
            fmpq_mpoly_add(f, f, t, ctx);
        }
        fmpq_clear(x0);
        fmpq_clear(half);
    } else {
        /* the coefficients of the first degree above the order that does not
         * vanish identically (a symmetric family has odd degrees only) */
        vigen_design_spec next = *d;
        next.order = d->order + 2 <= VIGEN_DESIGN_MAX_ORDER ? d->order + 2 : VIGEN_DESIGN_MAX_ORDER;
        design_system hi;
        rc = design_family_conditions(&hi, &next, q, err);
        if (rc == VIGEN_OK) {
            int degree = 0;
            for (slong i = 0; i < hi.n; i++)
                if (hi.h_degree[i] > d->order && (degree == 0 || hi.h_degree[i] < degree)) degree = hi.h_degree[i];
            for (slong i = 0; i < hi.n; i++) {
                if (hi.h_degree[i] != degree) continue;
                to_mpoly(t, &hi.cond[i], ctx);
                fmpq_mpoly_mul(t, t, t, ctx);
                fmpq_mpoly_add(f, f, t, ctx);
            }
            if (degree == 0)
                rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: stationary: the family has no error term above order %d "
                                     "up to order %d", d->path, d->order, next.order);
            design_system_clear(&hi);
        }
    }
    fmpq_mpoly_clear(t, ctx);
    return rc;
}

int design_criterion_system(design_system *out, const design_system *sys, const slong *rows, slong m,
                            const vigen_design_spec *d, int q, vigen_error *err)
{
    memset(out, 0, sizeof *out);
    slong k = sys->k, nv = k + m;
    if (d->nnearest > 0 && d->nnearest != k)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: nearest: %ld values for the %ld unknowns of the family", d->path,
                               (long)d->nnearest, (long)k);
    if (m >= k)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: the order conditions leave no unknown free: there is nothing "
                               "to optimise (ask solutions = \"all\")", d->path);
    fmpq_mpoly_ctx_t ctx;
    fmpq_mpoly_ctx_init(ctx, nv, ORD_LEX);
    fmpq_mpoly_t f, t, u;
    fmpq_mpoly_init(f, ctx);
    fmpq_mpoly_init(t, ctx);
    fmpq_mpoly_init(u, ctx);
    int rc = objective(f, sys, d, q, ctx, err);
    if (rc == VIGEN_OK) {
        fmpq_mpoly_struct *eq = malloc((size_t)nv * sizeof(fmpq_mpoly_struct));
        for (slong i = 0; i < nv; i++) fmpq_mpoly_init(eq + i, ctx);
        for (slong i = 0; i < m; i++) to_mpoly(eq + i, &sys->cond[rows[i]], ctx);
        for (slong j = 0; j < k; j++) {
            fmpq_mpoly_derivative(eq + m + j, f, j, ctx);
            for (slong i = 0; i < m; i++) {
                to_mpoly(t, &sys->dcond[rows[i] * k + j], ctx);
                fmpq_mpoly_gen(u, k + i, ctx);
                fmpq_mpoly_mul(t, t, u, ctx);
                fmpq_mpoly_add(eq + m + j, eq + m + j, t, ctx);
            }
        }
        out->k = nv;
        out->n = nv;
        out->nmultipliers = m;
        out->cond = calloc((size_t)nv, sizeof(design_poly));
        out->dcond = calloc((size_t)(nv * nv), sizeof(design_poly));
        out->what = calloc((size_t)nv, sizeof(char *));
        out->h_degree = calloc((size_t)nv, sizeof(int));
        for (slong i = 0; i < nv; i++) {
            from_mpoly(&out->cond[i], eq + i, nv, ctx);
            for (slong j = 0; j < nv; j++) {
                fmpq_mpoly_derivative(t, eq + i, j, ctx);
                from_mpoly(&out->dcond[i * nv + j], t, nv, ctx);
            }
            out->what[i] = i < m ? vigen_strdup(sys->what[rows[i]] ? sys->what[rows[i]] : "pin")
                                 : vigen_strdup_printf("d/dx%ld", (long)(i - m + 1));
            out->h_degree[i] = i < m ? sys->h_degree[rows[i]] : 0;
        }
        for (slong i = 0; i < nv; i++) fmpq_mpoly_clear(eq + i, ctx);
        free(eq);
    }
    fmpq_mpoly_clear(f, ctx);
    fmpq_mpoly_clear(t, ctx);
    fmpq_mpoly_clear(u, ctx);
    fmpq_mpoly_ctx_clear(ctx);
    return rc;
}

int design_pinned_zero(const design_system *sys, const slong *rows, slong m, slong j)
{
    for (slong r = 0; r < m; r++) {
        const design_poly *p = &sys->cond[rows[r]];
        int ones = 0, others = 0;
        for (slong t = 0; t < p->nterms; t++) {
            if (fmpq_is_zero(p->coef + t)) continue;
            int xj = fmpq_is_one(p->coef + t);
            for (slong l = 0; l < p->k; l++) xj &= p->exp[t * p->k + l] == (l == j);
            ones += xj;
            others += !xj;
        }
        if (ones == 1 && others == 0) return 1;
    }
    return 0;
}

int design_criterion_replace(design_system *sys, slong **rows, slong *m, const vigen_design_spec *d, int q,
                             vigen_error *err)
{
    design_system aug;
    int rc = design_criterion_system(&aug, sys, *rows, *m, d, q, err);
    if (rc != VIGEN_OK) return rc;
    design_system_clear(sys);
    *sys = aug;
    *rows = realloc(*rows, (size_t)(aug.k + 1) * sizeof(slong));
    for (slong i = 0; i < aug.k; i++) (*rows)[i] = i;
    *m = aug.k;
    return VIGEN_OK;
}

slong design_criterion_search(double **roots, const design_system *aug, const slong *rows, const vigen_design_spec *d,
                              slong k, double box)
{
    if (d->nnearest == 0) return design_newton_search(roots, aug, rows, d->starts, d->seed, box);
    /* nearest: Newton from the given point with multipliers 0 */
    slong nv = aug->k;
    *roots = calloc((size_t)nv, sizeof(double));
    for (slong j = 0; j < k; j++) {
        fmpq_t x0;
        fmpq_init(x0);
        if (decimal_fmpq(x0, d->nearest[j]) == VIGEN_OK) (*roots)[j] = fmpq_get_d(x0);
        fmpq_clear(x0);
    }
    if (design_newton_polish(*roots, aug, rows, 50)) return 1;
    free(*roots);
    *roots = NULL;
    return 0;
}

char *design_criterion_how(const vigen_design_spec *d, slong nconditions)
{
    if (d->nnearest > 0)
        return vigen_strdup_printf("the member of the family nearest to the given coefficients: the %ld order "
                                   "conditions (polynomials in the steps, from the BCH series of the method) and the "
                                   "Lagrange conditions of |x - x0|^2 solved by Newton from x0, the root refined in "
                                   "arb and proved by the Krawczyk operator, the file certified by the checker",
                                   (long)nconditions);
    return vigen_strdup_printf("a stationary point of the Lyndon 2-norm of the principal error on the family: the %ld "
                               "order conditions (polynomials in the steps, from the BCH series of the method) and "
                               "the Lagrange conditions of that norm solved by Newton from %ld random starts, the root "
                               "refined in arb and proved by the Krawczyk operator, the file certified by the checker",
                               (long)nconditions, (long)d->starts);
}
