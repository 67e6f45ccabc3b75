/* tableau.h — a partitioned Runge–Kutta tableau (c, A, b; ct, At, bt) and its
 * file format, shared by the generator, the checker and the emitter.
 *
 * A tableau file is a Lua chunk returning
 *   { name = "gauss2", s = 2,
 *     c = {...}, A = {{...}, ...}, b = {...},           -- q part (required)
 *     At = {{...}, ...}, ct = {...}, bt = {...},         -- p part (optional; bt defaults to b,
 *                                                       --   ct to the row sums of At)
 *     digits = 34, source = "...", description = "...",  -- metadata (optional)
 *     basis = '...', nodes = '...', generator = "vigen 0.1.0",
 *     order = 4, symplectic = true }                     -- claims (optional; checked by vigen check)
 * Entries are strings.  A plain decimal with a point or an exponent
 * ("0.2113248654051871177454256097490213", "-1.5e-3", "0e-40") stands for the
 * ball of radius half a unit in its last digit: it was rounded.  Anything else
 * ("0", "1/2", "1/6 - sqrt(2)/48", "(pi-2)/(2*pi)") is an exact expression.
 * Lua integers are accepted as exact; Lua floats are refused.
 */
#ifndef VIGEN_TABLEAU_H
#define VIGEN_TABLEAU_H

#include <arb.h>
#include <arb_mat.h>
#include "vigen/error.h"
#include "vigen/limits.h"

/* the longest generalized_order claim read */
#define VIGEN_MAX_GENERALIZED 16

/* The named flows of a splitting file (`flows = {...}`,
 * src/method/splitting_file.h) whose method became this tableau.  Two flows:
 * the first is the letter A of the substeps (substep_drift[k] = 1), the
 * second B; bracket flows besides them: below. */
typedef struct {
    slong nflows;
    char **names;          /* [nflows] */
    int perturbation;      /* the flow that carries epsilon in H = A + eps B */
    slong ncorrector;      /* a processed method: the first ncorrector substeps are the corrector C and
                            * the last ncorrector its inverse (kernel between); 0 otherwise */
    int ngeneralized;      /* the claim generalized_order = {r1, ..., rk}; 0 when absent */
    int generalized[VIGEN_MAX_GENERALIZED];
    /* Bracket flows (`brackets` of the file): NULL and 0 when it has none.
     * Then the tableau (and its substeps) is the method of the plain flows'
     * substeps alone, and one step of the method is step_flow/step_coef. */
    int *degree;           /* [nflows] 1 for a plain flow, k for a bracket of k letters */
    int **bracket;         /* [nflows] NULL for a plain flow, else its degree[j] letters (0 or 1, the plain
                            * flows), the left-nested Poisson bracket {{L1, L2}, L3}... */
    slong nstep;           /* substeps of one step (C, the kernel, C^-1), bracket flows included */
    int *step_flow;        /* [nstep] flow indices */
    char **step_coef;      /* [nstep] coefficient texts: flow j advances by coef h^degree[j] */
} vigen_flows;

typedef struct {
    char *name;
    slong s;
    int has_At, has_ct, has_bt;

    /* Entry texts, row-major for matrices (A_text[i*s+j]); NULL when absent. */
    char **c_text, **b_text, **A_text, **ct_text, **bt_text, **At_text;

    /* Balls, valid after vigen_tableau_evaluate or the generator. */
    slong prec;                  /* precision of the balls; 0 = not evaluated */
    arb_ptr c, b, ct, bt;        /* bt mirrors b when has_bt == 0 */
    arb_mat_t A, At;             /* At zero when has_At == 0 */

    /* Metadata. */
    slong digits;                /* certified digits of a generated file; 0 = exact/hand-written */
    char *description, *source, *basis, *nodes, *generator;
    int claim_order;             /* -1 when absent */
    int claim_symplectic;        /* -1 absent, 0 false, 1 true */
    int claim_order_sep;         /* order_separable = p: the order for H = T(p) + V(q); -1 absent */
    int claim_order_nys;         /* order_nystrom = p: the order for H = p^T M^-1 p / 2 + V(q); -1 absent */
    int generated_now;           /* 1: made by the generator in this run (from a spec), not read */

    /* A splitting or composition file: its substeps in order of application
     * (substep_drift[k]: 1 drift q <- q + coef h dT/dp, 0 kick p <- p - coef
     * h dV/dq; coefficient texts as entries), when the method is known as
     * one; nsubsteps = 0 otherwise. */
    slong nsubsteps;
    int *substep_drift;
    char **substep_coef;
    vigen_flows *flows;          /* named flows of the splitting file; NULL for every other method */
} vigen_tableau;

/* Allocates an s-stage tableau with all balls zero and no texts. */
void vigen_tableau_init(vigen_tableau *t, slong s);
void vigen_tableau_clear(vigen_tableau *t);
/* dst (uninitialised on entry) becomes a deep copy of src: texts, balls and
 * metadata. */
void vigen_tableau_copy(vigen_tableau *dst, const vigen_tableau *src);
/* Replaces t's substeps by copies of drift[0..n-1] and coef[0..n-1] (n = 0:
 * none). */
void vigen_tableau_set_substeps(vigen_tableau *t, slong n, const int *drift, char *const *coef);

/* Replaces t's named flows by a copy of fl (NULL: none). */
void vigen_tableau_set_flows(vigen_tableau *t, const vigen_flows *fl);

/* Reads a tableau file (run once in a fresh sandbox).  Messages name the file
 * and the entry ("gauss2.lua: A[2][1]: ..."): missing fields, wrong sizes, Lua
 * floats, unparsable expressions.  Does not evaluate; call
 * vigen_tableau_evaluate.  A command that accepts a spec as well loads the
 * file with vigen_method_load (vigen/method.h). */
int vigen_tableau_load(vigen_tableau *t, const char *path, const vigen_sandbox_limits *limits,
                       vigen_error *err);

/* (Re)computes the balls from the entry texts at precision prec. */
int vigen_tableau_evaluate(vigen_tableau *t, slong prec, vigen_error *err);

/* Evaluates one entry text.  Every decimal in an entry was rounded, bare
 * ("0.2113248654") or inside an expression ("0.5*sqrt(3)"): it stands for the
 * ball of half a unit in its last digit ("0.5" is 0.5 +/- 0.05).  Integers,
 * fractions and the rest of an expression are exact. */
int vigen_tableau_entry_eval(arb_t res, const char *text, slong prec, vigen_error *err);

/* 1 when the entry text holds a decimal, bare or inside an expression (its
 * value is then a ball, not exact); 0 for an exact expression (or a text
 * that does not parse). */
int vigen_tableau_entry_is_rounded(const char *text);

/* Fills every *_text from the balls with `digits` certified significant digits
 * (entries that are exactly zero become "0"; balls containing zero become
 * "0eK" with the certified absolute bound).  Returns VIGEN_E_PRECISION when some
 * entry cannot be certified at the balls' precision. */
int vigen_tableau_texts_from_balls(vigen_tableau *t, slong digits, vigen_error *err);

/* Serialises as a tableau file (Lua) into a string; deterministic. */
char *vigen_tableau_to_lua(const vigen_tableau *t);

/* max over i, j of |b_i at_ij + b_j a_ji - b_i b_j| as a ball (contains 0 for a
 * symplectic method).  Requires At. */
void vigen_tableau_symplectic_residual(arb_t res, const vigen_tableau *t, slong prec);

#endif
