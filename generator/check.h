/* check.h — `vigen check`: certify what a PRK tableau is (MATH.md section 1).
 *
 * Everything is decided in ball arithmetic, with three outcomes per condition:
 *   holds      the ball of (left side - right side) contains 0 and its radius
 *              is at most 2^-tol_bits (default 2^-30);
 *   fails      the ball excludes 0 (certain);
 *   undecided  anything else (a wide ball containing 0, or a non-finite ball).
 * When something is undecided and the entries are exact expressions, the
 * tableau is re-evaluated at twice the precision (up to max_prec) and every
 * check is redone; decimal entries stand for half-ulp balls, so a condition
 * that needs more digits than the file gives stays undecided and is reported
 * as such.
 *
 * Checks: row sums (c_i = sum_j a_ij, ct_i = sum_j at_ij when ct is given,
 * sum b = 1, sum bt = 1), symplecticity (bt = b, b_i at_ij + b_j a_ji - b_i b_j
 * = 0; for separable H the pair conditions b_i at_ij + bt_j a_ji - b_i bt_j = 0
 * suffice, so splitting methods written with bt != b are reported as
 * "symplectic for separable H" and a claim symplectic = true holds for
 * them, as a claimed order holds when it is the order for separable H), order conditions of every bicoloured tree up to max_order (general H,
 * separable H, each part alone as an RK method), simplifying assumptions B, C,
 * D and stage order of each part, claims of the file, and --against.  A
 * tableau without At is one RK method used for both parts (At = A, bt = b,
 * ct = c).  Failed row-sum and symplecticity conditions that all involve one
 * entry are traced back to it: the entry is named (1-based) with the value
 * that satisfies them.
 */
#ifndef VIGEN_CHECK_H
#define VIGEN_CHECK_H

#include <stdio.h>
#include <arb.h>
#include "error.h"
#include "tableau.h"
#include "trees.h"

/* Hook for files that are not tableau files: loads path into t (uninitialised
 * on entry, initialised on success), generating the tableau when path is a
 * spec file.  vigen_source_load (source.h) has exactly this signature; with
 * NULL the checker reads tableau files only (vigen_tableau_load). */
typedef int (*vigen_check_loader_fn)(vigen_tableau *t, const char *path, slong digits, vigen_error *err);

typedef struct {
    const char *path;            /* FILE */
    const char *against;         /* FILE2 or NULL */
    int max_order;               /* P: orders 1..P are checked; default 8, at most VIGEN_TREE_MAX_ORDER */
    int json;                    /* print one JSON object instead of the text report */
    slong prec;                  /* starting precision in bits; 0 = adequate to the entries (>= 128) */
    slong max_prec;              /* cap for the refinement; default 4096 */
    int tol_bits;                /* holding means radius <= 2^-tol_bits; default 30 */
    slong spec_digits;           /* digits asked of the loader for spec files; default 34 */
    vigen_check_loader_fn load;  /* spec hook, see above; NULL = tableau files only */
} vigen_check_options;

void vigen_check_options_init(vigen_check_options *opt);

/* Tri-state outcome. */
enum { VIGEN_CHECK_NO = 0, VIGEN_CHECK_YES = 1, VIGEN_CHECK_UNDECIDED = 2 };

/* A level such as an order or B(p): the largest p such that everything up to
 * p holds.  capped: everything up to the cap held (the true level may be
 * higher).  undecided: level + 1 is undecided rather than failing. */
typedef struct {
    int value;
    int capped;
    int undecided;
} vigen_check_level;

/* Order conditions of one family of trees. */
enum {
    VIGEN_CHECK_GENERAL = 0,     /* every bicoloured tree: any H */
    VIGEN_CHECK_SEPARABLE = 1,   /* alternating trees: H = T(p) + V(q) */
    VIGEN_CHECK_A_ALONE = 2,     /* black trees: (c, A, b) as an RK method */
    VIGEN_CHECK_AT_ALONE = 3,    /* white trees: (ct, At, bt) as an RK method */
    VIGEN_CHECK_FAMILIES = 4
};

typedef struct {
    vigen_check_level level;
    int evaluated_to;            /* highest order whose conditions were all evaluated */
    slong count[VIGEN_TREE_MAX_ORDER + 1], hold[VIGEN_TREE_MAX_ORDER + 1],
          fail[VIGEN_TREE_MAX_ORDER + 1], undecided[VIGEN_TREE_MAX_ORDER + 1];
    /* The first tree (lowest order, enumeration order) that fails, and the
     * first that is undecided; order 0 when there is none. */
    int fail_order, undecided_order;
    char *fail_tree, *undecided_tree;
    arb_t fail_value, fail_expected;            /* sum bhat_i Phi_i(t) and 1/gamma(t) */
    arb_t undecided_value, undecided_expected;
} vigen_check_orders;

enum { VIGEN_PROBLEM_ROWSUM, VIGEN_PROBLEM_SYMPLECTIC, VIGEN_PROBLEM_CLAIM, VIGEN_PROBLEM_AGAINST };

typedef struct {
    int kind;                    /* VIGEN_PROBLEM_* */
    const char *claim;           /* claims: "order" or "symplectic"; NULL otherwise */
    const char *matrix;          /* "A", "At", "b", "bt", "c", "ct"; NULL when not applicable */
    slong row, col;              /* 1-based; 0 when not applicable */
    int undecided;               /* the condition is undecided, not failing */
    int diagnosed;               /* names the single entry that explains the failures */
    int has_value, has_expected;
    arb_t value, expected;       /* balls (row sums, symplecticity, against, diagnoses) */
    char *value_json, *expected_json;  /* for claims: JSON literals ("4", "true") */
    char *message;               /* one line */
} vigen_check_problem;

typedef struct {
    char *path, *name;
    slong s, prec;               /* precision of the final round, bits */
    slong rounds;                /* evaluations done (1 + refinements) */
    slong undecided_left;        /* undecided balls in the final round */
    const char *undecided_reason;/* why refining stopped with undecided balls (static string) */
    int max_order;
    int has_At, has_bt, has_ct;
    int tol_bits;

    int consistent;              /* row sums and sum b = 1 (tri-state) */
    int symplectic;              /* tri-state: bt = b and b_i at_ij + b_j a_ji = b_i b_j */
    int symplectic_separable;    /* tri-state: b_i at_ij + bt_j a_ji = b_i bt_j, which suffices
                                    for separable H (GNI Thm VI.4.6); bt may differ from b */
    slong sym_fail, sym_undecided, sym_total;   /* conditions of symplecticity */
    slong row_fail, row_undecided, row_total;   /* row-sum conditions */

    vigen_check_orders orders[VIGEN_CHECK_FAMILIES];

    /* Simplifying assumptions, [0] = (c, A, b), [1] = (ct, At, bt). */
    vigen_check_level B[2], C[2], D[2], stage_order[2];
    int simplifying_cap;

    int claim_order;             /* -1 when the file states none */
    int claim_order_status;      /* tri-state */
    int claim_order_separable;   /* the claim matches the separable order only */
    int claim_symplectic;        /* -1, 0, 1 */
    int claim_symplectic_status;
    int claim_symplectic_separable;  /* the claim holds for separable H only */

    int against_checked;
    slong against_differences;

    slong nproblems, alloc_problems;
    vigen_check_problem *problems;

    int exit_code;               /* 0 consistent and every claim holds, 1 otherwise */
} vigen_check_report;

void vigen_check_report_init(vigen_check_report *rep);
void vigen_check_report_clear(vigen_check_report *rep);

/* Checks t, loaded (texts) or evaluated (balls).  When t has entry texts it is
 * (re-)evaluated here at opt->prec (or an adequate precision) and refined as
 * described above; a tableau with balls only is checked at t->prec as it is.
 * against: NULL, or a second tableau compared entry by entry.  path is used
 * in messages only (may be NULL).  Returns VIGEN_OK (the outcome is in rep,
 * including rep->exit_code), or an error when t cannot be evaluated. */
int vigen_check_tableau(vigen_check_report *rep, vigen_tableau *t, vigen_tableau *against,
                        const vigen_check_options *opt, vigen_error *err);

void vigen_check_print_text(FILE *out, const vigen_check_report *rep);
void vigen_check_print_json(FILE *out, const vigen_check_report *rep);

/* Loads opt->path (and opt->against), checks, prints the report to out and
 * returns the exit status: 0 consistent and every stated claim holds, 1
 * something fails or cannot be decided, 2 unreadable input or usage error
 * (err then holds the message; nothing is printed to out). */
int vigen_check_run(const vigen_check_options *opt, FILE *out, vigen_error *err);

/* The command line `vigen check FILE [--against FILE2] [--max-order P] [--json]
 * [--prec BITS]`: argv[0 .. argc-1] are the arguments after "check" (as
 * cmd_generate gets them: main calls vigen_check_main(argc - 2, argv + 2,
 * vigen_source_load)).  The report goes to stdout, messages to stderr;
 * returns the exit status.  load: the spec hook (vigen_source_load). */
int vigen_check_main(int argc, char **argv, vigen_check_loader_fn load);

extern const char *vigen_check_usage;

#endif
