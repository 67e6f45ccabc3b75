/* check.h — `vigen check`: certify what a PRK tableau is.
 *
 * Everything is decided in ball arithmetic.  Each condition is a ball r = left
 * side - right side, with three outcomes (a condition holds only when its ball
 * contains 0 and fails only when the ball excludes 0):
 *   fails      the ball excludes 0 (certain);
 *   holds      the ball contains 0, and
 *                - when some entry the condition involves is a rounded decimal
 *                  (a half-ulp ball) or a ball given by a caller: its radius
 *                  is at most 2^-VIGEN_CHECK_DATA_BITS = 2^-10 times the size
 *                  of the terms it compares; the condition then holds "within
 *                  the precision of the data" (its exact value may differ
 *                  from 0 by less than that radius) and the report shows the
 *                  largest radius of such balls.  A wider ball containing 0 is
 *                  undecided: the data are too short to decide (a 1-digit
 *                  "0.5" is 0.5 +/- 0.05, 10% of itself, wide enough to
 *                  "satisfy" conditions that fail by a few per cent).  Row
 *                  sums and symplecticity pairs are intersected with an
 *                  enclosure to second order around the midpoints, in which
 *                  an entry that occurs twice varies once;
 *                - when every entry it involves is an exact expression: the
 *                  radius is at most 2^-(prec/2) times the size of the terms
 *                  (the ball is as tight as the working precision makes it, not
 *                  wide from cancellation), and the same verdicts came out at
 *                  two successive precisions p and 2p (or the ball is exactly
 *                  0);
 *                - or, proved, when every entry of the tableau is rational
 *                  with common denominator D: |v| D^k g < 1 (k entries per
 *                  term, g the denominator of the constant); or every entry
 *                  is a + b sqrt(d) for one squarefree d > 1, a and b rational
 *                  with common denominator D: |v| |v'| (D^k g)^2 < 1, v' the
 *                  same condition on the conjugate tableau (sqrt(d) ->
 *                  -sqrt(d)), since v v' (D^k g)^2 = m^2 - d n^2 is an integer
 *                  and m = n = 0 is the only way to make it 0;
 *   undecided  anything else (an exact condition whose ball is still wide or
 *              unconfirmed at the precision cap, a condition on rounded data
 *              whose ball contains 0 but is wider than 2^-10 of its terms, or
 *              a non-finite ball).
 * An order, a simplifying assumption, consistency, symplecticity or a claim
 * that rests on at least one hold within the precision of the data is
 * reported as such ("order 4 within the precision of the data"; JSON status
 * "within_data"), never as certain.  Such a claim still counts as holding for
 * the exit status (0): the threshold makes its radius meaningful, at most
 * 2^-10 of the terms compared.
 *
 * Notes: a rounded decimal with at most 3 significant digits in a file whose
 * longest decimals have at least 10 is named, with its radius and the exact
 * fraction to write if it is exact ("0.5" -> "1/2").
 * The starting precision is adequate to the entries: enough bits for the
 * digits of every rounded decimal and of every exact literal (a number's
 * digits, and |k| log10 B for a power B^k), plus 64, at least 128.  When an
 * exact condition is undecided or unconfirmed the tableau is re-evaluated at
 * twice the precision, up to max(max_prec, twice the start).  An exact
 * difference smaller than about 2^-(final precision) of the terms is below
 * what any finite precision can see; the literal digits keep the visible ones
 * (such as 1/10^45) inside the starting precision.
 *
 * Checks: row sums (c_i = sum_j a_ij, ct_i = sum_j at_ij when ct is given,
 * sum b = 1, sum bt = 1), symplecticity (bt = b, b_i at_ij + b_j a_ji - b_i b_j
 * = 0; for separable H the pair conditions b_i at_ij + bt_j a_ji - b_i bt_j = 0
 * suffice, so splitting methods written with bt != b are reported as
 * "symplectic for separable H" and a claim symplectic = true holds for them),
 * order conditions of every bicoloured tree up to max_order (general H,
 * separable H, each part alone as an RK method), simplifying assumptions B, C,
 * D and stage order of each part, claims of the file, and --against.  A
 * tableau without At is one RK method used for both parts (At = A, bt = b,
 * ct = c).  Every failed or undecided row sum and symplecticity pair is a
 * problem of the report.  Failed row-sum and symplecticity conditions that all
 * involve one entry are traced back to it: the entry is named (1-based) with
 * the value that satisfies them, solved for with the entry as an exact unknown.
 *
 * A claim order = p means the order is p: it holds when every condition up to
 * order p holds and some condition of order p + 1 fails (for general H, or for
 * separable H), so orders up to p + 1 are evaluated (p + 1 <= 12).  What the
 * enumerated trees leave open is decided, where they can, by the simplifying
 * assumptions (Butcher's theorem for both parts, see vigen_check_theorem) and
 * by the bushy trees (B(q) on the row sums); otherwise the claim is undecided
 * and its message names the conditions that would decide it.
 *
 * Figures (docs/analysis.md): the principal error constants of general,
 * separable and Nystrom H, the linear stability interval on the harmonic
 * oscillator (certified root isolation), the cost of a step.
 */
#ifndef VIGEN_CHECK_H
#define VIGEN_CHECK_H

/* A condition on rounded data holds when its ball contains 0 with a radius at
 * most 2^-VIGEN_CHECK_DATA_BITS of the size of its terms. */
#define VIGEN_CHECK_DATA_BITS 10

#include <stdio.h>
#include <arb.h>
#include "vigen/error.h"
#include "vigen/tableau.h"
#include "vigen/trees.h"

/* Hook for files that are not tableau files: loads path into t (uninitialised
 * on entry, initialised on success), generating the tableau when path is a
 * spec file.  vigen_source_load (vigen/method.h) has exactly this signature; with
 * NULL the checker reads tableau files only (vigen_tableau_load). */
typedef int (*vigen_check_loader_fn)(vigen_tableau *t, const char *path, slong digits, vigen_error *err);

typedef struct {
    const char *path;            /* FILE */
    const char *against;         /* FILE2 or NULL */
    int max_order;               /* P: orders 1..P are checked; default 8, at most VIGEN_TREE_MAX_ORDER */
    slong prec;                  /* starting precision in bits; 0 = adequate to the entries (>= 128) */
    slong max_prec;              /* cap for the refinement; default 4096 (raised to twice the
                                    starting precision when the entries need more) */
    slong spec_digits;           /* digits asked of the loader for spec files; default 34 */
    vigen_check_loader_fn load;  /* spec hook, see above; NULL = tableau files only */
    int generalized;             /* 1: the generalized orders of named flows (default); 0 skips
                                    them, for a caller after the classical figures only */
} vigen_check_options;

/* Sets every option to its default: max_order 8, prec 0 (adequate to the
 * entries), max_prec 4096, spec_digits 34, no FILE2, no loader, the
 * generalized orders computed. */
void vigen_check_options_init(vigen_check_options *opt);

/* Tri-state outcome. */
enum { VIGEN_CHECK_NO = 0, VIGEN_CHECK_YES = 1, VIGEN_CHECK_UNDECIDED = 2 };

/* A level such as an order or B(p): the largest p such that everything up to
 * p holds.  capped: everything up to the cap held (the true level may be
 * higher).  undecided: level + 1 is undecided rather than failing.
 * within_data: some condition up to the level holds only within the
 * precision of the data (the level is not certain).  too_short: level + 1 is
 * undecided because the rounded data are too short (every undecided condition
 * there has a ball containing 0 wider than 2^-10 of its terms). */
typedef struct {
    int value;
    int capped;
    int undecided;
    int within_data;
    int too_short;
} vigen_check_level;

/* Order conditions of one family of trees. */
enum {
    VIGEN_CHECK_GENERAL = 0,     /* every bicoloured tree: any H */
    VIGEN_CHECK_SEPARABLE = 1,   /* alternating trees: H = T(p) + V(q) */
    VIGEN_CHECK_A_ALONE = 2,     /* black trees: (c, A, b) as an RK method */
    VIGEN_CHECK_AT_ALONE = 3,    /* white trees: (ct, At, bt) as an RK method */
    VIGEN_CHECK_NYSTROM = 4,     /* alternating trees whose black vertices have at most one child:
                                    H = p^T M^-1 p / 2 + V(q), where dH/dp is linear in p */
    VIGEN_CHECK_FAMILIES = 5
};

typedef struct {
    vigen_check_level level;
    int evaluated_to;            /* highest order whose conditions were all evaluated */
    slong count[VIGEN_TREE_MAX_ORDER + 1], hold[VIGEN_TREE_MAX_ORDER + 1],
          fail[VIGEN_TREE_MAX_ORDER + 1], undecided[VIGEN_TREE_MAX_ORDER + 1];
    slong hold_data[VIGEN_TREE_MAX_ORDER + 1];        /* of hold: within the precision of the data */
    slong undecided_short[VIGEN_TREE_MAX_ORDER + 1];  /* of undecided: the data are too short */
    /* The first tree (lowest order, enumeration order) that fails, and the
     * first that is undecided; order 0 when there is none. */
    int fail_order, undecided_order;
    char *fail_tree, *undecided_tree;
    arb_t fail_value, fail_expected;            /* sum bhat_i Phi_i(t) and 1/gamma(t) */
    arb_t undecided_value, undecided_expected;
    /* Of hold: the conditions not evaluated because they follow from the
     * evaluated ones by symplecticity (docs/analysis.md, "One condition per
     * class of rerooted trees"); count - inferred were evaluated. */
    slong inferred[VIGEN_TREE_MAX_ORDER + 1];
} vigen_check_orders;

/* Sections of the report, for the statistics of holding conditions. */
enum {
    VIGEN_CHECK_SECT_ROWSUM = 0,
    VIGEN_CHECK_SECT_SYMPLECTIC = 1,
    VIGEN_CHECK_SECT_ORDER = 2,
    VIGEN_CHECK_SECT_SIMPLIFYING = 3,
    VIGEN_CHECK_SECT_AGAINST = 4,
    VIGEN_CHECK_SECTIONS = 5
};

/* How the conditions of one section that hold were decided. */
typedef struct {
    slong exact;                 /* on exact entries (confirmed at two precisions, or exactly 0) */
    slong data;                  /* within the precision of the data (rounded decimals, balls) */
    mag_t radius;                /* the largest radius among the latter */
    slong too_short;             /* undecided (not holding): balls on rounded data that contain 0
                                    but are wider than 2^-10 of their terms */
} vigen_check_holds;

/* A short decimal in a file of long ones: it may be an exact value typed as
 * a decimal ("0.5" for 1/2), read as a wide ball. */
typedef struct {
    char *entry;                 /* "b[1]", "A[2][1]" */
    char *text;                  /* the decimal as written */
    char *expression;            /* the entry's text when the decimal is inside an expression
                                    ("0.5*sqrt(3)"); NULL for a bare decimal */
    slong digits;                /* its significant digits */
    char *radius;                /* half a unit in its last digit ("0.05") */
    char *fraction;              /* its exact value ("1/2") */
    char *message;
} vigen_check_note;

/* The kind of a failing (or undecided) check in the list of failures: a row
 * sum, a symplecticity pair, a claim of the file, an entry that differs from
 * FILE2's. */
enum { VIGEN_CHECK_FAIL_ROWSUM, VIGEN_CHECK_FAIL_SYMPLECTIC, VIGEN_CHECK_FAIL_CLAIM, VIGEN_CHECK_FAIL_AGAINST };

/* One failing or undecided condition (or the diagnosis of a misprint). */
typedef struct {
    int kind;                    /* VIGEN_CHECK_FAIL_* */
    const char *claim;           /* claims: "order" or "symplectic"; NULL otherwise */
    const char *matrix;          /* "A", "At", "b", "bt", "c", "ct"; NULL when not applicable */
    slong row, col;              /* 1-based; 0 when not applicable */
    int undecided;               /* the condition is undecided, not failing */
    int diagnosed;               /* names the single entry that explains the failures */
    int has_value, has_expected;
    arb_t value, expected;       /* balls (row sums, symplecticity, against, diagnoses) */
    char *value_json, *expected_json;  /* for claims: JSON literals ("4", "true") */
    char *message;               /* one line */
} vigen_check_failure;

/* The order by the simplifying assumptions (theorem.c).  Butcher's theorem
 * (Butcher 1964; Hairer, Norsett, Wanner I, Thm II.7.4): B(p), C(eta), D(zeta)
 * with p <= eta + zeta + 1 and p <= 2 eta + 2 give order p.  Its proof
 * replaces sums over the children of a vertex by C and removes roots by D;
 * for a PRK method with c = ct (both the row sums) and b = bt every such step
 * gives the same result whatever the colours, so the statement holds for the
 * PRK method with eta, zeta and p the smallest over the two parts (the
 * colour-blind form; Hairer, Lubich, Wanner, GNI sec. III.2.2 uses the same
 * reduction for Lobatto IIIA-IIIB).  Necessary conditions: the bushy tree of
 * order q (a root and q - 1 leaves) has the condition
 * sum_i bhat_i (M 1)_i^(q-1) = 1/q with bhat the root's weights and M the
 * leaves' matrix: B(q) of (M 1, bhat).  Its failure with leaves of the
 * root's colour bounds the order for general H (and of that part alone), with
 * leaves of the other colour (an alternating tree) also for separable H. */
typedef struct {
    int applies;                 /* row sums, b = bt and c = ct hold: the theorem applies */
    const char *why_not;         /* otherwise which of them does not hold (static string) */
    int order;                   /* then the order for general H is >= order (0: nothing) */
    int B, eta, zeta;            /* the smallest levels over the parts */
    int within_data;             /* some assumption used holds only within the precision of the data */
    int bushy_to;                /* bushy trees decided up to this order */
    int bushy_fail[2];           /* [0] general H, [1] separable H: the lowest order q whose bushy
                                    tree fails (so the order is < q); 0 when none up to bushy_to */
} vigen_check_theorem;

/* The principal error coefficients (error_cost.c): for a family of order p, the
 * bicoloured trees t of order p + 1 of the family give
 * e(t) = (Phi(t) - 1/gamma(t)) / sigma(t), the coefficient of h^(p+1) F(t)
 * in the local error y1 - y(t0 + h) (P-series, HLW GNI sec. III.1-2);
 * the error constant is sqrt(sum e(t)^2). */
enum {
    VIGEN_CHECK_EC_GENERAL = 0,
    VIGEN_CHECK_EC_SEPARABLE = 1,
    VIGEN_CHECK_EC_NYSTROM = 2,
    VIGEN_CHECK_EC_FAMILIES = 3
};

typedef struct {
    int available;               /* computed: the order p is decided and p + 1 <= the orders evaluated */
    int order;                   /* p */
    slong ntrees;                /* trees of order p + 1 in the family */
    arb_t value;                 /* the 2-norm */
    arb_t sumsq[VIGEN_TREE_MAX_ORDER + 1];   /* sum of e(t)^2 over the family's trees of each order */
} vigen_check_error_constant;

/* The principal error of a splitting or composition method in the Lyndon
 * basis of the free Lie algebra on A (the generator of the drifts, T) and B
 * (the kicks, V), the form of the splitting literature (lie.c): the method is
 * exp(h (A + B) + h^(p+1) sum_w coef_w P(w) + ...), the substeps' Lie
 * operators multiplied in the order the flows are applied, P(w) the
 * standard bracketing of the Lyndon word w (A < B); p the order for
 * separable H. */
#define VIGEN_LIE_MAX_DEGREE 10
#define VIGEN_LIE_MAX_DEGREE_TEXT "10"
typedef struct {
    int computed;
    const char *why;             /* when not computed (static) */
    int degree;                  /* p + 1 */
    slong nterms;                /* Lyndon words of that length */
    slong ncap;                  /* the length of coef as allocated (>= nterms) */
    char **words;                /* "AAB" */
    char **brackets;             /* "[A,[A,B]]" */
    arb_ptr coef;
    arb_t norm;                  /* the 2-norm of coef */
} vigen_check_lie_error;

/* The orders of a splitting with named flows (or a corrector) for H = A +
 * eps B, B the flow `perturbation` (generalized.c).  The log of one step,
 * h (A + eps B) + sum_n h^n Z_n, is computed in the free Lie algebra to
 * degree `degree`; its part with j letters B carries eps^j.  r[j] is the
 * generalized order for eps^j: every term with j letters B of degree <=
 * r[j] vanishes and one of degree r[j] + 1 does not, so that the local error
 * is O(eps h^(r1+1) + eps^2 h^(r2+1) + ...) and the error in the energy
 * and over a fixed time O(eps h^r1 + eps^2 h^r2 + ...), the convention of
 * Laskar & Robutel (2001) and Blanes et al. (2013): SABA_n is (2n, 2).  The
 * classical order p (general A + B) is the least r[j]; the generalized
 * order is written (r1, ..., rk) with k the first j where r[j] = p (the
 * terms eps^j h^p beyond it are dominated). */
#define VIGEN_GEN_MAX_DEGREE 14
enum { VIGEN_GEN_DECIDED = 0, VIGEN_GEN_AT_LEAST = 1, VIGEN_GEN_UNDECIDED = 2 };
typedef struct {
    int computed;                /* the file names two flows or has a corrector */
    const char *why;             /* not decided: why (static), else NULL */
    char *letter_a, *letter_b;   /* the flows behind A and B (B carries eps), from malloc */
    int flipped;                 /* B is the file's first flow (the Lie basis's letter A) */
    int processed;               /* the step is C K C^-1 */
    int degree;                  /* terms computed to this degree */
    int rounded;                 /* coefficients are rounded decimals: vanishing means to the data's precision */
    int within_data;             /* some term taken as vanishing only to the data's precision */
    int classical;               /* the classical order p */
    int classical_state;         /* VIGEN_GEN_*: p decided, p >= classical (nothing fails to degree),
                                    or undecided (a term is undecided at degree classical + 1) */
    int k;                       /* the generalized order has k entries r[1..k] */
    int r[VIGEN_GEN_MAX_DEGREE + 1];
    int state[VIGEN_GEN_MAX_DEGREE + 1];   /* VIGEN_GEN_* of each r[j] */
    vigen_check_lie_error terms[VIGEN_GEN_MAX_DEGREE + 1];  /* [j]: the leading terms of eps^j (degree
                                                               r[j] + 1) in the Lyndon basis, when decided */
    int claim_status;            /* generalized_order claimed: tri-state (VIGEN_CHECK_YES ...); -1 absent */
    int claim_k;
    int claim[VIGEN_MAX_GENERALIZED];
    int brackets;                /* bracket flows of the file: the step's series has them, while the tableau
                                    (the tree conditions, stability, cost) is of the plain flows' substeps alone */
} vigen_check_generalized;

/* The linear stability interval on q'' = -omega^2 q (stability.c). */
enum { VIGEN_CHECK_STAB_NONE = 0, VIGEN_CHECK_STAB_BOUNDED = 1, VIGEN_CHECK_STAB_UNBOUNDED = 2,
       VIGEN_CHECK_STAB_UNDECIDED = 3 };

typedef struct {
    int status;                  /* VIGEN_CHECK_STAB_* */
    arb_t x;                     /* bounded: the end x* of the interval (h omega < x*), certified */
    const char *reason;          /* why (static string) */
} vigen_check_stability;

/* The cost of a step (error_cost.c). */
typedef struct {
    slong stages;
    slong force;                 /* evaluations of -dV/dq per step, separable H */
    slong velocity;              /* evaluations of dT/dp per step, separable H */
    int explicit_separable;      /* the stages can be computed in sequence for H = T(p) + V(q) */
    int explicit_general;        /* ... for every H (A and At strictly lower triangular) */
    int fsal;                    /* the first force is the last one of the previous step */
} vigen_check_cost;

/* The C type of the value of an X_RESULT row of check_fields.def, by the
 * row's type (BALL values are initialised and cleared with the report, STR
 * values are from malloc and freed with it). */
#define VIGEN_CHECK_VALUE_BOOL int
#define VIGEN_CHECK_VALUE_INT int
#define VIGEN_CHECK_VALUE_LONG slong
#define VIGEN_CHECK_VALUE_TRI int
#define VIGEN_CHECK_VALUE_STR char *
#define VIGEN_CHECK_VALUE_BALL arb_t

/* What a check found.  The checks of vigen/check_fields.def write it; the
 * reports print it, one row of that table per figure.  The members below up
 * to exit_code are written by hand (the X_CHECK rows' findings); a check of
 * an X_RESULT row has its member generated from its row, at the end. */
typedef struct {
    char *path, *name;
    slong s, prec;               /* precision of the final round, bits */
    slong prec_first;            /* precision of the first round */
    slong rounds;                /* evaluations done (1 + refinements and confirmations) */
    slong undecided_left;        /* undecided balls in the final round */
    slong undecided_short;       /* ... of which on rounded data too short to decide them */
    const char *undecided_reason;/* why refining stopped with undecided balls (static string) */
    int max_order;
    int has_At, has_bt, has_ct;
    int rounded_entries;         /* some entry is a rounded decimal (or the tableau is balls only) */
    int exact_entries;           /* some entry is an exact expression */
    char *rational_denominator;  /* every entry rational: their common denominator D (decimal); else NULL */
    char *quadratic_d;           /* every entry a + b sqrt(d), a and b rational, for one squarefree d > 1
                                    (and some b != 0): d (decimal); else NULL */
    char *quadratic_denominator; /* ... and the common denominator D of every a and b (decimal) */
    slong proved;                /* holds proved exactly by the denominator bound (rational tableaux) or
                                    by the norm bound (quadratic tableaux) */
    vigen_check_holds holds[VIGEN_CHECK_SECTIONS];

    int consistent;              /* row sums and sum b = 1 (tri-state) */
    int consistent_within_data;  /* consistent, some condition only within the precision of the data */
    int symplectic_within_data;  /* symplectic (or for separable H), likewise */
    int symplectic;              /* tri-state: bt = b and b_i at_ij + b_j a_ji = b_i b_j */
    int symplectic_separable;    /* tri-state: b_i at_ij + bt_j a_ji = b_i bt_j, which suffices
                                    for separable H (GNI Thm VI.4.6); bt may differ from b */
    slong sym_fail, sym_undecided, sym_total;   /* conditions of symplecticity */
    slong row_fail, row_undecided, row_total;   /* row-sum conditions */

    vigen_check_orders orders[VIGEN_CHECK_FAMILIES];

    /* Simplifying assumptions, [0] = (c, A, b), [1] = (ct, At, bt). */
    vigen_check_level B[2], C[2], D[2], stage_order[2];
    int simplifying_cap;

    vigen_check_theorem theorem;
    vigen_check_error_constant error_constant[VIGEN_CHECK_EC_FAMILIES];
    vigen_check_stability stability;
    vigen_check_lie_error lie_error;
    vigen_check_generalized *generalized;   /* named flows: the orders for H = A + eps B; else NULL */
    vigen_check_cost cost;

    int claim_order;             /* -1 when the file states none */
    int claim_order_status;      /* tri-state */
    int claim_order_separable;   /* the claim matches the separable order only */
    int claim_order_beyond;      /* undecided because order claim + 1 exceeds VIGEN_TREE_MAX_ORDER */
    int claim_order_within_data; /* holds, resting on conditions that hold within the precision of the data */
    int claim_order_too_short;   /* undecided because the data are too short */
    int claim_order_theorem;     /* decided by the simplifying assumptions and the bushy trees */
    int claim_symplectic;        /* -1, 0, 1 */
    int claim_order_family[2];   /* order_separable, order_nystrom claimed (-1 absent) */
    int claim_order_family_status[2];   /* tri-state: the certified order of the family is exactly that */
    int claim_symplectic_status;
    int claim_symplectic_separable;  /* the claim holds for separable H only */
    int claim_symplectic_within_data;

    int against_checked;
    slong against_differences;
    slong against_undecided;
    slong against_stages;        /* FILE2's stage count when it differs from s, else 0 */

    slong nfailures, alloc_failures;
    vigen_check_failure *failures;   /* failing and undecided conditions (JSON "problems") */

    slong nnotes;
    vigen_check_note *notes;     /* short decimals that look exact */
    char *reducible;             /* stages that are one stage, or that do nothing: the cause and
                                    what to change (one sentence), or NULL */

    int exit_code;               /* 0 consistent, every claim holds (within the precision of the
                                    data counts) and (--against) no entry differs or is
                                    undecided; 1 otherwise */

    /* One member per X_RESULT row of check_fields.def, named as the check:
     * set when the check reported its value (else the JSON has null and the
     * text no line), the value, and the check's own words for the text
     * report (NULL: the value in words). */
#define X_CHECK(name, fn, description)
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn)
#define X_RESULT(name, fn, description, type, sep, text_at, label)                                                   \
    struct {                                                                                                           \
        int set;                                                                                                       \
        VIGEN_CHECK_VALUE_##type value;                                                                                \
        char *text;                                                                                                    \
    } name;
#include "vigen/check_fields.def"
#undef X_CHECK
#undef X_FIGURE
#undef X_RESULT
} vigen_check_report;

/* A report with nothing checked (no claims, no failures); every report is
 * initialised before a check and cleared after it (which frees its texts,
 * balls, failures and notes). */
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

/* The order the report certifies for a family (VIGEN_CHECK_GENERAL,
 * _SEPARABLE, _NYSTROM): the enumerated trees, a confirmed claim, or
 * Butcher's theorem beyond them; *at_least when nothing bounds it from above,
 * *undecided when the next order is undecided. */
int vigen_check_certified_order(const vigen_check_report *rep, int family, int *at_least, int *undecided);

/* Checks t (a copy; its texts as written, as `vigen check` reads the file)
 * and records what is certified as the file's claims: order = p when the
 * order is decided, symplectic = true or false when decided.  For a tableau
 * the generator has just made (t->generated_now) the order is first decided
 * by Butcher's theorem on the generator's balls (B(p), C, D and every bushy
 * tree of order p + 1 failing, at the precision of its digits up to 1024
 * bits), which gives what the check would; the
 * check runs where the theorem does not decide.  The environment variable
 * VIGEN_CERTIFY_TREES=1 makes it run always.  A claim
 * t->claim_order already set (a spec's order = p) that is false is an error
 * (VIGEN_E_MATH) naming the failing tree. */
int vigen_check_certify(vigen_tableau *t, const char *path, vigen_error *err);

/* The checks the checker runs (the X_CHECK and X_RESULT rows of
 * vigen/check_fields.def), one line each with what it
 * decides, for `vigen help checks`.  A heap string; free with free(). */
char *vigen_check_list_text(void);

/* The report of `vigen check` as text (for a reader) or as one JSON object
 * and a newline.  Both print the same figures, one per row of the report
 * table (vigen/check_fields.def: the JSON key, how the value is written,
 * when the figure is reported, where its text lines go), so that a
 * figure cannot be in one report and missing from the other by oversight.
 * Texts from the file are escaped. */
void vigen_check_print_text(FILE *out, const vigen_check_report *rep);
void vigen_check_print_json(FILE *out, const vigen_check_report *rep);

/* Loads opt->path (and opt->against) through opt->load (tableau files only
 * when NULL) and checks it into rep (initialised by the caller with
 * vigen_check_report_init, cleared by it).  Returns VIGEN_OK when everything
 * could be loaded and evaluated: the verdict is then rep->exit_code (0
 * consistent and every stated claim holds, 1 something fails or cannot be
 * decided), and the caller prints rep.  Otherwise err holds the message
 * (prefixed with the path when the tableau could not be evaluated) and
 * vigen_status_exit_code of the code (status.def) is the exit status: 2
 * unreadable or invalid input (a file that describes no method included) or
 * usage error, 3 a resource limit or the precision cap reached. */
int vigen_check_file(vigen_check_report *rep, const vigen_check_options *opt, vigen_error *err);

#endif
