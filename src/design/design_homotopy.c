/* design_homotopy.c — every complex root of a square subsystem, by a
 * total-degree homotopy: the start system G_i(x) = x_i^(d_i) - 1 (d_i the
 * degree of condition i) has exactly the Bezout number of roots, all known,
 * and H(x, t) = (1 - t) gamma G(x) + t F(x), gamma a random complex number of
 * modulus 1, carries each to a root of F at t = 1 or off to infinity (the
 * "gamma trick": for all but finitely many gamma no path meets a singular
 * point before t = 1).  Each path is followed by an Euler predictor and a
 * Newton corrector in complex double with an adapted step.
 *
 * When every path ends at a nonsingular root or diverges, and no two paths
 * end at one root, the finite endpoints are every isolated root of F, so its
 * real roots are all among them: that is how `vigen design` states
 * completeness.  It is not a proof: the tracking is in floating point, and a
 * path may jump to a neighbour's (two paths at one root betray that, and the
 * claim is then withdrawn); certified tracking is not done (docs/design.md). */
/* GSL's headers first: its gsl_complex stays the struct its functions take */
#include <gsl/gsl_complex_math.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_rng.h>
#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "design/design_internal.h"
#include "support/progress.h"

#define STEP_FIRST 0.01
#define STEP_MAX 0.05
#define STEP_MIN 1e-14
#define CORRECTOR_ITERATIONS 3
#define CORRECTOR_TOL 1e-10
#define AT_INFINITY 1e-7
#define ENDGAME_POINTS 12
#define DECAY_EXPONENT 0.05
#define ENDPOINT_ITERATIONS 30
#define ENDPOINT_TOL 1e-11
#define SINGULAR_PIVOT 1e-9
#define REAL_TOL 1e-8
#define SAME_ROOT 1e-6

typedef double complex cplx;

typedef struct {
    const design_system *sys;
    const slong *rows;
    slong k;
    int *deg;
    cplx gamma;
    cplx *patch;                 /* the affine chart sum_j patch_j z_j = 1 of projective space */
    gsl_matrix_complex *jac, *pjac;
    gsl_vector_complex *rhs, *dx, *prhs, *pdx;
    gsl_permutation *perm, *pperm;
    double step_max;             /* the largest step in t (smaller on a second try of a lost path) */
} tracker;

static cplx poly_eval_c(const design_poly *p, const cplx *x)
{
    cplx sum = 0;
    for (slong t = 0; t < p->nterms; t++) {
        cplx term = p->coef_d[t];
        for (slong j = 0; j < p->k; j++)
            for (slong e = 0; e < p->exp[t * p->k + j]; e++) term *= x[j];
        sum += term;
    }
    return sum;
}

static cplx cpow_int(cplx z, int n)
{
    cplx r = 1;
    for (int i = 0; i < n; i++) r *= z;
    return r;
}

/* H(x, t) into h (when non-NULL), dH/dt into ht (when non-NULL), and the
 * Jacobian H_x into tr->jac */
static void eval_h(tracker *tr, cplx *h, cplx *ht, const cplx *x, double t)
{
    slong k = tr->k;
    for (slong i = 0; i < k; i++) {
        const design_poly *f = &tr->sys->cond[tr->rows[i]];
        cplx fi = poly_eval_c(f, x), gi = cpow_int(x[i], tr->deg[i]) - 1;
        if (h) h[i] = (1 - t) * tr->gamma * gi + t * fi;
        if (ht) ht[i] = fi - tr->gamma * gi;
        for (slong j = 0; j < k; j++) {
            cplx dfij = poly_eval_c(&tr->sys->dcond[tr->rows[i] * k + j], x);
            cplx dgij = i == j ? tr->deg[i] * cpow_int(x[i], tr->deg[i] - 1) : 0;
            cplx v = (1 - t) * tr->gamma * dgij + t * dfij;
            gsl_matrix_complex_set(tr->jac, (size_t)i, (size_t)j, gsl_complex_rect(creal(v), cimag(v)));
        }
    }
}

/* solves H_x dx = rhs (rhs given in r); 0 when H_x is singular. *pivot: the
 * smallest |U_ii| over the largest */
static int solve(tracker *tr, cplx *dx, const cplx *r, double *pivot)
{
    slong k = tr->k;
    int sign;
    if (gsl_linalg_complex_LU_decomp(tr->jac, tr->perm, &sign) != GSL_SUCCESS) return 0;
    double lo = INFINITY, hi = 0;
    for (slong i = 0; i < k; i++) {
        double u = gsl_complex_abs(gsl_matrix_complex_get(tr->jac, (size_t)i, (size_t)i));
        lo = fmin(lo, u);
        hi = fmax(hi, u);
    }
    if (pivot) *pivot = hi > 0 ? lo / hi : 0;
    if (!(lo > 0)) return 0;
    for (slong i = 0; i < k; i++) gsl_vector_complex_set(tr->rhs, (size_t)i, gsl_complex_rect(creal(r[i]), cimag(r[i])));
    if (gsl_linalg_complex_LU_solve(tr->jac, tr->perm, tr->rhs, tr->dx) != GSL_SUCCESS) return 0;
    for (slong i = 0; i < k; i++) {
        gsl_complex z = gsl_vector_complex_get(tr->dx, (size_t)i);
        dx[i] = GSL_REAL(z) + I * GSL_IMAG(z);
    }
    return 1;
}

/* The homogenised homotopy in z = (z0, x1 .. xk) on the chart: H_i(z, t) =
 * (1 - t) gamma (z_i^d_i - z0^d_i) + t z0^d_i F_i(x / z0), and the chart's
 * equation last; its values into h, its t-derivative into ht, its Jacobian
 * into tr->pjac.  A root at infinity of F is a point with z0 = 0: every
 * path stays finite. */
static void eval_hp(tracker *tr, cplx *h, cplx *ht, const cplx *z, double t)
{
    slong k = tr->k, n = k + 1;
    cplx *grad = malloc((size_t)n * sizeof(cplx));
    for (slong i = 0; i < k; i++) {
        const design_poly *f = &tr->sys->cond[tr->rows[i]];
        int d = tr->deg[i];
        cplx fi = 0;
        for (slong j = 0; j < n; j++) grad[j] = 0;
        for (slong term = 0; term < f->nterms; term++) {
            const slong *e = f->exp + term * k;
            slong e0 = d;
            for (slong j = 0; j < k; j++) e0 -= e[j];
            cplx mono = f->coef_d[term] * cpow_int(z[0], (int)e0);
            for (slong j = 0; j < k; j++) mono *= cpow_int(z[j + 1], (int)e[j]);
            fi += mono;
            /* d/dz_j of the monomial: e_j z_j^(e_j - 1) times the rest */
            for (slong j = 0; j < n; j++) {
                slong ej = j == 0 ? e0 : e[j - 1];
                if (ej == 0) continue;
                cplx part = f->coef_d[term] * ej;
                for (slong l = 0; l < n; l++) {
                    slong el = l == 0 ? e0 : e[l - 1];
                    part *= cpow_int(z[l], (int)(l == j ? el - 1 : el));
                }
                grad[j] += part;
            }
        }
        cplx gi = cpow_int(z[i + 1], d) - cpow_int(z[0], d);
        if (h) h[i] = (1 - t) * tr->gamma * gi + t * fi;
        if (ht) ht[i] = fi - tr->gamma * gi;
        for (slong j = 0; j < n; j++) {
            cplx dg = j == 0 ? -d * cpow_int(z[0], d - 1) : j == i + 1 ? d * cpow_int(z[i + 1], d - 1) : 0;
            cplx v = (1 - t) * tr->gamma * dg + t * grad[j];
            gsl_matrix_complex_set(tr->pjac, (size_t)i, (size_t)j, gsl_complex_rect(creal(v), cimag(v)));
        }
    }
    cplx chart = -1;
    for (slong j = 0; j < n; j++) {
        chart += tr->patch[j] * z[j];
        gsl_matrix_complex_set(tr->pjac, (size_t)k, (size_t)j, gsl_complex_rect(creal(tr->patch[j]),
                                                                                cimag(tr->patch[j])));
    }
    if (h) h[k] = chart;
    if (ht) ht[k] = 0;
    free(grad);
}

static int solve_p(tracker *tr, cplx *dz, const cplx *r)
{
    slong n = tr->k + 1;
    int sign;
    if (gsl_linalg_complex_LU_decomp(tr->pjac, tr->pperm, &sign) != GSL_SUCCESS) return 0;
    for (slong i = 0; i < n; i++)
        if (gsl_complex_abs(gsl_matrix_complex_get(tr->pjac, (size_t)i, (size_t)i)) == 0) return 0;
    for (slong i = 0; i < n; i++) gsl_vector_complex_set(tr->prhs, (size_t)i, gsl_complex_rect(creal(r[i]), cimag(r[i])));
    if (gsl_linalg_complex_LU_solve(tr->pjac, tr->pperm, tr->prhs, tr->pdx) != GSL_SUCCESS) return 0;
    for (slong i = 0; i < n; i++) {
        gsl_complex v = gsl_vector_complex_get(tr->pdx, (size_t)i);
        dz[i] = GSL_REAL(v) + I * GSL_IMAG(v);
    }
    return 1;
}

static double norm_c(const cplx *x, slong k)
{
    double s = 0;
    for (slong j = 0; j < k; j++) s = fmax(s, cabs(x[j]));
    return s;
}

enum { PATH_ROOT, PATH_INFINITE, PATH_SINGULAR, PATH_FAILED };

/* Follows the path from the start root x (t = 0) to t = 1 in projective
 * coordinates; x gets the affine endpoint. */
static int track(tracker *tr, cplx *x)
{
    slong k = tr->k, n = k + 1;
    cplx *z = malloc((size_t)(5 * n) * sizeof(cplx)), *h = z + n, *ht = z + 2 * n, *dz = z + 3 * n, *y = z + 4 * n;
    /* the start point (1, x) scaled onto the chart */
    z[0] = 1;
    for (slong j = 0; j < k; j++) z[j + 1] = x[j];
    cplx c = 0;
    for (slong j = 0; j < n; j++) c += tr->patch[j] * z[j];
    for (slong j = 0; j < n; j++) z[j] /= c;
    double t = 0, dt = fmin(STEP_FIRST, tr->step_max);
    /* the endgame's record: |z0| / |z| at t = 1 - 10^-j */
    double ratio[ENDGAME_POINTS];
    int reached = 0;
    while (t < 1) {
        double mark = reached < ENDGAME_POINTS ? 1 - pow(10, -(double)(reached + 1)) : 1;
        double step = fmin(dt, mark - t);
        /* predictor: dz/dt = -H_z^-1 H_t */
        eval_hp(tr, NULL, ht, z, t);
        int ok = solve_p(tr, dz, ht);
        for (slong j = 0; ok && j < n; j++) y[j] = z[j] - step * dz[j];
        /* corrector: Newton on H(., t + step) */
        double tn = step == mark - t ? mark : t + step;
        int converged = 0;
        for (int it = 0; ok && it < CORRECTOR_ITERATIONS && !converged; it++) {
            eval_hp(tr, h, NULL, y, tn);
            ok = solve_p(tr, dz, h);
            for (slong j = 0; ok && j < n; j++) y[j] -= dz[j];
            converged = ok && norm_c(dz, n) <= CORRECTOR_TOL * (1 + norm_c(y, n));
        }
        if (converged) {
            memcpy(z, y, (size_t)n * sizeof(cplx));
            t = tn;
            dt = fmin(dt * 1.6, tr->step_max);
            if (t == mark && reached < ENDGAME_POINTS) ratio[reached++] = cabs(z[0]) / norm_c(z + 1, k);
        } else {
            dt /= 2;
            if (dt < STEP_MIN) break;
        }
    }
    int outcome = PATH_FAILED;
    double scale = norm_c(z + 1, k);

    /* z0 falling like a power of 1 - t over the last two records: the path
     * runs to infinity, to a singular point there that stops the tracking
     * short of t = 1 (the criterion of a power-series endgame: near t = 1,
     * z0 ~ a (1 - t)^(w/c) with w/c > 0 for a root at infinity) */
    int decays = reached >= 3 && ratio[reached - 1] < ratio[reached - 2] * pow(10, -DECAY_EXPONENT) &&
                 ratio[reached - 2] < ratio[reached - 3] * pow(10, -DECAY_EXPONENT);
    if (cabs(z[0]) <= AT_INFINITY * scale && t >= 1) {
        outcome = PATH_INFINITE;
    } else if (t < 1) {
        outcome = decays ? PATH_INFINITE : PATH_FAILED;
    } else {
        for (slong j = 0; j < k; j++) x[j] = z[j + 1] / z[0];
        /* the endpoint: Newton on F itself, and its conditioning */
        double pivot = 0;
        int ok = 1;
        cplx *hx = malloc((size_t)(2 * k) * sizeof(cplx)), *dx = hx + k;
        for (int it = 0; ok && it < ENDPOINT_ITERATIONS; it++) {
            eval_h(tr, hx, NULL, x, 1);
            ok = solve(tr, dx, hx, &pivot);
            for (slong j = 0; ok && j < k; j++) x[j] -= dx[j];
            if (ok && norm_c(dx, k) <= 1e-15 * (1 + norm_c(x, k))) break;
        }
        eval_h(tr, hx, NULL, x, 1);
        ok = solve(tr, dx, hx, &pivot) && ok;
        outcome = ok && norm_c(hx, k) <= ENDPOINT_TOL * (1 + norm_c(x, k)) && pivot > SINGULAR_PIVOT ? PATH_ROOT
                                                                                                      : PATH_SINGULAR;
        free(hx);
    }
    free(z);
    return outcome;
}

slong design_homotopy_solve(design_homotopy *out, const design_system *sys, const slong *rows, unsigned long seed,
                            slong max_paths)
{
    memset(out, 0, sizeof *out);
    slong k = sys->k;
    double paths = 1;
    int *deg = malloc((size_t)k * sizeof(int));
    for (slong i = 0; i < k; i++) {
        deg[i] = (int)sys->cond[rows[i]].degree;
        paths *= deg[i] > 0 ? deg[i] : 1;
    }
    if (paths > (double)max_paths) {
        free(deg);
        return -1;
    }
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, seed + 15485863);
    double angle = 2 * M_PI * gsl_rng_uniform(rng);
    size_t n = (size_t)k + 1;
    cplx *patch = malloc(n * sizeof(cplx));
    for (size_t j = 0; j < n; j++) {
        double a = 2 * M_PI * gsl_rng_uniform(rng);
        patch[j] = cos(a) + I * sin(a);
    }
    tracker tr = {sys, rows, k, deg, cos(angle) + I * sin(angle), patch,
                  gsl_matrix_complex_alloc((size_t)k, (size_t)k), gsl_matrix_complex_alloc(n, n),
                  gsl_vector_complex_alloc((size_t)k), gsl_vector_complex_alloc((size_t)k),
                  gsl_vector_complex_alloc(n), gsl_vector_complex_alloc(n),
                  gsl_permutation_alloc((size_t)k), gsl_permutation_alloc(n), STEP_MAX};
    out->paths = (slong)paths;
    cplx *roots = malloc((size_t)(out->paths * k) * sizeof(cplx)), *x = malloc((size_t)k * sizeof(cplx));
    out->real_roots = malloc((size_t)(out->paths * k + 1) * sizeof(double));
    slong *digit = calloc((size_t)k, sizeof(slong));
    for (slong p = 0; p < out->paths; p++) {
        if (p % 16 == 0) vigen_progress_set("homotopy path %ld of %ld", (long)p, (long)out->paths);
        /* the start root of index p: x_i = exp(2 pi i digit_i / d_i), the
         * digits counting p in mixed radix */
        for (slong j = 0; j < k; j++) {
            double a = deg[j] > 0 ? 2 * M_PI * (double)digit[j] / deg[j] : 0;
            x[j] = cos(a) + I * sin(a);
        }
        for (slong j = 0; j < k; j++) {
            if (++digit[j] < (deg[j] > 0 ? deg[j] : 1)) break;
            digit[j] = 0;
        }
        cplx *start = roots + out->finite * k;         /* scratch: the next free slot */
        memcpy(start, x, (size_t)k * sizeof(cplx));
        int outcome = track(&tr, x);
        if (outcome == PATH_FAILED) {
            /* once more with steps a tenth as long */
            memcpy(x, start, (size_t)k * sizeof(cplx));
            tr.step_max = STEP_MAX / 10;
            outcome = track(&tr, x);
            tr.step_max = STEP_MAX;
        }
        if (outcome == PATH_INFINITE) {
            out->infinite++;
            continue;
        }
        if (outcome == PATH_SINGULAR) out->singular++;
        if (outcome == PATH_FAILED) out->failed++;
        if (outcome != PATH_ROOT) continue;
        int seen = 0;
        for (slong r = 0; r < out->finite && !seen; r++) {
            double d = 0;
            for (slong j = 0; j < k; j++) d = fmax(d, cabs(x[j] - roots[r * k + j]) / (1 + cabs(x[j])));
            seen = d < SAME_ROOT;
        }
        if (seen) {
            out->repeated++;
            continue;
        }
        memcpy(roots + out->finite * k, x, (size_t)k * sizeof(cplx));
        out->finite++;
        double im = 0;
        for (slong j = 0; j < k; j++) im = fmax(im, fabs(cimag(x[j])) / (1 + cabs(x[j])));
        if (im < REAL_TOL) {
            for (slong j = 0; j < k; j++) out->real_roots[out->real * k + j] = creal(x[j]);
            /* a root that looks real but that real Newton cannot settle
             * (nearly real, or ill-conditioned): the account is not complete */
            if (design_newton_polish(out->real_roots + out->real * k, sys, rows, 20)) out->real++;
            else out->failed++;
        }
    }
    out->complete = out->failed == 0 && out->singular == 0 && out->repeated == 0;
    free(digit);
    free(x);
    free(roots);
    free(deg);
    gsl_matrix_complex_free(tr.jac);
    gsl_matrix_complex_free(tr.pjac);
    gsl_vector_complex_free(tr.rhs);
    gsl_vector_complex_free(tr.dx);
    gsl_vector_complex_free(tr.prhs);
    gsl_vector_complex_free(tr.pdx);
    gsl_permutation_free(tr.perm);
    gsl_permutation_free(tr.pperm);
    free(patch);
    gsl_rng_free(rng);
    gsl_set_error_handler(old);
    return out->paths;
}

void design_homotopy_clear(design_homotopy *h)
{
    free(h->real_roots);
    h->real_roots = NULL;
}
