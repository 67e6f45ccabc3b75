/* design_internal.h — what the files of the designer share: the order
 * conditions of a family as polynomials in its unknowns (exact rational
 * coefficients), evaluated in double for the search and in arb for the proof.
 * Not installed: nothing outside src/design uses it. */
#ifndef VIGEN_DESIGN_INTERNAL_H
#define VIGEN_DESIGN_INTERNAL_H

#include <arb.h>
#include <arb_mat.h>
#include <flint/fmpq.h>
#include "vigen/design.h"

/* A polynomial in k unknowns: nterms terms coef[t] x^exp[t*k .. t*k+k-1]. */
typedef struct {
    slong k, nterms;
    fmpq *coef;
    double *coef_d;              /* coef rounded to double (the search) */
    slong *exp;
    slong degree;                /* total degree */
} design_poly;

void design_poly_clear(design_poly *p);
double design_poly_eval_d(const design_poly *p, const double *x);
void design_poly_eval_arb(arb_t out, const design_poly *p, arb_srcptr x, slong prec);

/* The order conditions of a family: cond[i] = 0 for i < n, in k unknowns,
 * with their partial derivatives dcond[i*k + j] = d cond[i] / d x_j; what each
 * condition says (the Lyndon word it is the coefficient of, "Y1 Y3"), and
 * the degree of its word (the power of h). */
typedef struct {
    slong k, n;
    design_poly *cond, *dcond;
    char **what;
    int *h_degree;
    slong nmultipliers;          /* the last unknowns are Lagrange multipliers (design_criterion.c) */
} design_system;

void design_system_clear(design_system *sys);

/* The conditions for order p of the composition of a symmetric base method
 * of order q (even) with stages steps gamma_i h, gamma the unknowns
 * (symmetric: gamma_i = gamma_{stages+1-i}, ceil(stages/2) unknowns).
 * design_conditions.c describes the derivation. */
int design_composition_conditions(design_system *sys, int stages, int symmetric, int q, int p, vigen_error *err);

/* The longest word the conditions are built or counted from: the order up
 * to which design_composition_count is exact. */
#define DESIGN_WORD_MAX 24

/* How many conditions order p asks of that family (the Lyndon words of the
 * alphabet, counted without building the polynomials: cheap for any p). */
slong design_composition_count(int symmetric, int q, int p);

/* The conditions for order p (separable H = T(p) + V(q)) of the splitting
 * drift a_1, kick b_1, drift a_2, ..., kick b_s, drift a_(s+1) (s kicks):
 * the Lyndon words in A (drifts) and B (kicks) of the logarithm of the
 * product of exp(a_i h A) and exp(b_i h B), against h (A + B); symmetric:
 * the substeps read the same backwards.  Unknowns: the distinct drifts, then
 * the distinct kicks; substep i (0-based, drift on even i) is unknown
 * design_substep_unknown(i).  mods (design_quotient.c): the conditions
 * modulo the Nystrom ideal or the processed image (0: plain). */
int design_splitting_conditions(design_system *sys, int kicks, int symmetric, int p, unsigned mods, vigen_error *err);
slong design_splitting_count(int symmetric, int p);
/* The same for two named flows A and B (B carrying eps) and the generalized
 * order r[0..nr-1]: the Lyndon words with j letters B and length <= r_j
 * (r_nr beyond the list), and the two words of one letter (each flow's
 * steps add up to 1). */
int design_flows_conditions(design_system *sys, int kicks, int symmetric, const int *r, int nr, vigen_error *err);
slong design_splitting_unknowns(int kicks, int symmetric);
slong design_substep_unknown(slong i, int kicks, int symmetric);

/* Conditions modulo a subspace (design_quotient.c): a condition is the
 * combination sum_t coef[t] c_(word[t]) of the coefficients of Lyndon words
 * of the logarithm, all of one degree; word[0] (coefficient 1) names it.
 * Words in A (0) and B (1) as integers, letter j from the left bit
 * degree-1-j. */
typedef struct {
    int degree;
    slong nterms, alloc;
    ulong *word;
    fmpq *coef;
} design_combo;

typedef struct {
    slong n;
    design_combo *c;
} design_combos;

/* What the logarithm of a splitting may keep: DESIGN_MOD_NYSTROM, the ideal
 * of the relations of T = p^2/2 and V(q) (brackets of functions of q vanish,
 * [B,[B,[B,A]]] the first); DESIGN_MOD_PROCESSED, the image of ad_(A+B),
 * which a processor removes (effective order 4). */
enum { DESIGN_MOD_NYSTROM = 1, DESIGN_MOD_PROCESSED = 2 };

/* The highest degree of the conditions modulo a subspace (the orders design solves). */
#define DESIGN_QUOTIENT_MAX_DEGREE 10

/* The conditions of degrees 1..p (odd degrees only when symmetric) modulo
 * mods; VIGEN_E_USAGE beyond DESIGN_QUOTIENT_MAX_DEGREE.  design_quotient_count: how
 * many (-1 beyond it). */
int design_quotient_conditions(design_combos *out, int p, int symmetric, unsigned mods);
slong design_quotient_count(int p, int symmetric, unsigned mods);
void design_combos_clear(design_combos *c);

/* The processor of a kernel of effective order 4: its h^3 term is
 * mu [A+B,[A,B]], and mu = scale times the coefficient of the Lyndon word
 * `word` (degree 3) in the kernel's logarithm. */
void design_quotient_processor(ulong *word, fmpq_t scale);

/* The corrector written for a processed method: drift y1, kick y2, drift
 * y3, kick y4, drift y5, kick y6 (five conditions: y6 is held at a chosen
 * binary fraction, design_processed.c). */
#define DESIGN_CORRECTOR_UNKNOWNS 6
#define DESIGN_CORRECTOR_CONDITIONS 5
/* Its first-order part, t (A + B): t = 1/2 (any t serves; 0 would make
 * partial sums of the step vanish). */
#define DESIGN_CORRECTOR_T_NUM 1
#define DESIGN_CORRECTOR_T_DEN 2

/* A symmetric kernel of effective order 4 with its corrector
 * (design_conditions.c): in the kernel's unknowns x (the splitting's, first)
 * and the corrector's y (DESIGN_CORRECTOR_UNKNOWNS, after), the kernel's
 * conditions (as design_splitting_conditions with mods |
 * DESIGN_MOD_PROCESSED, order 4, the same rows in the same order) and then
 * the corrector's: log C = t h (A+B) + mu(x) h^2 [A,B] + (t/2) h^3 X3(x) +
 * O(h^4), so that C K C^-1 has order 4 (docs/design.md). */
int design_processed_conditions(design_system *sys, int kicks, unsigned mods, vigen_error *err);

/* The family of d (design_family.c): 1 for the kick/drift families
 * ("splitting", "rkn", "processed"); the mods of its conditions; its unknowns; the
 * steps of the method written (stages of a composition, substeps of a
 * splitting) and the unknown each one is; its conditions for order
 * d->order (q: the base's order, compositions), counted or built. */
int design_family_is_splitting(const vigen_design_spec *d);
unsigned design_family_mods(const vigen_design_spec *d);
slong design_family_unknowns(const vigen_design_spec *d);
slong design_family_nvalues(const vigen_design_spec *d);
slong design_family_value_unknown(const vigen_design_spec *d, slong i);
slong design_family_count(const vigen_design_spec *d, int q);
int design_family_conditions(design_system *sys, const vigen_design_spec *d, int q, vigen_error *err);

/* The unknown each stage's step is: gamma_i = x[design_stage_unknown(i)]. */
slong design_stage_unknown(slong i, int stages, int symmetric);

/* F(x) (n values) and its Jacobian (n x k, row-major) in double, for the
 * conditions rows[0..m-1] (rows NULL: all). */
void design_eval_d(double *f, double *jac, const design_system *sys, const slong *rows, slong m, const double *x);

/* Many-start Newton (design_newton.c): the distinct real solutions of the
 * square subsystem rows[0..k-1], x[sol*k + j], at most max_sol; returns the
 * count. */
slong design_newton_search(double **sols, const design_system *sys, const slong *rows, slong starts,
                           unsigned long seed, double box);

/* The same with the first nanchor unknowns of every start at anchor[j]
 * (the others random): the roots near a known part (a kernel's corrector). */
slong design_newton_search_anchored(double **sols, const design_system *sys, const slong *rows, slong starts,
                                    unsigned long seed, double box, const double *anchor, slong nanchor);

/* The corrector of the proved kernel root x (kernel square rows rows[0 ..
 * kx-1] of the kernel's system ksys, its pins among them) in the system of
 * design_processed_conditions (design_processed.c): on success (1) digits
 * gets kx + DESIGN_CORRECTOR_UNKNOWNS certified decimals (the kernel's and
 * the corrector's, one proof), *radius the box's; 0 with *why. */
int design_corrector_find(char ***digits, char **radius, char **why, const vigen_design_spec *d,
                          const design_system *ksys, const slong *rows, const double *x, long ndigits,
                          vigen_error *err);

/* Every complex root of the square subsystem rows[0..k-1] by a
 * total-degree homotopy in double (design_homotopy.c): paths, the Bezout
 * number tracked; finite, the distinct nonsingular roots reached, real of
 * them real (real_roots, k values each, polished); infinite, singular,
 * failed, repeated: paths that diverged, ended at a singular point, were
 * lost (or ended at a root that looks real but that real Newton cannot
 * settle), or ended at a root another path reached.  complete: none lost,
 * singular or repeated, so the finite endpoints are every root. */
typedef struct {
    slong paths, finite, real;
    slong infinite, singular, failed, repeated;
    int complete;
    double *real_roots;
} design_homotopy;

/* -1 (nothing done) when the Bezout number exceeds max_paths; else the
 * paths tracked, with out filled (design_homotopy_clear frees it). */
slong design_homotopy_solve(design_homotopy *out, const design_system *sys, const slong *rows, unsigned long seed,
                            slong max_paths);
void design_homotopy_clear(design_homotopy *h);

/* Newton on x (k unknowns) for the subsystem rows (k of them) in double;
 * returns 1 when it converged to a root. */
int design_newton_polish(double *x, const design_system *sys, const slong *rows, int iterations);

/* The square subsystem: k conditions of sys independent at a generic point
 * (the first in order that raise the rank of the Jacobian), into rows;
 * returns how many were found (< k: the conditions leave free parameters). */
slong design_square_rows(slong *rows, const design_system *sys, unsigned long seed);

/* Pins (design_pin.c): design_system_add_pin appends the condition
 * x_j - t = 0 (t = 0) and returns its row; design_system_set_pin sets t,
 * exactly the double given. */
slong design_system_add_pin(design_system *sys, slong j);
void design_system_set_pin(design_system *sys, slong row, double t);
/* The pin of row `row` of src (x_j - t, t exact) appended to dst, whose
 * first unknowns are src's; its row in dst. */
slong design_system_copy_pin(design_system *dst, const design_system *src, slong row);

/* The unknowns d fixes (`fix`), each the condition x_j - v = 0 with v its
 * exact rational, put before every other condition (so that the square
 * subsystem takes them); VIGEN_E_SPEC when a value does not read. */
int design_system_fix(design_system *sys, const vigen_design_spec *d);

/* The free unknowns of the conditions rows[0..m-1] (m < k): the unknowns
 * left when m columns independent at a generic point are taken as the
 * dependent ones; free_out gets k - m of them (design_minimize.c). */
void design_free_unknowns(slong *free_out, const design_system *sys, const slong *rows, slong m, unsigned long seed);

/* The Krawczyk proof (design_krawczyk.c): from the approximate root x0 of
 * the square subsystem rows, Newton in arb at prec, then the Krawczyk test
 * on a box around it.  On success (returns 1) box[j] encloses the unique
 * exact root in it; 0: not proved. */
int design_krawczyk_prove(arb_ptr box, const design_system *sys, const slong *rows, const double *x0, slong prec);

/* The Krawczyk test alone on the box mid +- rad (every unknown): 1 when
 * K(box) lies inside it, enclosure in out. */
int design_krawczyk_test(arb_ptr out, const design_system *sys, const slong *rows, arb_srcptr mid, const mag_t rad,
                         slong prec);

/* Optimality criteria as equations (design_criterion.c): out gets the
 * Lagrange system of the objective of d (stationary or nearest) on the
 * conditions rows[0..m-1] of sys (m < k), in the k unknowns and m
 * multipliers, square; design_criterion_search finds its real roots (many
 * starts, or for nearest Newton from the given point); design_criterion_replace
 * puts that system in place of sys, every row of it in rows (*m of them). */
int design_criterion_system(design_system *out, const design_system *sys, const slong *rows, slong m,
                            const vigen_design_spec *d, int q, vigen_error *err);
int design_criterion_replace(design_system *sys, slong **rows, slong *m, const vigen_design_spec *d, int q,
                             vigen_error *err);
/* 1 when a row of rows[0..m-1] is the pin x_j = 0: the root has x_j = 0
 * exactly (a splitting whose first substep is a kick). */
int design_pinned_zero(const design_system *sys, const slong *rows, slong m, slong j);
char *design_criterion_how(const vigen_design_spec *d, slong nconditions);
slong design_criterion_search(double **roots, const design_system *aug, const slong *rows, const vigen_design_spec *d,
                              slong k, double box);

#endif
