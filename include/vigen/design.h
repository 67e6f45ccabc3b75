/* design.h — `vigen design`: methods found from their order conditions, each
 * solution proved to exist, written as method files the checker certifies.
 *
 * A design file is a Lua chunk (run in the sandbox, like spec files)
 * returning a family and what is wanted:
 *   { name = "y6", design = "composition", base = "stormer_verlet_position",
 *     stages = 7, order = 6, symmetric = true, solutions = "all" }
 * The composition S(gamma_s h) ... S(gamma_1 h) of a symmetric base method S
 * has the order conditions of docs/design.md (polynomials in the gammas with
 * rational coefficients, from the Baker-Campbell-Hausdorff series); kick/drift
 * splittings have theirs for separable H ("splitting"), for Nystrom H ("rkn":
 * modulo the relations of T = p^2/2), and as kernels of effective order 4
 * with a corrector ("processed"); a "splitting" of two named flows for
 * H = A + eps B asks a generalized order (flows, perturbation,
 * generalized_order); `fix` holds unknowns at rationals.  A
 * square subsystem of independent conditions is solved by many-start Newton
 * in double; each root is refined in arb and proved with the Krawczyk
 * operator (an exact root exists, unique, in a small box); the conditions
 * outside the subsystem are decided on the box, and the method file written
 * for each solution is checked by the checker, whose certified order and
 * symplecticity become its claims.
 */
#ifndef VIGEN_DESIGN_H
#define VIGEN_DESIGN_H

#include <flint/flint.h>
#include "vigen/error.h"

/* The highest order a design may ask for (the conditions are polynomials of
 * that degree in the steps). */
#define VIGEN_DESIGN_MAX_ORDER 10
/* The most entries of a generalized order asked for (a splitting file's claim). */
#define VIGEN_DESIGN_MAX_GENERALIZED 16

/* Newton starts of a search for every root, when the file gives none. */
#define VIGEN_DESIGN_DEFAULT_STARTS 2000L

/* The most paths a total-degree homotopy follows unless the file says
 * (`homotopy = N`; a few ms a path). */
#define VIGEN_DESIGN_HOMOTOPY_PATHS 4096L

/* What is wanted of the family. */
enum { VIGEN_DESIGN_ALL = 0, VIGEN_DESIGN_MINIMIZE = 1 };

typedef struct {
    char *path;                  /* the design file */
    char *name;                  /* the stem of the method files written */
    char *family;                /* "composition", "splitting", "rkn" or "processed" */
    char *base;                  /* the base method, a library name or a file, as written */
    int stages, order, symmetric;
    int nystrom;                 /* the conditions for Nystrom H (T = p^2/2): "rkn", or processed with kernel "rkn" */
    int processed;               /* "processed": a kernel of effective order `order` and its corrector */
    int goal;                    /* VIGEN_DESIGN_ALL or VIGEN_DESIGN_MINIMIZE */
    char *minimize;              /* goal MINIMIZE: "error_constant" (general H), "error_constant_separable",
                                    "error_constant_nystrom": the checker's constant minimised; "effective_error",
                                    "effective_error_separable", "effective_error_nystrom": that constant times
                                    the forces per step to the power `order` */
    int minimize_family;         /* the constant's family, VIGEN_CHECK_EC_* (general when not minimising) */
    int minimize_effective;      /* 1: the effective error, constant x forces^order */
    char *stationary;            /* "error_norm": every stationary point of the principal error's
                                    Lyndon norm on the family (design_criterion.c); else NULL */
    char **nearest;              /* the member of the family nearest these decimals (one per unknown) */
    slong nnearest;              /* their count (0: not asked) */
    int first_kick;              /* splittings: first = "kick", the first drift is 0 */
    char *flow_a, *flow_b;       /* splittings of named flows: `flows`, B (flow_b) the `perturbation` carrying
                                    eps, A the other; NULL for kicks (B) and drifts (A) */
    int flows_first_b;           /* the file lists the perturbation first in `flows` */
    int ngeneralized;            /* `generalized_order = {r1, ..., rk}` (k entries; 0: absent): the conditions
                                    are the Lyndon words with j letters B of length <= r_j (r_k beyond k) */
    int generalized[VIGEN_DESIGN_MAX_GENERALIZED];
    long nfix;                   /* `fix = { b1 = "-3/73", ... }`: unknowns held at exact rationals */
    char **fix_name;             /* each one's name: a1, b2 (splittings: drifts, kicks), gamma3 (compositions) */
    char **fix_value;            /* its value, a rational "p/q" */
    long *fix_unknown;           /* its index among the unknowns of the family */
    long nequal;                 /* `equal = { {"gamma1", "gamma2"}, ... }`: pairs of unknowns tied */
    long *equal_unknown;         /* 2 nequal indices among the unknowns, a pair after a pair */
    long starts;                 /* Newton starts (default 2000); minimize: descents (default 8) */
    long starts_asked;           /* starts as the file gives it (0: not given) */
    unsigned long seed;          /* of the starts (default 1) */
    long homotopy;               /* the most paths of the homotopy that accounts for every root (default
                                    VIGEN_DESIGN_HOMOTOPY_PATHS; 0: none) */
    long screen;                 /* minimize: random points where the error constant is evaluated
                                    first, the descents starting from the best (default 0: from
                                    random starts) */
} vigen_design_spec;

/* Reads and validates the design file at path (d uninitialised on entry;
 * initialised on success).  Every failure is one message naming the file
 * and the field ("y6.lua: stages: must be a whole number from 1 to 64") with
 * VIGEN_E_SPEC (exit status 2). */
int vigen_design_read(vigen_design_spec *d, const char *path, vigen_error *err);
/* Frees the strings of d; d is then empty. */
void vigen_design_spec_clear(vigen_design_spec *d);

/* One solution of the family. */
typedef struct {
    int proved;                  /* the Krawczyk test proved an exact root in the box */
    int excluded;                /* a condition outside the square subsystem certainly fails on the box */
    int certified;               /* the method file was checked: order and symplecticity certified */
    slong nunknowns;
    double *x;                   /* the root in double */
    char **digits;               /* each unknown with the certified digits (NULL when not proved) */
    char *radius;                /* the largest radius of the proving box, as a decimal */
    int order;                   /* certified order for general H (-1 unknown) */
    int order_separable;         /* ... for separable H */
    int order_nystrom;           /* ... for Nystrom H */
    char *error_constant;        /* the checker's principal error constant, general H (text) */
    char *error_constant_sep;    /* ... separable H */
    char *error_constant_nystrom;/* ... Nystrom H */
    double error_constant_d;     /* the three as doubles (-1: not available) */
    double error_constant_sep_d, error_constant_nystrom_d;
    long force;                  /* force evaluations per step (separable H; a processed method: its
                                    kernel's, as C and C^-1 run once, at the start and at an output) */
    int ngeneralized;            /* named flows: the checker's generalized order r[1..n], all decided (0: not) */
    int generalized[VIGEN_DESIGN_MAX_GENERALIZED];
    char *file;                  /* the path the method file goes to */
    char *text;                  /* its contents */
    char *why;                   /* not proved / excluded / not certified: why (one line) */
} vigen_design_solution;

typedef struct {
    slong nunknowns, nconditions;   /* of the family */
    slong nsquare;               /* the conditions of the square subsystem solved (<= nunknowns) */
    char **conditions;           /* each condition: the word of the Lie series it is the coefficient of */
    int *condition_degree;       /* its power of h */
    slong bezout;                /* the product of the degrees of the square subsystem (-1: too large) */
    slong starts;                /* Newton starts made */
    slong nfound;                /* distinct real roots of the square subsystem found */
    int complete;                /* every real root is among those found: nfound == bezout (every root
                                    real), or the homotopy's account below */
    slong homotopy_paths;        /* a total-degree homotopy: its paths (the Bezout number; 0: not run) */
    slong homotopy_finite;       /* ... the distinct nonsingular roots they reached */
    slong homotopy_real;         /* ... of them real */
    slong homotopy_infinite;     /* ... the paths that diverged (roots at infinity) */
    slong homotopy_lost;         /* ... the paths lost, ended at a singular point, or at a root reached twice */
    slong homotopy_new;          /* ... real roots the Newton search had missed (now among those found) */
    int homotopy_complete;       /* no path lost: the finite endpoints are every root (floating-point
                                    tracking, not certified) */
    int base_order;              /* the base method's certified order */
    int minimized;               /* minimize: sol[0] is the best point found */
    slong nfree;                 /* minimize: the unknowns the conditions leave free */
    long evaluations;            /* minimize: the checker's runs on trial points */
    slong nsol;
    vigen_design_solution *sol;  /* in the order found, sorted by the first unknown */
} vigen_design_result;

typedef struct {
    const char *outdir;          /* where the method files go ("." by default) */
    long digits;                 /* certified digits of every step (default 40) */
} vigen_design_options;

/* Sets the defaults: outdir ".", digits 40. */
void vigen_design_options_init(vigen_design_options *opt);

/* Solves the design d: res (uninitialised on entry, initialised whatever the
 * return) gets every root found, proved or not, with the texts of the method
 * files of the certified ones.  Writes nothing.  Errors: VIGEN_E_SPEC for a
 * design that cannot be posed (an unknown base, a base that is not a
 * symmetric splitting, more conditions than unknowns beyond
 * VIGEN_DESIGN_MAX_ORDER); a family without a solution is not an error (no
 * certified solution in res). */
int vigen_design_run(vigen_design_result *res, const vigen_design_spec *d, const vigen_design_options *opt,
                     vigen_error *err);

/* Writes the method files of the certified solutions of res, all or none
 * (vigen_write_files_atomic).  VIGEN_E_WRITE naming the file. */
int vigen_design_write(const vigen_design_result *res, vigen_error *err);

/* The figure `minimize` ranks solutions by: the error constant of
 * d->minimize_family, times force^order for an effective error; -1 when
 * the checker gave no such constant. */
double vigen_design_solution_criterion(const vigen_design_solution *sol, const vigen_design_spec *d);

/* Frees what vigen_design_run put in res (every solution, texts and
 * conditions); res is then empty. */
void vigen_design_result_clear(vigen_design_result *res);

#endif
