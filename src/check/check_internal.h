/* check_internal.h — what the files of the checker share: the three-valued
 * verdict, entries and their exactness, the evaluation context (ctx_t) that
 * every decision goes through, the row-sum and symplecticity conditions, and
 * the state of one round of checks (chk_round) that the checks of
 * vigen/check_fields.def are run on.  Not installed: nothing outside src/check uses it.
 */
#ifndef VIGEN_CHECK_INTERNAL_H
#define VIGEN_CHECK_INTERNAL_H

#include <arb.h>
#include <arb_mat.h>
#include "vigen/check.h"
#include "check/balls.h"
#include "vigen/trees.h"
#include "support/strbuf.h"

/* Appends the bracket notation (vigen/trees.h) of a stored tree, or of the
 * tree (colour, forest), to sb: the reports build their lines with it
 * (trees.c; vigen_tree_text gives it as a string to library users). */
void chk_tree_append(vigen_strbuf *sb, const vigen_treeset *ts, slong id);
void chk_forest_tree_append(vigen_strbuf *sb, const vigen_treeset *ts, int colour, const slong *ids, int k);

#define CHK_DEFAULT_MAX_ORDER 8
#define CHK_DEFAULT_MAX_PREC 4096

/* Short decimals that look exact: at most this many significant digits ... */
#define CHK_NOTE_SHORT_DIGITS 3
/* ... in a file whose longest decimal has at least this many. */
#define CHK_NOTE_LONG_DIGITS 10

/* The verdict on one condition (see check.h for when each is given). */
enum { HOLDS = 0, FAILS = 1, UNDECIDED = 2 };

/* Entry names; At, bt, ct alias A, b, c when the tableau does not give them. */
enum { M_A, M_AT, M_B, M_BT, M_C, M_CT };
extern const char *const chk_matrix_names[6];   /* "A", "At", "b", "bt", "c", "ct" */

typedef struct {
    int mat;
    slong i, j;
} entry;

/* Which entries are exact expressions (1) rather than rounded decimals or
 * balls without texts (0); row-major for the matrices, as the texts. */
typedef struct {
    slong s;
    unsigned char *A, *At, *b, *bt, *c, *ct;
    int part[2];                 /* every entry of (A, b) resp. (At, bt) is exact */
    int part_c[2];               /* ... and of c resp. ct */
    int any_exact, any_rounded;
    /* Every entry a + b sqrt(qd) with a, b rational, in Q (qd = 1) or in one
     * real quadratic field Q(sqrt qd) (qd > 1 squarefree): den is a common
     * denominator of every a and b; otherwise den = qd = 0. */
    fmpz_t den, qd;
    char **conj[6];              /* qd > 1: the conjugate entries a - b sqrt(qd) as texts, in the
                                    order of the lists of chk_exactness_init (NULL when not given) */
} exactness;

/* Which condition a decision is about: its section, its shape (k, g, see
 * chk_ctx_shape) and its identity within the section. */
typedef struct {
    int section;
    slong k;
    ulong g;
    slong id[3];
} cond_tag;

/* For a tableau in Q(sqrt d): one round on the conjugate tableau (every
 * sqrt(d) negated) records, per decision, the condition and an upper bound of
 * |v'|, its value there; the round on the tableau itself replays the
 * record in order and uses a bound only while every condition so far was the
 * same (the sequences could differ where the two rounds' verdicts do, since
 * later checks depend on earlier verdicts: the rest of that round then goes
 * without bounds). */
typedef struct {
    cond_tag *tag;
    mag_struct *bound;
    slong n, alloc;
    slong pos;                   /* replay: the next decision */
    int in_step;                 /* replay: every decision so far matched the record */
} conj_log;

typedef struct {
    slong s, prec;
    int has_At, has_bt, has_ct;
    const vigen_tableau *t;
    const arb_mat_struct *A, *At;
    arb_srcptr b, bt, c, ct;
    const exactness *ex;
    int strict;                  /* exact holds with a nonzero radius count as undecided */
    int section;                 /* VIGEN_CHECK_SECT_* of the decisions being made */
    vigen_check_holds *holds;    /* statistics per section (the report's) */
    slong n_undecided, n_undecided_exact, n_unconfirmed;
    slong n_undecided_short;     /* undecided: rounded data too short (ball containing 0, too wide) */
    int last_within;             /* the last decision: a hold within the precision of the data */
    int last_short;              /* the last decision: undecided, the data too short */
    slong n_proved;              /* holds proved by the denominator bound */
    slong rat_k;                 /* the condition being decided: a sum of products of rat_k */
    ulong rat_g;                 /* entries, minus a constant with denominator rat_g (0: no bound) */
    slong cond_id[3];            /* ... and which condition of its section it is */
    ulong hash;                  /* of the sequence of verdicts */
    conj_log *conj;              /* quadratic entries: the conjugate's bounds (NULL: none) */
    int conj_recording;          /* this round runs on the conjugate tableau and fills conj */
    const mag_struct *conj_bound;/* for the decision being made: an upper bound of |v'|, or NULL */
    int skip_generalized;        /* the caller wants the classical figures only */
} ctx_t;

/* Up to two entries replaced by other values. */
typedef struct {
    int n;
    entry e[2];                  /* canonical */
    arb_srcptr value[2];
} override;

enum { C_ROWSUM_A, C_ROWSUM_AT, C_SUM_B, C_SUM_BT, C_BT_EQ_B, C_SYMP };

typedef struct {
    int type;
    slong i, j;
    int status;
    int too_short;               /* undecided because the rounded data are too short */
    arb_t r;                     /* left side - right side */
} cond;

/* The tableau at the midpoints of its balls (exact values), for the typo
 * diagnosis. */
typedef struct {
    arb_mat_t A, At;
    arb_ptr b, bt, c, ct;
    ctx_t cx;
} midpoints;


/* One round of every check at one precision: what the checks of
 * vigen/check_fields.def read and write. */
typedef struct {
    vigen_check_report *rep;
    ctx_t *cx;                   /* the checked tableau at this round's precision */
    vigen_tableau *t;
    vigen_tableau *against;      /* FILE2 or NULL */
    const exactness *ex_against;
    int P;                       /* orders 1..P */
    /* the row-sum and symplecticity conditions of this round, in the order
     * decided, kept for the diagnosis that traces their failures to an entry */
    cond *conds;
    slong nconds, alloc_conds;
    int have_mid;
    midpoints mid;               /* the tableau at its midpoints (when have_mid) */
} chk_round;

/* A check: the function of an X_CHECK or X_RESULT row of
 * vigen/check_fields.def. */
typedef int (*chk_check_fn)(chk_round *r, vigen_error *err);

#define X_CHECK(name, fn, description) int fn(chk_round *r, vigen_error *err);
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn)
#define X_RESULT(name, fn, description, type, sep, text_at, label) int fn(chk_round *r, vigen_error *err);
#include "vigen/check_fields.def"
#undef X_CHECK
#undef X_FIGURE
#undef X_RESULT

/* report_init.c: problems filed into the report, its notes torn down, the
 * members of the X_RESULT rows cleared before a round */
vigen_check_failure *chk_failure_new(vigen_check_report *rep, int kind);
void chk_results_reset(vigen_check_report *rep);
void chk_failures_clear(vigen_check_report *rep);
void chk_notes_clear(vigen_check_report *rep);

/* exactness.c: which entries are exact, and in which field (Q, Q(sqrt d)) */
void chk_exactness_init(exactness *x, const vigen_tableau *t);
void chk_exactness_clear(exactness *x);
int chk_has_texts(const vigen_tableau *t);

/* decide.c: the context of a round and the decision on one condition.
 * chk_ctx_shape states the shape of the next condition (a sum of products of
 * at most k entries minus a constant with denominator dividing g; g = 0: no
 * proof by denominators) and its identity (a, b, c) within its section;
 * chk_decide gives its verdict on r with scale an upper bound of the size of
 * its terms, chk_decide2 with the scale |a| + |b| of a comparison a = b. */
void chk_conj_log_init(conj_log *log);
void chk_conj_log_clear(conj_log *log);
void chk_conj_log_start(conj_log *log, int recording);
void chk_ctx_init(ctx_t *cx, const vigen_tableau *t, const exactness *ex, vigen_check_holds *holds);
void chk_ctx_shape(ctx_t *cx, slong k, ulong g, slong a, slong b, slong c);
void chk_mid_mag(mag_t m, const arb_t x);
int chk_decide(ctx_t *cx, const arb_t r, int exact, const mag_t scale);
int chk_decide2(ctx_t *cx, const arb_t r, int exact, const arb_t a, const arb_t b);
int chk_tri_of(slong fail, slong undecided);

/* conditions.c: entries and the row-sum and symplecticity conditions */
int chk_entry_eq(entry x, entry y);
const char *chk_entry_text(const ctx_t *cx, entry e);
override chk_ov1(entry e, arb_srcptr v);
arb_srcptr chk_get(const ctx_t *cx, int mat, slong i, slong j, const override *ov);
int chk_cond_is_rowsum(const cond *c);
void chk_add_cond(cond *conds, slong *n, int type, slong i, slong j);
void chk_cond_parts(arb_t value, arb_t expected, const ctx_t *cx, const cond *c, const override *ov);
void chk_cond_eval(arb_t r, const ctx_t *cx, const cond *c, const override *ov);
slong chk_cond_entries(entry *out, const ctx_t *cx, const cond *c);
int chk_cond_involves(const ctx_t *cx, const cond *c, entry e);
int chk_cond_exact(const ctx_t *cx, const cond *c);
int chk_cond_decide(ctx_t *cx, const cond *c);
const char *chk_cond_kind_words(int type);
arb_srcptr chk_entry_value(const ctx_t *cx, entry e);
char *chk_entry_name(entry e);

/* diagnose.c: the enclosure of a condition over the balls of its entries */
void chk_midpoints_init(midpoints *m, const ctx_t *cx);
void chk_midpoints_clear(midpoints *m);
void chk_cond_enclose(arb_t out, const ctx_t *cx, const ctx_t *mx, const cond *c, const entry *e, const arb_t fix);

/* notes.c: the precision the literals ask for, notes on short decimals */
void chk_collect_notes(vigen_check_report *rep, const vigen_tableau *t);
/* Stages that are one stage (equal rows of A and At) or that do nothing
 * (weight 0, used by no stage): rep->reducible (notes.c). */
void chk_collect_reducible(vigen_check_report *rep, const vigen_tableau *t);
/* The principal error of t's substeps in the Lyndon basis at degree p + 1
 * (lie.c); le->computed = 0 with le->why when it does not apply. */
int chk_lie_error(vigen_check_lie_error *le, const vigen_tableau *t, int p, slong prec, vigen_error *err);
void chk_lie_error_clear(vigen_check_lie_error *le);
/* lie.c: series in the free associative algebra on {A, B} truncated at
 * degree N, vectors of 2^(N+1) balls: the word of n letters with bits b (the
 * first letter the most significant, A = 0, B = 1) at index (1 << n) | b.
 * chk_lie_mul: out = x y (no aliasing).  chk_lie_is_lyndon: the word (b, n)
 * is a Lyndon word.  chk_lie_bracket: its standard bracketing P(w) into out,
 * the bracket's text appended to sb.  chk_lie_log: log of the product of t's
 * substeps exp(coef_k h X_k) in order of application (X = A for the drift
 * letter, B for the kick; flip = 1 swaps them).  chk_lie_lyndon: the
 * coefficients of lg's homogeneous part of degree n (nb >= 0: with nb
 * letters B only) in the Lyndon basis into le (lg's part is consumed). */
void chk_lie_mul(arb_ptr out, arb_srcptr x, arb_srcptr y, slong N, slong prec);
int chk_lie_is_lyndon(slong b, slong n);
void chk_lie_bracket(arb_ptr out, vigen_strbuf *sb, slong b, slong n, slong N, slong prec);
int chk_lie_log(arb_ptr lg, const vigen_tableau *t, slong N, int flip, slong prec, vigen_error *err);
void chk_lie_lyndon(vigen_check_lie_error *le, arb_ptr lg, slong N, slong n, int nb, slong prec);
slong chk_adequate_prec(const vigen_tableau *t);
/* The substeps of one step as the Lie series reads them: the tableau's, or
 * for a method with bracket flows its step (vigen_flows.step_*): their
 * number and the coefficient text of substep k.  chk_lie_log takes a
 * bracket flow's substep as exp(coef X), X its bracket in the free Lie
 * algebra (homogeneous of degree its letters: h^k). */
slong chk_lie_step_count(const vigen_tableau *t);
const char *chk_lie_step_coef(const vigen_tableau *t, slong k);

/* simplifying.c: the simplifying assumptions of one part (c, A, b) of the
 * tableau, decided: B(k) sum_i b_i c_i^(k-1) = 1/k, C(k) sum_j a_ij
 * c_j^(k-1) = c_i^k / k for every i, D(k) sum_i b_i c_i^(k-1) a_ij = b_j (1 -
 * c_j^k) / k for every j; HOLDS, FAILS or UNDECIDED (the worst over i, j). */
typedef struct {
    ctx_t *cx;
    const arb_mat_struct *A;
    arb_srcptr b, c;
    arb_ptr cp;                  /* cp[k*s + i] = c_i^k, k = 0..cap */
    int exact;                   /* every entry of (c, A, b) of the part is exact (D) */
    int exact_B;                 /* ... of (c, b) (B) */
    int exact_C;                 /* ... of (c, A) (C) */
    int part;                    /* 0: (c, A, b), 1: (ct, At, bt) */
} chk_part;
int chk_assumption_B(chk_part *p, int k);
int chk_assumption_C(chk_part *p, int k);
int chk_assumption_D(chk_part *p, int k);

/* theorem.c: x_i = y_i for every i (b = bt, c = ct; ex, ey: which are
 * exact), HOLDS, FAILS or UNDECIDED, *data |= some hold is within the
 * precision of the data; and the bushy trees of orders from..Q, root
 * weights bhat (b or bt), leaves rows of M (A or At): sum_i bhat_i (M 1)_i^(n-1)
 * = 1/n.  fail[0]: the first order where one fails (general H), fail[1]: where
 * one with leaves of the other colour fails (separable H), *all: where all
 * four fail (0: none); it stops when fail[0] and fail[1] are set and returns
 * the last order evaluated. */
int chk_decide_equal(ctx_t *cx, arb_srcptr x, arb_srcptr y, const unsigned char *ex, const unsigned char *ey,
                     slong id, int *data);
int chk_bushy(ctx_t *cx, int from, int Q, int fail[2], int *all);

/* certify_theorem.c: the order of a tableau with balls (a generated one),
 * exactly p for general, separable and Nystrom H, decided by Butcher's
 * theorem and a failing bushy tree of order p + 1 on its balls at the
 * precision of its certified digits, and its symplecticity.  Returns 1 and
 * sets *out when all of it is decided; 0 when the trees must decide. */
typedef struct {
    int order;                   /* for every family; -1: at least 64, undecided as in the check */
    int symplectic;              /* 1 yes, 0 no */
    slong prec;                  /* the precision that decided */
} chk_theorem_verdict;
int chk_certify_theorem(chk_theorem_verdict *out, const vigen_tableau *t);

/* checks.c: one round of every check of vigen/check_fields.def */
int chk_round_run(vigen_check_report *rep, ctx_t *cx, vigen_tableau *t, vigen_tableau *against,
                  const exactness *ex_against, int P, vigen_error *err);

/* reduction.c: order conditions that follow from others by symplecticity.
 * For trees u, v whose roots are joined by an edge of the kind edge[colour of
 * u's root][colour of v's root] allows, u o v (v grafted onto u's root) and
 * v o u satisfy Phi(u o v) + Phi(v o u) = Phi(u) Phi(v), as 1/gamma does:
 * when the conditions of lower order hold, the two residuals are opposite.
 * A tree is skipped when its root has a child v of order > n/2 across such
 * an edge; following skips ends at an evaluated tree of the same class. */
typedef struct {
    int on;                      /* some edge allows rerooting */
    int edge[2][2];              /* [root colour][child colour] */
    int within_data;             /* the symplecticity used holds within the precision of the data */
} chk_reduction;
void chk_reduction_init(chk_reduction *red, const vigen_check_report *rep, const ctx_t *cx);
int chk_reduction_skips(const chk_reduction *red, const vigen_treeset *ts, int n, int colour, const slong *ids, int k);

/* enclose_tree.c: the enclosure of a tree condition r = bhat . Phi - 1/gamma
 * (colour, forest ids[0..k-1]; inv = 1/gamma) over the balls of the entries
 * by the mean-value form r(mid) +- (sum_u |dr/du| rad_u + second-order
 * remainder); for rounded data, where plain ball arithmetic overestimates. */
typedef struct chk_tree_encl chk_tree_encl;
chk_tree_encl *chk_tree_encl_new(const ctx_t *cx);
void chk_tree_encl_free(chk_tree_encl *te);
/* exclusion_only: the caller needs the enclosure only if it may exclude 0;
 * returns 0 without it when it certainly contains 0, 1 when out is set. */
int chk_tree_enclose(arb_t out, chk_tree_encl *te, const vigen_treeset *ts, int colour, const slong *ids, int k,
                     const arb_t inv, int exclusion_only);

#endif
