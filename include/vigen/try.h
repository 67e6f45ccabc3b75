/* try.h — `vigen try` and `vigen order`: run methods on the standard problems
 * of the problem collection (runtime/include/vigen/problems.h) and measure
 * them.
 *
 * For each method (a tableau file, a spec file, generated on the fly with
 * the digits `vigen emit` uses for double, or the name of a published
 * tableau: the stem of a file in tableaux/published/) the library emits the
 * stepper (vigen/emit.h), renders a driver program from
 * templates/try/driver.c.in, compiles both with the system C compiler ($CC,
 * else cc) against the runtime and the problem library (those of the build
 * tree when vigen runs from it, those installed beside vigen otherwise) in a
 * private temporary directory ($TMPDIR, else /tmp), runs the driver and reads
 * what it measured.  The directory is removed afterwards, also on failure and
 * when SIGINT, SIGTERM, SIGHUP or the time cap (SIGALRM) ends the process.
 *
 * Measures of one run (step h, N steps, final time N h):
 *   - energy error: (H(t) - H(0)) / |H(0)| (absolute when H(0) = 0) at up to
 *     VIGEN_TRY_SAMPLES + 1 equally spaced times; its maximum modulus, and the
 *     drift: the least-squares slope of the error against time (compensated
 *     sums), per unit time;
 *   - each invariant of the problem: the largest |I(t) - I(0)| at the samples;
 *   - global error: the Euclidean norm of (q, p) - (q, p)_ref at the final
 *     time, when the problem has a reference solution;
 *   - gradient evaluations per step (calls of dH/dq plus calls of dH/dp) and
 *     nanoseconds per step (wall clock of the steps alone).
 * Each method runs on the fastest path the problem allows: a mechanical
 * problem (H = 1/2 p^T M^-1 p + V(t, q), M diagonal: separable with dH/dp
 * linear and diagonal in p, which the driver checks) through the stepper's
 * NAME_alloc_mechanical (Nystrom form; its forces counted as gradient
 * evaluations), any other through NAME_alloc; the result says which
 * (vigen_try_result.path).
 * A step that fails (stage iteration not converging, a non-finite state) ends
 * that method's run: its result says at which step and time, and why.
 */
#ifndef VIGEN_TRY_H
#define VIGEN_TRY_H

#include <stddef.h>
#include <stdio.h>
#include "vigen/error.h"

/* Energy samples per run (the plots' resolution). */
#define VIGEN_TRY_SAMPLES 1000
/* Steps per period when neither h nor steps_per_period is given. */
#define VIGEN_TRY_DEFAULT_STEPS_PER_PERIOD 100

typedef struct {
    const char *problem;    /* a name of the collection ("kepler") */
    const char *params;     /* "k=v,k=v" or NULL: the problem's defaults */
    double h;               /* step; 0: period / steps_per_period */
    long steps_per_period;  /* 0: VIGEN_TRY_DEFAULT_STEPS_PER_PERIOD */
    double time;            /* final time; 0: the problem's default time */
    const char *cc;         /* C compiler; NULL: $CC, else "cc" */
    int progress;           /* 1: a progress line on stderr while it runs */
    int allow_inexact;      /* round a method file's decimals as written when they have too few
                               digits for double (`--allow-inexact`, as for vigen emit); the
                               methods of the library (by name) are always taken with their
                               published digits, with the emitter's warning */
} vigen_try_options;

/* Fills opt from the texts of the command line's options (NULL: absent):
 * params holds one "k=v" a line (repeated --param), joined into
 * opt->params with commas (a heap string: free((char *)opt->params)).
 * VIGEN_E_USAGE naming the option: h and time positive numbers,
 * steps_per_period a whole number from 1, not both h and steps_per_period. */
int vigen_try_options_set(vigen_try_options *opt, const char *problem, const char *params, const char *h,
                          const char *steps_per_period, const char *time, vigen_error *err);

/* What one method did on one problem. */
typedef struct {
    char *label;             /* the method as given (file stem or name) */
    int failed;              /* 1: a step failed; message says where and why */
    char *message;           /* NULL unless failed */
    double h;                /* step used */
    unsigned long planned;   /* steps asked for */
    unsigned long steps;     /* steps done (fewer when a step failed) */
    double t_end;            /* time reached */
    double energy_max;       /* max |relative energy error| */
    double energy_drift;     /* least-squares slope of the relative energy error, per unit time */
    size_t ninv;
    char **inv_names;        /* ninv names ("angular-momentum") */
    double *inv_max;         /* ninv largest deviations */
    int has_reference;
    double global_error;     /* NaN without a reference */
    double grad_per_step;    /* (dH/dq + dH/dp calls) / steps */
    double ns_per_step;
    size_t dim;
    double *final_state;     /* q then p, 2 dim values */
    size_t nsamples;         /* samples, the first at t = 0 */
    double *ts, *energy;     /* time and signed relative energy error */
    size_t norbit;           /* orbit points: t0 and the first (up to 2000) steps */
    double *x, *y;           /* orbit: (q1, q2), or (q1, p1) when dim = 1 */
    char *path;              /* how the stepper ran the problem: "mechanical" (Nystrom form,
                                grad_per_step counts forces), "general" (dH/dq and dH/dp),
                                "split" (the problem's exact flows, grad_per_step counts
                                flow calls), "lagrangian"; NULL when the driver did not say */
} vigen_try_result;

/* Runs every method on the problem.  On VIGEN_OK *results holds n results
 * (each may report a failed step).  Errors, with one message naming the
 * method: VIGEN_E_USAGE (unknown problem or parameter, unknown method name,
 * bad h, steps or time), the loader's and emitter's codes for a method file,
 * and VIGEN_E_TEMPLATE (exit status 3, a broken installation) when the C
 * compiler is missing or rejects the code, or a driver cannot run. */
int vigen_try_run(size_t n, const char *const *methods, const vigen_try_options *opt, vigen_try_result **results,
                  vigen_error *err);
void vigen_try_results_free(vigen_try_result *results, size_t n);

/* The summary: a table, one row per method (text), or one JSON object. */
void vigen_try_print_summary(FILE *out, const vigen_try_options *opt, const vigen_try_result *r, size_t n);
void vigen_try_print_json(FILE *out, const vigen_try_options *opt, const vigen_try_result *r, size_t n);

/* The problems of the collection with their parameters, one block each;
 * the published methods known by name, one a line. */
void vigen_try_print_problems(FILE *out);
void vigen_try_print_methods(FILE *out);

/* Plots of a run into dir (created if missing, one level): energy.csv,
 * energy.svg, energy.png (|energy error| against time, log scale, one curve
 * per method that has a positive error) and orbit.csv, orbit.svg, orbit.png
 * (the orbit or phase portrait, one curve per method), with gnuplot
 * ($GNUPLOT, else gnuplot).  Each file is written atomically.  *written
 * (may be NULL) receives the number of files.  VIGEN_E_WRITE for a
 * directory or file that cannot be written, VIGEN_E_TEMPLATE when gnuplot is
 * missing or fails. */
int vigen_try_plot(const char *dir, const vigen_try_options *opt, const vigen_try_result *r, size_t n,
                   vigen_error *err);

/* Work-precision: each method at steps_per_period 2^k * base for k < levels
 * (base: opt->steps_per_period, default 64; levels 6 when 0) up to
 * opt->time (default 10 periods), error (global error against the
 * reference, or the maximum energy error when the problem has none) against
 * cost (gradient evaluations and seconds). */
typedef struct {
    char *label;
    size_t npoints;
    double *h, *evals, *seconds, *error;
    int error_is_energy;     /* 1: the problem has no reference solution */
    char *message;           /* a failed run at some h (later points left out), or NULL */
} vigen_try_wp_curve;

/* The curves of the n methods, each run at `levels` steps h halved from
 * the plan's (*curves: n curves, freed by vigen_try_wp_free); a method that
 * fails at some h keeps its points before and says why in its message. */
int vigen_try_work_precision(size_t n, const char *const *methods, const vigen_try_options *opt, int levels,
                             vigen_try_wp_curve **curves, vigen_error *err);
/* Frees the n curves (and the array). */
void vigen_try_wp_free(vigen_try_wp_curve *c, size_t n);
/* The curves as a text table, one block per method. */
void vigen_try_wp_print(FILE *out, const vigen_try_wp_curve *c, size_t n);
/* {"problem", "params", "error_is_energy", "methods": [{"name", "points":
 * [{"h", "evals", "seconds", "error"}], "failed"}]} */
void vigen_try_wp_print_json(FILE *out, const vigen_try_options *opt, const vigen_try_wp_curve *c, size_t n);
/* work_precision_evals.{csv,svg,png} and work_precision_seconds.{csv,svg,png}
 * (the same data beside each figure): one curve per method, log-log. */
int vigen_try_wp_plot(const char *dir, const vigen_try_options *opt, const vigen_try_wp_curve *c, size_t n,
                      vigen_error *err);

/* Empirical order under step halving: errors at h_k = h_0 / 2^k, k < levels
 * (h_0: opt->h, else period / opt->steps_per_period, default 64 steps per
 * period), against the reference solution when the problem has one,
 * otherwise against the same method at a step 4 times finer than the finest; the
 * order between successive levels is log2(e_k / e_(k+1)).  certified is the
 * order `vigen check` certifies for the tableau (vigen/check.h; 0 when it
 * certifies none), certified_separable the order for separable H.  For a
 * built-in Lagrangian integrator (builtin = 1; no tableau) both are the
 * order the literature proves for it. */
typedef struct {
    char *label;
    int certified, certified_separable;
    int builtin;
    size_t levels;
    double *h, *error, *order; /* order[k] between k and k+1; order[levels-1] = NaN */
    int against_reference;
    double estimate;           /* the order of the finest pair whose errors lie above round-off */
} vigen_try_order_result;

/* The order of the method measured at `levels` levels into *res (cleared by
 * vigen_try_order_clear). */
int vigen_try_order(const char *method, const vigen_try_options *opt, int levels, vigen_try_order_result *res,
                    vigen_error *err);
/* Frees what vigen_try_order filled in. */
void vigen_try_order_clear(vigen_try_order_result *res);
/* The result as a text table or (json = 1) as JSON. */
void vigen_try_order_print(FILE *out, const vigen_try_options *opt, const vigen_try_order_result *res, int json);
/* order.csv, order.svg, order.png: error against h, log-log, with the line
 * of slope `certified` through the finest point. */
int vigen_try_order_plot(const char *dir, const vigen_try_options *opt, const vigen_try_order_result *res,
                         vigen_error *err);

#endif
