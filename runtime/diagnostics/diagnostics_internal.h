/* diagnostics_internal.h — what the problem checks (diagnostics.c for
 * Hamiltonians, diagnostics_mechanical.c, diagnostics_lagrangian.c) share
 * with the comparison engine (diagnostics_differences.c) and the report
 * (diagnostics_report.c): a scalar function of m = nparts * n variables
 * with its gradient, described for messages; the comparison of a gradient
 * with central differences of the function and of second derivatives with
 * differences of the gradient; the nearby points; the report's text. */
#ifndef VIGEN_DIAGNOSTICS_INTERNAL_H
#define VIGEN_DIAGNOSTICS_INTERNAL_H

#include <stdint.h>
#include <vigen/diagnostics.h>

/* Components of a part compared one by one at the state; longer parts are
 * sampled (and the whole gradient is compared along DG_DIRECTIONS random
 * directions).  At the nearby points, DG_NEARBY_COMPONENTS. */
#define DG_MAX_COMPONENTS 64
#define DG_NEARBY_COMPONENTS 16
#define DG_DIRECTIONS 2
/* Second derivatives are compared up to this many variables (the matrix of
 * second derivatives has m^2 entries). */
#define DG_MAX_SECOND 2048
/* Points checked: the state and DG_POINTS - 1 nearby ones. */
#define DG_POINTS 3

typedef struct {
    size_t n;              /* length of a part */
    int nparts;            /* 1 (mechanical) or 2 */
    /* the function at x (m values); NULL: none given */
    double (*value)(const void *self, const double *x);
    /* the gradient at x into g (m values, all parts) */
    void (*gradient)(const void *self, const double *x, double *g);
    const void *self;
    const char *value_name;     /* "H" */
    const char *part_name[2];   /* "dH/dq", "dH/dp" (as the user sees the part) */
    const char *var_name[2];    /* "q", "p" */
    double part_sign[2];        /* the part as the user sees it = sign * gradient (the force: -1) */
} vigen_dg_function;

/* A function of two parts (q, p) or (q, v) with its two gradients, as H and
 * L come: vigen_dg_pair_value and vigen_dg_pair_gradient serve as vigen_dg_function's value
 * and gradient with self = a vigen_dg_pair. */
typedef struct {
    size_t n;
    double t;
    double (*value)(double t, const double *a, const double *b, void *ctx);
    void (*grad[2])(double t, const double *a, const double *b, double *out, void *ctx);
    void *ctx;
} vigen_dg_pair;
double vigen_dg_pair_value(const void *self, const double *x);
void vigen_dg_pair_gradient(const void *self, const double *x, double *g);

/* One comparison: a given derivative against its differences. */
typedef struct {
    double ratio;          /* |given - differences| / tolerance; above 1: flagged */
    double rel;            /* relative mismatch (see vigen_problem_report) */
    double given, differences, accuracy;   /* accuracy: the error estimate of the differences */
    int part;              /* of the gradient component (the row); -1: along a direction */
    size_t index, column;  /* column: (size_t)-1 for a gradient */
    const char *block;     /* second derivatives: the matrix's name */
    int point;             /* 0: the state, else a nearby point */
    int found;
} vigen_dg_mismatch;

/* The worst comparisons of a check. */
typedef struct {
    vigen_dg_mismatch flagged;   /* ratio above 1, at the first point with one, largest ratio
                              there (found = 0: none) */
    vigen_dg_mismatch largest;   /* largest relative mismatch of a component */
    size_t compared;
    int sampled;           /* a part was sampled at the state (longer than DG_MAX_COMPONENTS) */
} vigen_dg_tally;

void vigen_dg_tally_init(vigen_dg_tally *t);
/* Counts m and keeps it if it is the worst so far (ratio, relative). */
void vigen_dg_tally_add(vigen_dg_tally *t, const vigen_dg_mismatch *m);

/* The deterministic pseudo-random sequence of the checks (splitmix64). */
typedef struct { uint64_t s; } vigen_dg_rng;
void vigen_dg_rng_init(vigen_dg_rng *r);
double vigen_dg_rng_uniform(vigen_dg_rng *r);   /* in [-1, 1) */

/* Scale of each variable: max(|x_k|, largest |x_j| of its part); for an
 * all-zero part, the distance at which f changes by about its own size
 * (1 when that cannot be told).  s has m entries. */
void vigen_dg_scales(const vigen_dg_function *f, const double *x, double *s);
/* A point near x: each variable moved by up to 2^-10 of its scale. */
void vigen_dg_nearby(const vigen_dg_function *f, const double *x, const double *s, vigen_dg_rng *r, double *out);
/* The components of a part to compare: all when n <= cap (at most
 * DG_MAX_COMPONENTS), else cap spread over it (one in each stratum);
 * returns how many were written to idx. */
size_t vigen_dg_sample(size_t n, size_t cap, vigen_dg_rng *r, size_t *idx);

/* Index of the first entry of v[0 .. m-1] that is NaN or infinite, or m. */
size_t vigen_dg_first_nonfinite(const double *v, size_t m);

/* Compares the gradient g (at x, finite) with central differences of
 * f->value at x, for the sampled components of each part, with steps for
 * the scales s (vigen_dg_scales of the state: a nearby point keeps the state's
 * scales); point numbers the point for messages.  VIGEN_ENOMEM or
 * VIGEN_SUCCESS (mismatches go to t). */
int vigen_dg_compare_gradient(const vigen_dg_function *f, const double *x, const double *g, const double *s, int point,
                        vigen_dg_rng *r, vigen_dg_tally *t);

/* A block of given second derivatives: entry (i, j) of the rows x cols matrix
 * a (row stride) is d g_{row0 + i} / d x_{col0 + j}. */
typedef struct {
    const char *name;      /* "the Hessian", "d2Ldq2" */
    size_t row0, col0, rows, cols, stride;
    const double *a;
} vigen_dg_block;

/* Compares the blocks (at x) with central differences of f->gradient, at
 * the sampled columns (steps for the scales s, as above). */
int vigen_dg_compare_second(const vigen_dg_function *f, const double *x, const double *s, const vigen_dg_block *blocks,
                      size_t nblocks, int point, vigen_dg_rng *r, vigen_dg_tally *t);

/* The checks of each point: the state x and DG_POINTS - 1 nearby points
 * (those where the function or gradient is not finite are skipped): the
 * gradient against differences of f->value (when given) into grad, then
 * extra (may be NULL) for the checks of the caller, which returns a status
 * (with the report set by the caller for an error of its own).  s (m)
 * receives the scales of x (vigen_dg_scales) before the first point; grad is
 * initialised here; *points counts the points checked.  The gradient at x
 * must be finite.  Every call draws the same pseudo-random sequence. */
typedef int (*vigen_dg_point_fn)(void *ctx, const double *y, int point, vigen_dg_rng *r);
int vigen_dg_check_points(const vigen_dg_function *f, const double *x, double *s, vigen_dg_tally *grad, vigen_dg_point_fn extra,
                    void *ctx, int *points);

/* Report helpers.  vigen_dg_report_start clears rep; vigen_dg_report_set sets status
 * and the one-sentence message (printf format); vigen_dg_report_mismatch describes
 * t->flagged (second: a derivative of the gradient) with status. */
void vigen_dg_report_start(vigen_problem_report *rep);
int vigen_dg_report_set(vigen_problem_report *rep, int status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
int vigen_dg_report_mismatch(vigen_problem_report *rep, const vigen_dg_function *f, const vigen_dg_mismatch *m, int status);
/* Records the largest relative mismatch of t into rep (success path). */
void vigen_dg_report_largest(vigen_problem_report *rep, const vigen_dg_tally *t);
/* The gradient at the state x into g (m), and VIGEN_ENONFINITE with the
 * report naming the value or the component when one is not finite. */
int vigen_dg_state_values(const vigen_dg_function *f, const double *x, double *g, vigen_problem_report *rep);
/* VIGEN_EINVAL when t, or an entry of a or b (n each; b may be NULL), is
 * not finite, naming it (na[k], nb[k]). */
int vigen_dg_state_check(vigen_problem_report *rep, double t, const char *na, const double *a, const char *nb,
                   const double *b, size_t n);
/* "at the state" or "near the state". */
const char *vigen_dg_where(int point);

#endif
