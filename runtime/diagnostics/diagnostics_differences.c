/* diagnostics_differences.c — the comparison engine of the problem checks:
 * a gradient against central differences of its function and second
 * derivatives against differences of the gradient, each with an error
 * estimate of the differences (truncation from three step sizes, round-off
 * from the size of the values or the noise measured) that sets the
 * tolerance; the step per variable, the noise measured, the nearby points
 * and the sampled components. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "diagnostics_internal.h"

/* A flagged mismatch exceeds this many times the error estimate. */
#define DG_SAFETY 8.0
/* The steps tried, as multiples of eps^(1/3) times the variable's scale,
 * until the differences settle: larger when round-off swamps them (a part
 * at rest whose scale is a guess), smaller when the function is not finite
 * at their points or they do not settle; the one with the smallest error
 * estimate is kept. */
#define DG_ATTEMPTS 4
static const double vigen_dg_step_factor[DG_ATTEMPTS] = { 1, 16, 1.0 / 16, 1.0 / 256 };
/* Differences have settled when their truncation estimate is below this
 * share of the derivative's scale. */
#define DG_SETTLED 0x1p-20

static size_t vigen_dg_m(const vigen_dg_function *f) { return (size_t)f->nparts * f->n; }

void vigen_dg_tally_init(vigen_dg_tally *t)
{
    memset(t, 0, sizeof *t);
    t->flagged.part = t->largest.part = -1;
}

void vigen_dg_tally_add(vigen_dg_tally *t, const vigen_dg_mismatch *m)
{
    t->compared++;
    /* the flagged one reported: at the state if there is one there, else
     * the largest ratio */
    if (m->ratio > 1 && (!t->flagged.found || m->point < t->flagged.point ||
                         (m->point == t->flagged.point && m->ratio > t->flagged.ratio)))
        t->flagged = *m;
    if (m->part >= 0 && (!t->largest.found || m->rel > t->largest.rel)) t->largest = *m;
}

double vigen_dg_pair_value(const void *self, const double *x)
{
    const vigen_dg_pair *f = self;
    return f->value(f->t, x, x + f->n, f->ctx);
}

void vigen_dg_pair_gradient(const void *self, const double *x, double *g)
{
    const vigen_dg_pair *f = self;
    f->grad[0](f->t, x, x + f->n, g, f->ctx);
    f->grad[1](f->t, x, x + f->n, g + f->n, f->ctx);
}

void vigen_dg_rng_init(vigen_dg_rng *r) { r->s = UINT64_C(0x243F6A8885A308D3); }

double vigen_dg_rng_uniform(vigen_dg_rng *r)
{
    uint64_t z = (r->s += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-52 - 1.0;
}

/* The scale of a part that is all zero (p = 0 at rest): the distance at
 * which f, growing quadratically from x along the part's first variable,
 * changes by the size of its terms (|f| + sum |x_j g_j|, estimated here by
 * |f| and a unit step); 1 when f is not given or does not change. */
static double vigen_dg_zero_part_scale(const vigen_dg_function *f, const double *x, int part)
{
    if (f->value == NULL) return 1;
    size_t m = vigen_dg_m(f), k = (size_t)part * f->n;
    double *y = malloc(m * sizeof *y);
    if (y == NULL) return 1;
    memcpy(y, x, m * sizeof *y);
    double f0 = f->value(f->self, x);
    y[k] = 1;
    double d = fabs(f->value(f->self, y) - f0);
    free(y);
    double s = sqrt((fabs(f0) + d) / d);
    return isfinite(s) && s > 0 ? s : 1;
}

void vigen_dg_scales(const vigen_dg_function *f, const double *x, double *s)
{
    for (int part = 0; part < f->nparts; part++) {
        const double *xp = x + (size_t)part * f->n;
        double big = 0;
        for (size_t j = 0; j < f->n; j++) big = fmax(big, fabs(xp[j]));
        if (!(big > 0) || !isfinite(big)) big = vigen_dg_zero_part_scale(f, x, part);
        for (size_t j = 0; j < f->n; j++) s[(size_t)part * f->n + j] = fmax(fabs(xp[j]), big);
    }
}

void vigen_dg_nearby(const vigen_dg_function *f, const double *x, const double *s, vigen_dg_rng *r, double *out)
{
    for (size_t k = 0; k < vigen_dg_m(f); k++) out[k] = x[k] + 0x1p-10 * vigen_dg_rng_uniform(r) * s[k];
}

size_t vigen_dg_sample(size_t n, size_t cap, vigen_dg_rng *r, size_t *idx)
{
    if (n <= cap) {
        for (size_t k = 0; k < n; k++) idx[k] = k;
        return n;
    }
    for (size_t k = 0; k < cap; k++) {
        size_t lo = k * n / cap, hi = (k + 1) * n / cap;
        size_t off = (size_t)((vigen_dg_rng_uniform(r) + 1) / 2 * (double)(hi - lo));
        idx[k] = lo + (off < hi - lo ? off : 0);
    }
    return cap;
}

size_t vigen_dg_first_nonfinite(const double *v, size_t m)
{
    for (size_t k = 0; k < m; k++)
        if (!isfinite(v[k])) return k;
    return m;
}

/* Largest |v| over each part into scale[part]. */
static void vigen_dg_part_scales(const vigen_dg_function *f, const double *v, double scale[2])
{
    scale[0] = scale[1] = 0;
    for (int part = 0; part < f->nparts; part++)
        for (size_t j = 0; j < f->n; j++) scale[part] = fmax(scale[part], fabs(v[(size_t)part * f->n + j]));
}

/* (f(x + h d) - f(x - h d)) / (the distance of the two points) with
 * d = e_k (dir NULL: the actual distance) or dir (2 h); xw holds x and is
 * restored.  *vmax grows to the largest |f| seen; *ok is cleared on a value
 * that is not finite. */
static double vigen_dg_central(const vigen_dg_function *f, double *xw, const double *x, size_t k, const double *dir, double h,
                         double *vmax, int *ok)
{
    double fp, fm, dist = 2 * h;
    if (dir == NULL) {
        double xk = xw[k], xp = xk + h, xm = xk - h;
        xw[k] = xp;
        fp = f->value(f->self, xw);
        xw[k] = xm;
        fm = f->value(f->self, xw);
        xw[k] = xk;
        dist = xp - xm;
    } else {
        size_t m = vigen_dg_m(f);
        for (size_t j = 0; j < m; j++) xw[j] = x[j] + h * dir[j];
        fp = f->value(f->self, xw);
        for (size_t j = 0; j < m; j++) xw[j] = x[j] - h * dir[j];
        fm = f->value(f->self, xw);
        memcpy(xw, x, m * sizeof *xw);
    }
    if (!isfinite(fp) || !isfinite(fm) || !(dist > 0)) *ok = 0;
    *vmax = fmax(*vmax, fmax(fabs(fp), fabs(fm)));
    return (fp - fm) / dist;
}

/* Round-off of one evaluation of a function whose terms are of size `size`,
 * in m variables: a few ulps, and the growth of a sum over the variables. */
static double vigen_dg_roundoff(double size, size_t m) { return DBL_EPSILON * (4 + sqrt((double)m)) * size; }

/* The noise the model above misses (a sum that cancels terms it does not
 * show, as in (T + C) - C), measured after Moré and Wild (Estimating
 * computational noise, SIAM J. Sci. Comput. 33 (2011)): values at 7 points
 * x + t_i delta d along DG_NOISE_DIRECTIONS random directions d (d_j =
 * +-s_j: every variable moves by its full scale, so that a value rounded to
 * a coarse grid still changes; delta = 2^-16, so that the smooth part of a
 * fourth difference, of size delta^4 relative, is far below round-off), and
 * the fourth divided differences of 5 consecutive points divided by the
 * root of the sum of their squared weights (the standard deviation of the
 * difference of unit white noise), 4 times the largest as a bound of the
 * noise of one value (moves up to 2^12 times longer where the values come
 * out equal: a value rounded to a grid coarser than the moves).  The nodes t_i = i - 3 + jitter are not equally
 * spaced: the rounding errors of an arithmetic progression of values form
 * a sawtooth that is linear between its wraps, and a fourth difference of
 * equally spaced points would not see them.  For each of the nv outputs of
 * f (the function, or the m gradient components), into noise; 0 where a
 * value is not finite.  buf holds 7 nv values, xw and d m each. */
#define DG_NOISE_DIRECTIONS 2
static void vigen_dg_noise(const vigen_dg_function *f, int gradient, const double *x, const double *s, vigen_dg_rng *r, double *xw,
                     double *d, double *buf, double *noise)
{
    size_t m = vigen_dg_m(f), nv = gradient ? m : 1;
    for (size_t k = 0; k < nv; k++) noise[k] = 0;
    for (int dir = 0; dir < DG_NOISE_DIRECTIONS; dir++) {
        double tn[7], w[3][5], norm[3];
        for (int i = 0; i < 7; i++) tn[i] = i - 3 + 0.45 * vigen_dg_rng_uniform(r);
        for (int a = 0; a < 3; a++) {   /* weights of the divided difference of nodes a .. a+4 */
            norm[a] = 0;
            for (int i = 0; i < 5; i++) {
                double prod = 1;
                for (int j = 0; j < 5; j++)
                    if (j != i) prod *= tn[a + i] - tn[a + j];
                w[a][i] = 1 / prod;
                norm[a] += w[a][i] * w[a][i];
            }
            norm[a] = sqrt(norm[a]);
        }
        for (size_t j = 0; j < m; j++) d[j] = (vigen_dg_rng_uniform(r) < 0 ? -s[j] : s[j]) * 0x1p-16;
        for (int grow = 0; grow < 4; grow++) {
            int flat = 0;
            for (int i = 0; i < 7; i++) {
                for (size_t j = 0; j < m; j++) xw[j] = x[j] + tn[i] * d[j];
                if (gradient) f->gradient(f->self, xw, buf + (size_t)i * nv);
                else buf[i] = f->value(f->self, xw);
                if (!gradient && i > 0 && buf[i] == buf[i - 1]) flat = 1;
            }
            /* equal values: f is rounded to a grid coarser than the moves
             * (a large hidden term); longer moves, until its steps show */
            if (!flat) break;
            for (size_t j = 0; j < m; j++) d[j] *= 16;
        }
        for (size_t k = 0; k < nv; k++)
            for (int a = 0; a < 3; a++) {
                double dd = 0;
                for (int i = 0; i < 5; i++) dd += w[a][i] * buf[(size_t)(a + i) * nv + k];
                if (isfinite(dd)) noise[k] = fmax(noise[k], 4 * fabs(dd) / norm[a]);
            }
    }
    memcpy(xw, x, m * sizeof *xw);
}

static void vigen_dg_record(vigen_dg_tally *t, double given, double diff, double acc, double scale, int part, size_t index,
                      size_t column, const char *block, int point)
{
    double err = fabs(given - diff), tol = DG_SAFETY * acc, den = fmax(fmax(fabs(given), fabs(diff)), scale);
    vigen_dg_mismatch m = { tol > 0 ? err / tol : (err > 0 ? HUGE_VAL : 0), den > 0 ? err / den : 0, given, diff, acc,
                      part, index, column, block, point, 1 };
    vigen_dg_tally_add(t, &m);
}

/* The derivative of f at x along e_k (dir NULL) or dir from central
 * differences at the steps 2h, h, h/2 (h = h1 times each factor of
 * vigen_dg_step_factor until they settle relative to scale): *D at h/2 and *acc
 * its error estimate (truncation from the three steps, the noise of one
 * value, at least that of values of the size seen).  0 when no step gives
 * finite values. */
static int vigen_dg_derivative(const vigen_dg_function *f, double *xw, const double *x, size_t k, const double *dir, double h1,
                         double noise, double scale, double *D, double *acc)
{
    double best = HUGE_VAL;
    for (int attempt = 0; attempt < DG_ATTEMPTS; attempt++) {
        double h = h1 * vigen_dg_step_factor[attempt], vmax = 0;
        int ok = 1;
        double d2 = vigen_dg_central(f, xw, x, k, dir, 2 * h, &vmax, &ok);
        double d1 = vigen_dg_central(f, xw, x, k, dir, h, &vmax, &ok);
        double d0 = vigen_dg_central(f, xw, x, k, dir, h / 2, &vmax, &ok);
        if (!ok) continue;
        double trunc = fmax(fabs(d2 - d1) / 12, fabs(d1 - d0) / 3);
        double a = trunc + 2 * fmax(noise, vigen_dg_roundoff(vmax, vigen_dg_m(f))) / h + 4 * DBL_EPSILON * fabs(d0);
        if (a < best) {
            best = a;
            *D = d0;
        }
        if (trunc <= DG_SETTLED * fmax(fabs(d0), scale)) break;
    }
    *acc = best;
    return best < HUGE_VAL;
}

/* A sampled gradient compared along random directions d (d_j = u_j s_j):
 * g.d against the derivative of f along d, so that a wrong component
 * outside the sample still shows. */
static void vigen_dg_compare_directions(const vigen_dg_function *f, double *xw, const double *x, const double *g,
                                  const double *s, double noise, double *dir, vigen_dg_rng *r, vigen_dg_tally *t)
{
    size_t m = vigen_dg_m(f);
    for (size_t dd = 0; dd < DG_DIRECTIONS; dd++) {
        vigen_neumaier dot;
        vigen_neumaier_init(&dot);
        double absum = 0, D = 0, acc;
        for (size_t j = 0; j < m; j++) {
            dir[j] = vigen_dg_rng_uniform(r) * s[j];
            vigen_neumaier_add(&dot, g[j] * dir[j]);
            absum += fabs(g[j] * dir[j]);
        }
        if (!vigen_dg_derivative(f, xw, x, 0, dir, cbrt(DBL_EPSILON), noise, absum, &D, &acc)) continue;
        vigen_dg_record(t, vigen_neumaier_result(&dot), D, acc + 4 * DBL_EPSILON * absum, absum, -1, dd, (size_t)-1, NULL,
                  0);
    }
}

int vigen_dg_compare_gradient(const vigen_dg_function *f, const double *x, const double *g, const double *s, int point,
                        vigen_dg_rng *r, vigen_dg_tally *t)
{
    size_t m = vigen_dg_m(f), idx[DG_MAX_COMPONENTS];
    double *xw = malloc(2 * m * sizeof *xw), gscale[2], buf[7], measured;
    if (xw == NULL) return VIGEN_ENOMEM;
    memcpy(xw, x, m * sizeof *xw);
    vigen_dg_part_scales(f, g, gscale);
    /* the size of the terms of f: |f| and sum |x_j g_j| (the terms of a sum
     * of homogeneous functions, which |f| alone misses when they cancel),
     * and the noise of its values: that of terms of this size, or the one
     * measured when larger */
    double size = fabs(f->value(f->self, x)), noise;
    for (size_t j = 0; j < m; j++) size += fabs(x[j] * g[j]);
    vigen_dg_noise(f, 0, x, s, r, xw, xw + m, buf, &measured);
    noise = fmax(vigen_dg_roundoff(size, m), measured);
    int sampled = 0;
    for (int part = 0; part < f->nparts; part++) {
        size_t ns = vigen_dg_sample(f->n, point ? DG_NEARBY_COMPONENTS : DG_MAX_COMPONENTS, r, idx);
        if (point == 0 && ns < f->n) sampled = t->sampled = 1;
        for (size_t c = 0; c < ns; c++) {
            size_t k = (size_t)part * f->n + idx[c];
            double D = 0, acc;
            if (!vigen_dg_derivative(f, xw, x, k, NULL, cbrt(DBL_EPSILON) * s[k], noise, fmax(fabs(g[k]), gscale[part]),
                               &D, &acc))
                continue;   /* no finite differences: nothing to compare */
            /* relative to the part's largest component, or where the part
             * vanishes (p = 0 at rest) to the function's size per scale */
            vigen_dg_record(t, g[k], D, acc, gscale[part] > 0 ? gscale[part] : size / s[k], part, idx[c], (size_t)-1, NULL,
                      point);
        }
    }
    if (sampled) vigen_dg_compare_directions(f, xw, x, g, s, noise, xw + m, r, t);
    free(xw);
    return VIGEN_SUCCESS;
}

/* Whether column c is a column of some block. */
static int vigen_dg_column_used(const vigen_dg_block *b, size_t nb, size_t c)
{
    for (size_t i = 0; i < nb; i++)
        if (c >= b[i].col0 && c < b[i].col0 + b[i].cols) return 1;
    return 0;
}

/* Differences of the gradient along column c at steps 2h, h, h/2 into
 * d (3 m); *gmax (m) grows to the largest |g_r| seen.  0 when a gradient
 * is not finite. */
static int vigen_dg_gradient_differences(const vigen_dg_function *f, double *xw, size_t c, double h, double *d, double *gp,
                                   double *gm, double *gmax)
{
    size_t m = vigen_dg_m(f);
    double xc = xw[c];
    int ok = 1;
    for (int k = 0; k < 3; k++) {
        double step = h * (k == 0 ? 2 : k == 1 ? 1 : 0.5), xp = xc + step, xm = xc - step;
        xw[c] = xp;
        f->gradient(f->self, xw, gp);
        xw[c] = xm;
        f->gradient(f->self, xw, gm);
        xw[c] = xc;
        if (vigen_dg_first_nonfinite(gp, m) < m || vigen_dg_first_nonfinite(gm, m) < m || !(xp > xm)) ok = 0;
        for (size_t r = 0; r < m; r++) {
            d[(size_t)k * m + r] = (gp[r] - gm[r]) / (xp - xm);
            gmax[r] = fmax(gmax[r], fmax(fabs(gp[r]), fabs(gm[r])));
        }
    }
    return ok;
}

int vigen_dg_compare_second(const vigen_dg_function *f, const double *x, const double *s, const vigen_dg_block *blocks,
                      size_t nblocks, int point, vigen_dg_rng *r, vigen_dg_tally *t)
{
    size_t m = vigen_dg_m(f), idx[DG_MAX_COMPONENTS];
    double *mem = malloc(19 * m * sizeof *mem);
    if (mem == NULL) return VIGEN_ENOMEM;
    double *gnoise = mem + 10 * m, *dir = gnoise + m, *buf = dir + m;
    double *xw = mem, *g0 = xw + m, *gp = g0 + m, *gm = gp + m, *gmax = gm + m, *d = gmax + m;
    double *bestD = d + 3 * m, *bestAcc = bestD + m, gscale[2];
    memcpy(xw, x, m * sizeof *xw);
    f->gradient(f->self, x, g0);
    vigen_dg_noise(f, 1, x, s, r, xw, dir, buf, gnoise);   /* measured, where the gradient cancels what it hides */
    vigen_dg_part_scales(f, g0, gscale);
    double bscale[8] = { 0 };   /* largest |entry| of each block (at most 8 blocks) */
    for (size_t b = 0; b < nblocks && b < 8; b++)
        for (size_t i = 0; i < blocks[b].rows; i++)
            for (size_t j = 0; j < blocks[b].cols; j++)
                bscale[b] = fmax(bscale[b], fabs(blocks[b].a[i * blocks[b].stride + j]));
    const double h0 = cbrt(DBL_EPSILON);
    for (int part = 0; part < f->nparts; part++) {
        size_t ns = vigen_dg_sample(f->n, point ? DG_NEARBY_COMPONENTS : DG_MAX_COMPONENTS, r, idx);
        for (size_t ci = 0; ci < ns; ci++) {
            size_t c = (size_t)part * f->n + idx[ci];
            if (!vigen_dg_column_used(blocks, nblocks, c)) continue;
            double bestq = HUGE_VAL;
            for (int attempt = 0; attempt < DG_ATTEMPTS; attempt++) {
                double h = h0 * s[c] * vigen_dg_step_factor[attempt], worstq = 0;
                memcpy(gmax, g0, m * sizeof *gmax);
                for (size_t k = 0; k < m; k++) gmax[k] = fabs(gmax[k]);
                if (!vigen_dg_gradient_differences(f, xw, c, h, d, gp, gm, gmax)) continue;
                for (size_t k = 0; k < m; k++) {
                    double d2 = d[k], d1 = d[m + k], d0 = d[2 * m + k];
                    double trunc = fmax(fabs(d2 - d1) / 12, fabs(d1 - d0) / 3);
                    double size = fmax(gmax[k], gscale[k / f->n]);
                    gp[k] = trunc + 2 * fmax(vigen_dg_roundoff(size, m), gnoise[k]) / h + 4 * DBL_EPSILON * fabs(d0);
                    double den = fmax(fabs(d0), size / s[c]);
                    if (den > 0) worstq = fmax(worstq, trunc / den);
                }
                if (worstq < bestq) {
                    bestq = worstq;
                    memcpy(bestD, d + 2 * m, m * sizeof *bestD);
                    memcpy(bestAcc, gp, m * sizeof *bestAcc);
                }
                if (worstq <= DG_SETTLED) break;
            }
            if (bestq == HUGE_VAL) continue;
            for (size_t b = 0; b < nblocks; b++) {
                const vigen_dg_block *B = &blocks[b];
                if (c < B->col0 || c >= B->col0 + B->cols) continue;
                for (size_t i = 0; i < B->rows; i++) {
                    size_t row = B->row0 + i;
                    vigen_dg_record(t, B->a[i * B->stride + (c - B->col0)], bestD[row], bestAcc[row],
                              b < 8 ? bscale[b] : 0, (int)(row / f->n), row % f->n, c, B->name, point);
                }
            }
        }
    }
    free(mem);
    return VIGEN_SUCCESS;
}

int vigen_dg_check_points(const vigen_dg_function *f, const double *x, double *s, vigen_dg_tally *grad, vigen_dg_point_fn extra,
                    void *ctx, int *points)
{
    size_t m = vigen_dg_m(f);
    vigen_dg_rng rng, *r = &rng;
    vigen_dg_rng_init(r);
    vigen_dg_tally_init(grad);
    vigen_dg_scales(f, x, s);
    double *y = malloc(3 * m * sizeof *y);
    if (y == NULL) return VIGEN_ENOMEM;
    double *gx = y + m, *gy = gx + m;
    f->gradient(f->self, x, gx);
    int rc = VIGEN_SUCCESS;
    for (int point = 0; point < DG_POINTS && rc == VIGEN_SUCCESS; point++) {
        const double *at = x, *gat = gx;
        if (point > 0) {   /* a nearby point, skipped where the problem is not finite */
            vigen_dg_nearby(f, x, s, r, y);
            f->gradient(f->self, y, gy);
            if (vigen_dg_first_nonfinite(gy, m) < m || (f->value && !isfinite(f->value(f->self, y)))) continue;
            at = y;
            gat = gy;
        }
        ++*points;
        if (f->value) rc = vigen_dg_compare_gradient(f, at, gat, s, point, r, grad);
        if (rc == VIGEN_SUCCESS && extra) rc = extra(ctx, at, point, r);
    }
    free(y);
    return rc;
}
