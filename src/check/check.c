/* check.c — the certifying checker behind `vigen check` (see check.h).
 *
 * Layout: the evaluation context and the three-valued decision; row sums and
 * symplecticity as a list of conditions (so that a failure can be traced back
 * to one entry); order conditions by a depth-first walk over the forests of
 * trees.h with memoised vectors; simplifying assumptions; claims and
 * --against; the refinement loop; text and JSON output; the command line.
 */
#include <math.h>
#include <mpfr.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/check.h"
#include "core/decimal.h"
#include "core/expr.h"


#define DEFAULT_MAX_ORDER 8
#define DEFAULT_MAX_PREC 4096

void vigen_check_options_init(vigen_check_options *opt)
{
    memset(opt, 0, sizeof(*opt));
    opt->max_order = DEFAULT_MAX_ORDER;
    opt->max_prec = DEFAULT_MAX_PREC;
    opt->spec_digits = 34;
}

/* ------------------------------------------------------------ context */

enum { HOLDS = 0, FAILS = 1, UNDECIDED = 2 };

/* Entry names; At, bt, ct alias A, b, c when the tableau does not give them. */
enum { M_A, M_AT, M_B, M_BT, M_C, M_CT };
static const char *const matrix_names[] = {"A", "At", "b", "bt", "c", "ct"};

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
                                    order of the lists of exactness_init (NULL when not given) */
} exactness;

static int text_exact(char **texts, slong k) { return texts != NULL && texts[k] != NULL && !vigen_decimal_is_rounded(texts[k]); }

/* Entries in Q or in one Q(sqrt d) make holds provable (see proved_zero()).
 * With D a common denominator of every a and b of the entries a + b sqrt(d),
 * each condition value v (a sum of products of k entries, minus a constant
 * with denominator g) has v D^k g = m + n sqrt(d) with integers m, n.  Sets
 * x->den = D and x->qd = d (1 for rationals) when every given entry is such a
 * value, and for d > 1 the texts of the conjugate entries a - b sqrt(d); the
 * caller has checked that every entry is exact. */
static void algebraic_init(exactness *x, char **const lists[6], const slong lens[6])
{
    int ok = x->part_c[0] && x->part_c[1];
    fmpz_one(x->den);
    fmpz_one(x->qd);
    fmpq *qa[6] = {NULL}, *qb[6] = {NULL};
    fmpz_t d;
    fmpz_init(d);
    for (int l = 0; l < 6 && ok; l++) {
        if (lists[l] == NULL) continue;
        qa[l] = _fmpq_vec_init(lens[l]);
        qb[l] = _fmpq_vec_init(lens[l]);
        for (slong k = 0; k < lens[l] && ok; k++) {
            vigen_expr *e = NULL;
            vigen_error err;
            vigen_error_init(&err);
            ok = lists[l][k] != NULL && vigen_expr_parse(&e, lists[l][k], 0, &err) == VIGEN_OK &&
                 vigen_expr_to_quadratic(qa[l] + k, qb[l] + k, d, e);
            /* one field for the whole tableau */
            if (ok && !fmpz_is_one(d)) {
                if (fmpz_is_one(x->qd)) fmpz_set(x->qd, d);
                else ok = fmpz_equal(x->qd, d);
            }
            if (ok) {
                fmpz_lcm(x->den, x->den, fmpq_denref(qa[l] + k));
                fmpz_lcm(x->den, x->den, fmpq_denref(qb[l] + k));
            }
            vigen_expr_free(e);
            vigen_error_clear(&err);
        }
    }
    if (ok && !fmpz_is_one(x->qd)) {
        char *ds = fmpz_get_str(NULL, 10, x->qd);
        for (int l = 0; l < 6; l++) {
            if (lists[l] == NULL) continue;
            x->conj[l] = flint_calloc((size_t)lens[l], sizeof(char *));
            for (slong k = 0; k < lens[l]; k++) {
                char *a = fmpq_get_str(NULL, 10, qa[l] + k), *b = fmpq_get_str(NULL, 10, qb[l] + k);
                x->conj[l][k] = vigen_strdup_printf("(%s) - (%s)*sqrt(%s)", a, b, ds);
                flint_free(a);
                flint_free(b);
            }
        }
        flint_free(ds);
    }
    for (int l = 0; l < 6; l++)
        if (qa[l]) {
            _fmpq_vec_clear(qa[l], lens[l]);
            _fmpq_vec_clear(qb[l], lens[l]);
        }
    fmpz_clear(d);
    if (!ok) {
        fmpz_zero(x->den);
        fmpz_zero(x->qd);
    }
}

static void exactness_init(exactness *x, const vigen_tableau *t)
{
    slong s = t->s;
    x->s = s;
    x->A = flint_calloc((size_t)(s * s), 1);
    x->At = flint_calloc((size_t)(s * s), 1);
    x->b = flint_calloc((size_t)s, 1);
    x->bt = flint_calloc((size_t)s, 1);
    x->c = flint_calloc((size_t)s, 1);
    x->ct = flint_calloc((size_t)s, 1);
    int texts = t->c_text != NULL && t->A_text != NULL && t->b_text != NULL;
    x->any_exact = 0;
    x->any_rounded = !texts;
    fmpz_init(x->den);
    fmpz_init(x->qd);
    for (int l = 0; l < 6; l++) x->conj[l] = NULL;
    if (!texts) {
        x->part[0] = x->part[1] = x->part_c[0] = x->part_c[1] = 0;
        return;
    }
    int has_At = t->has_At, has_bt = t->has_At && t->has_bt, has_ct = t->has_At && t->has_ct;
    for (slong k = 0; k < s * s; k++) {
        x->A[k] = (unsigned char)text_exact(t->A_text, k);
        x->At[k] = has_At ? (unsigned char)text_exact(t->At_text, k) : x->A[k];
    }
    for (slong i = 0; i < s; i++) {
        x->b[i] = (unsigned char)text_exact(t->b_text, i);
        x->bt[i] = has_bt ? (unsigned char)text_exact(t->bt_text, i) : x->b[i];
        x->c[i] = (unsigned char)text_exact(t->c_text, i);
        if (!has_At) x->ct[i] = x->c[i];
        else if (has_ct) x->ct[i] = (unsigned char)text_exact(t->ct_text, i);
        else {   /* ct computed from the row sums of At */
            int all = 1;
            for (slong j = 0; j < s; j++) all &= x->At[i * s + j];
            x->ct[i] = (unsigned char)all;
        }
    }
    for (int part = 0; part < 2; part++) {
        const unsigned char *M = part ? x->At : x->A, *w = part ? x->bt : x->b, *c = part ? x->ct : x->c;
        int all = 1, allc = 1;
        for (slong k = 0; k < s * s; k++) all &= M[k];
        for (slong i = 0; i < s; i++) all &= w[i];
        for (slong i = 0; i < s; i++) allc &= c[i];
        x->part[part] = all;
        x->part_c[part] = all && allc;
    }
    /* what the file gives (texts present), exact or rounded */
    char **lists[6] = {t->c_text, t->b_text, has_ct ? t->ct_text : NULL, has_bt ? t->bt_text : NULL, t->A_text,
                       has_At ? t->At_text : NULL};
    slong lens[6] = {s, s, s, s, s * s, s * s};
    for (int l = 0; l < 6; l++)
        for (slong k = 0; lists[l] && k < lens[l]; k++) {
            if (lists[l][k] == NULL) continue;
            if (vigen_decimal_is_rounded(lists[l][k])) x->any_rounded = 1;
            else x->any_exact = 1;
        }
    algebraic_init(x, lists, lens);
}

static void exactness_clear(exactness *x)
{
    slong lens[6] = {x->s, x->s, x->s, x->s, x->s * x->s, x->s * x->s};
    for (int l = 0; l < 6; l++) {
        for (slong k = 0; x->conj[l] && k < lens[l]; k++) free(x->conj[l][k]);
        flint_free(x->conj[l]);
    }
    fmpz_clear(x->den);
    fmpz_clear(x->qd);
    flint_free(x->A);
    flint_free(x->At);
    flint_free(x->b);
    flint_free(x->bt);
    flint_free(x->c);
    flint_free(x->ct);
}

/* Which condition a decision is about: its section, its shape (k, g, see
 * ctx_shape) and its identity within the section. */
typedef struct {
    int section;
    slong k;
    ulong g;
    slong id[3];
} cond_tag;

static int cond_tag_eq(const cond_tag *x, const cond_tag *y)
{
    return x->section == y->section && x->k == y->k && x->g == y->g && x->id[0] == y->id[0] &&
           x->id[1] == y->id[1] && x->id[2] == y->id[2];
}

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

static void conj_log_init(conj_log *log) { memset(log, 0, sizeof(*log)); }

static void conj_log_clear(conj_log *log)
{
    for (slong k = 0; k < log->alloc; k++) mag_clear(log->bound + k);
    flint_free(log->bound);
    flint_free(log->tag);
}

/* Starts a round: recording afresh, or replaying from the first decision. */
static void conj_log_start(conj_log *log, int recording)
{
    if (recording) log->n = 0;
    log->pos = 0;
    log->in_step = 1;
}

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
} ctx_t;

static void ctx_init(ctx_t *cx, const vigen_tableau *t, const exactness *ex, vigen_check_holds *holds)
{
    cx->s = t->s;
    cx->prec = t->prec;
    cx->t = t;
    cx->ex = ex;
    cx->has_At = t->has_At;
    cx->has_bt = t->has_At && t->has_bt;
    cx->has_ct = t->has_At && t->has_ct;
    cx->A = t->A;
    cx->At = t->has_At ? t->At : t->A;
    cx->b = t->b;
    cx->bt = cx->has_bt ? t->bt : t->b;
    cx->c = t->c;
    cx->ct = t->has_At ? t->ct : t->c;   /* tableau.c fills ct with row sums of At when absent */
    cx->strict = 0;
    cx->section = VIGEN_CHECK_SECT_ROWSUM;
    cx->holds = holds;
    cx->n_undecided = cx->n_undecided_exact = cx->n_unconfirmed = 0;
    cx->n_undecided_short = 0;
    cx->last_within = cx->last_short = 0;
    cx->n_proved = 0;
    cx->rat_k = 0;
    cx->rat_g = 0;
    cx->cond_id[0] = cx->cond_id[1] = cx->cond_id[2] = 0;
    cx->hash = 1469598103934665603ULL;
    cx->conj = NULL;
    cx->conj_recording = 0;
    cx->conj_bound = NULL;
}

/* Sets the next condition: a sum of products of at most k entries, minus a
 * constant with denominator dividing g (for the denominator bound; g = 0: no
 * bound), and (a, b, c) naming it within its section (for the conjugate's
 * record, see conj_log). */
static void ctx_shape(ctx_t *cx, slong k, ulong g, slong a, slong b, slong c)
{
    cx->rat_k = k;
    cx->rat_g = g;
    cx->cond_id[0] = a;
    cx->cond_id[1] = b;
    cx->cond_id[2] = c;
}

/* Before a decision on r: records an upper bound of |r| when this round runs
 * on the conjugate tableau; otherwise points cx->conj_bound at the bound the
 * conjugate recorded for the same condition, if the record is still in step. */
static void conj_step(ctx_t *cx, const arb_t r)
{
    conj_log *log = cx->conj;
    cx->conj_bound = NULL;
    if (log == NULL) return;
    cond_tag tag = {cx->section, cx->rat_k, cx->rat_g, {cx->cond_id[0], cx->cond_id[1], cx->cond_id[2]}};
    if (cx->conj_recording) {
        if (log->n == log->alloc) {
            slong alloc = log->alloc ? 2 * log->alloc : 256;
            log->tag = flint_realloc(log->tag, sizeof(cond_tag) * (size_t)alloc);
            log->bound = flint_realloc(log->bound, sizeof(mag_struct) * (size_t)alloc);
            for (slong k = log->alloc; k < alloc; k++) mag_init(log->bound + k);
            log->alloc = alloc;
        }
        log->tag[log->n] = tag;
        arb_get_mag(log->bound + log->n, r);   /* inf when r is not finite */
        log->n++;
        return;
    }
    if (log->in_step && log->pos < log->n && cond_tag_eq(&tag, log->tag + log->pos))
        cx->conj_bound = log->bound + log->pos;
    else log->in_step = 0;
    log->pos++;
}

/* Tableau in Q(sqrt d), d > 1: v D^k g = m + n sqrt(d) with integers m, n
 * (D the common denominator of the a and b of the entries a + b sqrt(d)), and
 * the same condition on the conjugate tableau has v' D^k g = m - n sqrt(d).
 * So m^2 - d n^2 = v v' (D^k g)^2 is an integer; below 1 in absolute value it
 * is 0, and as d is not a square, m = n = 0: v = 0.  Upper bounds only. */
static int quadratic_zero(const ctx_t *cx, const arb_t r)
{
    if (cx->conj_bound == NULL || mag_is_inf(cx->conj_bound)) return 0;
    mag_t m, t;
    mag_init(m);
    mag_init(t);
    arb_get_mag(m, r);
    mag_mul(m, m, cx->conj_bound);
    mag_set_fmpz(t, cx->ex->den);
    mag_pow_ui(t, t, 2 * (ulong)cx->rat_k);
    mag_mul(m, m, t);
    mag_set_ui(t, cx->rat_g);
    mag_mul(t, t, t);
    mag_mul(m, m, t);
    int zero = mag_cmp_2exp_si(m, 0) < 0;
    mag_clear(m);
    mag_clear(t);
    return zero;
}

/* 1 if r is certainly 0.  Rational entries with common denominator D: r =
 * N / (D^k g) for an integer N, and |r| D^k g < 1 forces N = 0.  Entries in
 * Q(sqrt d): see quadratic_zero. */
static int proved_zero(const ctx_t *cx, const arb_t r)
{
    if (cx->ex == NULL || fmpz_is_zero(cx->ex->den) || cx->rat_k <= 0 || cx->rat_g == 0) return 0;
    if (!fmpz_is_one(cx->ex->qd)) return quadratic_zero(cx, r);
    fmpz_t m;
    arb_t u;
    arf_t ub;
    fmpz_init(m);
    arb_init(u);
    arf_init(ub);
    fmpz_pow_ui(m, cx->ex->den, (ulong)cx->rat_k);
    fmpz_mul_ui(m, m, cx->rat_g);
    arb_mul_fmpz(u, r, m, cx->prec);
    arb_get_abs_ubound_arf(ub, u, cx->prec);
    int zero = arf_cmp_si(ub, 1) < 0;
    fmpz_clear(m);
    arb_clear(u);
    arf_clear(ub);
    return zero;
}

/* |midpoint of x|, rounded up: the size of a term for the scales below (the
 * radius is left out, so that a ball much wider than its terms shows it). */
static void mid_mag(mag_t m, const arb_t x) { arf_get_mag(m, arb_midref(x)); }

/* Rounded data: a ball containing 0 holds within the precision of the data
 * only when its radius is at most 2^-VIGEN_CHECK_DATA_BITS = 2^-10 of the size
 * of the terms it compares.  A wider ball says too little: "0.5" is 0.5 +/-
 * 0.05, and with it a 2-stage tableau "satisfies" order-5 conditions that fail
 * by a few per cent (b.c^4 = 7/36, not 1/5).  Why 2^-10 (about 0.1%):
 *   - an entry with k significant digits has a relative radius of at most
 *     5 10^-k: up to 5e-3 for k = 3 (above 2^-10, so 1- to 3-digit data are
 *     not enough to decide alone), at most 5e-4 for k = 4;
 *   - a condition of order n multiplies n entries, so its relative radius is
 *     about n times theirs: for the 9- to 16-digit tables in the literature
 *     (order <= 12) that is below 1e-7, four decades under the threshold,
 *     which leaves room for cancellation among the terms;
 *   - what a hold then says is precise: the exact value of the condition is
 *     within 0.1% of its terms of 0 (the radius shown).
 * On exact entries the rule is the tighter 2^-(prec/2) below. */
static int data_ball_tight(const arb_t r, const mag_t scale)
{
    mag_t thr;
    mag_init(thr);
    mag_mul_2exp_si(thr, scale, -VIGEN_CHECK_DATA_BITS);
    int tight = mag_cmp(arb_radref(r), thr) <= 0;
    mag_clear(thr);
    return tight;
}

/* The verdict on a ball r = left side - right side (see check.h).  exact: every
 * entry the condition involves is exact; scale: an upper bound of the size of
 * its terms (exact conditions hold only with radius <= 2^-(prec/2) scale,
 * conditions on rounded data only with radius <= 2^-10 scale; *too_short: the
 * latter is undecided for that reason). */
static int verdict(const ctx_t *cx, const arb_t r, int exact, const mag_t scale, int *unconfirmed, int *proved,
                   int *too_short)
{
    *unconfirmed = 0;
    *proved = 0;
    *too_short = 0;
    if (!arb_is_finite(r)) return UNDECIDED;
    if (!arb_contains_zero(r)) return FAILS;
    if (mag_is_zero(arb_radref(r))) return HOLDS;
    if (!exact) {
        if (data_ball_tight(r, scale)) return HOLDS;
        *too_short = 1;
        return UNDECIDED;
    }
    if (proved_zero(cx, r)) {
        *proved = 1;
        return HOLDS;
    }
    mag_t thr;
    mag_init(thr);
    mag_mul_2exp_si(thr, scale, -(cx->prec / 2));
    int tight = mag_cmp(arb_radref(r), thr) <= 0;
    mag_clear(thr);
    if (!tight || cx->strict) return UNDECIDED;
    *unconfirmed = 1;
    return HOLDS;
}

/* The verdict, with the bookkeeping of the refinement loop and the report. */
static int decide(ctx_t *cx, const arb_t r, int exact, const mag_t scale)
{
    int unconfirmed, proved, too_short;
    conj_step(cx, r);
    int v = verdict(cx, r, exact, scale, &unconfirmed, &proved, &too_short);
    cx->hash = (cx->hash ^ (ulong)(v + 1)) * 1099511628211ULL;
    cx->n_unconfirmed += unconfirmed;
    cx->n_proved += proved;
    cx->last_within = v == HOLDS && !exact;
    cx->last_short = too_short;
    vigen_check_holds *h = cx->holds + cx->section;
    if (v == HOLDS) {
        if (exact) h->exact++;
        else {
            h->data++;
            mag_max(h->radius, h->radius, arb_radref(r));
        }
    } else if (v == UNDECIDED) {
        cx->n_undecided++;
        cx->n_undecided_exact += exact != 0;
        cx->n_undecided_short += too_short;
        h->too_short += too_short;
    }
    return v;
}

/* decide() with the scale |a| + |b| of a comparison a = b. */
static int decide2(ctx_t *cx, const arb_t r, int exact, const arb_t a, const arb_t b)
{
    mag_t m, t;
    mag_init(m);
    mag_init(t);
    mid_mag(m, a);
    mid_mag(t, b);
    mag_add(m, m, t);
    int v = decide(cx, r, exact, m);
    mag_clear(m);
    mag_clear(t);
    return v;
}

static int tri_of(slong fail, slong undecided)
{
    return fail ? VIGEN_CHECK_NO : undecided ? VIGEN_CHECK_UNDECIDED : VIGEN_CHECK_YES;
}

static entry canon(const ctx_t *cx, entry e)
{
    if (e.mat == M_AT && !cx->has_At) e.mat = M_A;
    if (e.mat == M_BT && !cx->has_bt) e.mat = M_B;
    if (e.mat == M_CT && !cx->has_At) e.mat = M_C;
    return e;
}

static int entry_eq(entry x, entry y) { return x.mat == y.mat && x.i == y.i && x.j == y.j; }

static int entry_exact(const ctx_t *cx, entry e)
{
    slong s = cx->s;
    switch (e.mat) {
    case M_A: return cx->ex->A[e.i * s + e.j];
    case M_AT: return cx->ex->At[e.i * s + e.j];
    case M_B: return cx->ex->b[e.i];
    case M_BT: return cx->ex->bt[e.i];
    case M_C: return cx->ex->c[e.i];
    default: return cx->ex->ct[e.i];
    }
}

/* The text of a canonical entry as the file gives it, or NULL. */
static const char *entry_text(const ctx_t *cx, entry e)
{
    const vigen_tableau *t = cx->t;
    slong s = cx->s;
    char **texts;
    slong k = e.i;
    switch (e.mat) {
    case M_A: texts = t->A_text; k = e.i * s + e.j; break;
    case M_AT: texts = t->At_text; k = e.i * s + e.j; break;
    case M_B: texts = t->b_text; break;
    case M_BT: texts = t->bt_text; break;
    case M_C: texts = t->c_text; break;
    default: texts = cx->has_ct ? t->ct_text : NULL; break;
    }
    return texts ? texts[k] : NULL;
}

/* Up to two entries replaced by other values. */
typedef struct {
    int n;
    entry e[2];                  /* canonical */
    arb_srcptr value[2];
} override;

static override ov1(entry e, arb_srcptr v)
{
    override o;
    o.n = 1;
    o.e[0] = e;
    o.value[0] = v;
    o.e[1] = e;
    o.value[1] = v;
    return o;
}

static arb_srcptr get(const ctx_t *cx, int mat, slong i, slong j, const override *ov)
{
    entry e = {mat, i, (mat == M_A || mat == M_AT) ? j : 0};
    e = canon(cx, e);
    if (ov)
        for (int k = 0; k < ov->n; k++)
            if (entry_eq(e, ov->e[k])) return ov->value[k];
    switch (e.mat) {
    case M_A: return arb_mat_entry(cx->A, i, j);
    case M_AT: return arb_mat_entry(cx->At, i, j);
    case M_B: return cx->b + i;
    case M_BT: return cx->bt + i;
    case M_C: return cx->c + i;
    default: return cx->ct + i;
    }
}

/* ----------------------------------------- row sums and symplecticity */

enum { C_ROWSUM_A, C_ROWSUM_AT, C_SUM_B, C_SUM_BT, C_BT_EQ_B, C_SYMP };

typedef struct {
    int type;
    slong i, j;
    int status;
    int too_short;               /* undecided because the rounded data are too short */
    arb_t r;                     /* left side - right side */
} cond;

static int cond_is_rowsum(const cond *c) { return c->type <= C_SUM_BT; }

static void add_cond(cond *conds, slong *n, int type, slong i, slong j)
{
    cond *c = conds + (*n)++;
    c->type = type;
    c->i = i;
    c->j = j;
    c->status = HOLDS;
    c->too_short = 0;
    arb_init(c->r);
}

/* r = value - expected of the condition, with one entry possibly overridden. */
static void cond_parts(arb_t value, arb_t expected, const ctx_t *cx, const cond *c, const override *ov)
{
    slong s = cx->s, prec = cx->prec, i = c->i, j = c->j;
    arb_zero(value);
    switch (c->type) {
    case C_ROWSUM_A:
    case C_ROWSUM_AT: {
        int m = c->type == C_ROWSUM_A ? M_A : M_AT;
        for (slong k = 0; k < s; k++) arb_add(value, value, get(cx, m, i, k, ov), prec);
        arb_set(expected, get(cx, m == M_A ? M_C : M_CT, i, 0, ov));
        break;
    }
    case C_SUM_B:
    case C_SUM_BT:
        for (slong k = 0; k < s; k++) arb_add(value, value, get(cx, c->type == C_SUM_B ? M_B : M_BT, k, 0, ov), prec);
        arb_one(expected);
        break;
    case C_BT_EQ_B:
        arb_set(value, get(cx, M_BT, i, 0, ov));
        arb_set(expected, get(cx, M_B, i, 0, ov));
        break;
    default: { /* b_i at_ij + bt_j a_ji - b_i bt_j (GNI VI.4.6; with bt = b as in MATH.md) */
        arb_srcptr bi = get(cx, M_B, i, 0, ov), bj = get(cx, M_BT, j, 0, ov);
        arb_mul(value, bi, get(cx, M_AT, i, j, ov), prec);
        arb_addmul(value, bj, get(cx, M_A, j, i, ov), prec);
        arb_submul(value, bi, bj, prec);
        arb_zero(expected);
        break;
    }
    }
}

static void cond_eval(arb_t r, const ctx_t *cx, const cond *c, const override *ov)
{
    arb_t e;
    arb_init(e);
    cond_parts(r, e, cx, c, ov);
    arb_sub(r, r, e, cx->prec);
    arb_clear(e);
}

/* An upper bound of the size of the terms of the condition (the scale of
 * its tightness test). */
static void cond_scale(mag_t m, const ctx_t *cx, const cond *c)
{
    slong s = cx->s, i = c->i, j = c->j;
    mag_t t, u;
    mag_init(t);
    mag_init(u);
    mag_zero(m);
    switch (c->type) {
    case C_ROWSUM_A:
    case C_ROWSUM_AT: {
        int mt = c->type == C_ROWSUM_A ? M_A : M_AT;
        for (slong k = 0; k < s; k++) {
            mid_mag(t, get(cx, mt, i, k, NULL));
            mag_add(m, m, t);
        }
        mid_mag(t, get(cx, mt == M_A ? M_C : M_CT, i, 0, NULL));
        mag_add(m, m, t);
        break;
    }
    case C_SUM_B:
    case C_SUM_BT:
        for (slong k = 0; k < s; k++) {
            mid_mag(t, get(cx, c->type == C_SUM_B ? M_B : M_BT, k, 0, NULL));
            mag_add(m, m, t);
        }
        mag_one(t);
        mag_add(m, m, t);
        break;
    case C_BT_EQ_B:
        mid_mag(m, get(cx, M_BT, i, 0, NULL));
        mid_mag(t, get(cx, M_B, i, 0, NULL));
        mag_add(m, m, t);
        break;
    default: {
        mag_t bi, bj;
        mag_init(bi);
        mag_init(bj);
        mid_mag(bi, get(cx, M_B, i, 0, NULL));
        mid_mag(bj, get(cx, M_BT, j, 0, NULL));
        mid_mag(t, get(cx, M_AT, i, j, NULL));
        mag_mul(m, bi, t);
        mid_mag(t, get(cx, M_A, j, i, NULL));
        mag_mul(u, bj, t);
        mag_add(m, m, u);
        mag_mul(u, bi, bj);
        mag_add(m, m, u);
        mag_clear(bi);
        mag_clear(bj);
        break;
    }
    }
    mag_clear(t);
    mag_clear(u);
}

/* The canonical entries a condition involves (at most s + 1 or 4). */
static slong cond_entries(entry *out, const ctx_t *cx, const cond *c)
{
    slong n = 0, s = cx->s;
    switch (c->type) {
    case C_ROWSUM_A:
    case C_ROWSUM_AT: {
        int m = c->type == C_ROWSUM_A ? M_A : M_AT;
        for (slong k = 0; k < s; k++) out[n++] = canon(cx, (entry){m, c->i, k});
        out[n++] = canon(cx, (entry){m == M_A ? M_C : M_CT, c->i, 0});
        break;
    }
    case C_SUM_B:
    case C_SUM_BT:
        for (slong k = 0; k < s; k++) out[n++] = canon(cx, (entry){c->type == C_SUM_B ? M_B : M_BT, k, 0});
        break;
    case C_BT_EQ_B:
        out[n++] = canon(cx, (entry){M_BT, c->i, 0});
        out[n++] = canon(cx, (entry){M_B, c->i, 0});
        break;
    default:
        out[n++] = canon(cx, (entry){M_B, c->i, 0});
        out[n++] = canon(cx, (entry){M_BT, c->j, 0});
        out[n++] = canon(cx, (entry){M_AT, c->i, c->j});
        out[n++] = canon(cx, (entry){M_A, c->j, c->i});
        break;
    }
    return n;
}

static int cond_involves(const ctx_t *cx, const cond *c, entry e)
{
    entry buf[4];
    entry *list = cond_is_rowsum(c) ? flint_malloc(sizeof(entry) * (size_t)(cx->s + 1)) : buf;
    slong n = cond_entries(list, cx, c);
    int hit = 0;
    for (slong k = 0; k < n && !hit; k++) hit = entry_eq(list[k], e);
    if (list != buf) flint_free(list);
    return hit;
}

/* Every entry the condition involves is exact. */
static int cond_exact(const ctx_t *cx, const cond *c)
{
    entry buf[4];
    entry *list = cond_is_rowsum(c) ? flint_malloc(sizeof(entry) * (size_t)(cx->s + 1)) : buf;
    slong n = cond_entries(list, cx, c);
    int all = 1;
    for (slong k = 0; k < n && all; k++) all = entry_exact(cx, list[k]);
    if (list != buf) flint_free(list);
    return all;
}

static int cond_decide(ctx_t *cx, const cond *c)
{
    mag_t m;
    mag_init(m);
    cond_scale(m, cx, c);
    ctx_shape(cx, cond_is_rowsum(c) || c->type == C_BT_EQ_B ? 1 : 2, 1, c->type, c->i, c->j);
    int v = decide(cx, c->r, cond_exact(cx, c), m);
    mag_clear(m);
    return v;
}

static const char *cond_kind_words(int type)
{
    switch (type) {
    case C_ROWSUM_A: case C_ROWSUM_AT: return "the row sum";
    case C_SUM_B: case C_SUM_BT: return "sum b = 1";
    case C_BT_EQ_B: return "bt = b";
    default: return "symplecticity";
    }
}

static arb_srcptr entry_value(const ctx_t *cx, entry e) { return get(cx, e.mat, e.i, e.j, NULL); }

/* ------------------------------------------------------------ problems */

static vigen_check_problem *problem_new(vigen_check_report *rep, int kind)
{
    if (rep->nproblems == rep->alloc_problems) {
        rep->alloc_problems = rep->alloc_problems ? 2 * rep->alloc_problems : 16;
        rep->problems = flint_realloc(rep->problems, sizeof(vigen_check_problem) * (size_t)rep->alloc_problems);
    }
    vigen_check_problem *p = rep->problems + rep->nproblems++;
    memset(p, 0, sizeof(*p));
    p->kind = kind;
    arb_init(p->value);
    arb_init(p->expected);
    return p;
}

static void problems_clear(vigen_check_report *rep)
{
    for (slong k = 0; k < rep->nproblems; k++) {
        vigen_check_problem *p = rep->problems + k;
        arb_clear(p->value);
        arb_clear(p->expected);
        free(p->value_json);
        free(p->expected_json);
        free(p->message);
    }
    flint_free(rep->problems);
    rep->problems = NULL;
    rep->nproblems = rep->alloc_problems = 0;
}

/* Digits enough to see the difference between x and y (8 .. 45). */
static slong digits_to_separate(const arb_t x, const arb_t y, slong prec)
{
    arb_t d;
    arb_init(d);
    arb_sub(d, x, y, prec);
    double dd = fabs(arf_get_d(arb_midref(d), ARF_RND_NEAR));
    double yy = fabs(arf_get_d(arb_midref(y), ARF_RND_NEAR));
    double xx = fabs(arf_get_d(arb_midref(x), ARF_RND_NEAR));
    arb_clear(d);
    double scale = yy > xx ? yy : xx;
    if (scale == 0.0 || dd == 0.0 || !isfinite(scale) || !isfinite(dd)) return 8;
    double rel = dd / scale;
    if (rel >= 1e-5) return 8;
    if (rel < 1e-40) return 45;
    slong n = (slong)ceil(-log10(rel)) + 4;
    return n > 45 ? 45 : n;
}

/* Significant digits of a decimal literal ("-0.01250e-3" has 4), 0 when it
 * is not one. */
static slong decimal_sig_digits(const char *text)
{
    slong n = 0, lead = 1;
    for (const char *c = text; *c && *c != 'e' && *c != 'E'; c++) {
        if (*c < '0' || *c > '9') continue;
        if (lead && *c == '0') continue;
        lead = 0;
        n++;
    }
    return n;
}

/* d significant digits of x, rounded down (up = 0) or up (up = 1). */
static char *arf_text(const arf_t x, slong d, int up)
{
    if (arf_is_zero(x)) return vigen_strdup("0");
    mpfr_t m;
    slong bits = arf_bits(x);
    mpfr_init2(m, bits < 2 ? 2 : bits);
    arf_get_mpfr(m, x, MPFR_RNDN);   /* exact: m has the bits of x */
    char fmt[32];
    snprintf(fmt, sizeof(fmt), "%%.%ldR%cg", (long)d, up ? 'U' : 'D');
    char *out = NULL;
    char *r;
    if (mpfr_asprintf(&out, fmt, m) >= 0) {
        r = vigen_strdup(out);
        mpfr_free_str(out);
    } else r = vigen_strdup("?");
    mpfr_clear(m);
    return r;
}

/* The interval [lo, hi] containing x, rounded outward, with enough digits to
 * show its width (3 .. digits). */
static char *interval_str(const arb_t x, slong digits)
{
    slong acc = arb_rel_accuracy_bits(x);
    slong d = acc > 0 ? (slong)(acc * 0.30103) + 2 : 3;
    if (d < 3) d = 3;
    if (d > digits && digits >= 3) d = digits;
    arf_t lo, hi;
    arf_init(lo);
    arf_init(hi);
    arb_get_lbound_arf(lo, x, 256);
    arb_get_ubound_arf(hi, x, 256);
    char *l = arf_text(lo, d, 0), *h = arf_text(hi, d, 1);
    char *r = vigen_strdup_printf("[%s, %s]", l, h);
    free(l);
    free(h);
    arf_clear(lo);
    arf_clear(hi);
    return r;
}

/* For messages: the `digits` digits of x when they are certain, otherwise the
 * interval [lo, hi] that contains x (rounded outward), so that a reader sees
 * at once whether the ball contains 0. */
static char *ball_str(const arb_t x, slong digits)
{
    if (!arb_is_finite(x)) return vigen_strdup("[not finite]");
    int narrow = arb_is_exact(x) || arb_rel_accuracy_bits(x) >= (slong)(digits * 3.33);
    if (!narrow) return interval_str(x, digits);
    char *s = arb_get_str(x, digits, ARB_STR_NO_RADIUS);
    char *r = vigen_strdup(s);
    flint_free(s);
    return r;
}

/* For JSON: arb's "[mid +/- rad]" with the midpoint always shown. */
static char *ball_json_str(const arb_t x, slong digits)
{
    int narrow = arb_is_exact(x) || arb_rel_accuracy_bits(x) >= (slong)(digits * 3.33);
    if (!narrow) {
        /* the midpoint to a few digits beyond the radius, not binary noise */
        slong acc = arb_rel_accuracy_bits(x);
        slong d = acc > 0 ? (slong)(acc * 0.30103) + 3 : 3;
        if (d < digits) digits = d;
    }
    char *s = arb_get_str(x, digits, narrow ? ARB_STR_NO_RADIUS : ARB_STR_MORE);
    char *r = vigen_strdup(s);
    flint_free(s);
    return r;
}

/* Radius (an upper bound) as a short decimal. */
static char *mag_str(const mag_t m)
{
    arf_t x;
    arf_init(x);
    arf_set_mag(x, m);
    char *r = arf_text(x, 2, 1);
    arf_clear(x);
    return r;
}

static char *entry_name(entry e)
{
    if (e.mat == M_A || e.mat == M_AT)
        return vigen_strdup_printf("%s[%ld][%ld]", matrix_names[e.mat], (long)(e.i + 1), (long)(e.j + 1));
    return vigen_strdup_printf("%s[%ld]", matrix_names[e.mat], (long)(e.i + 1));
}

/* ------------------------------------------------------- typo diagnosis */

/* Solves condition c for entry e: writes x with c(x) = 0 nearest the current
 * value (the condition is at most quadratic in one entry); 0 if it cannot. */
static int solve_for(arb_t x, const ctx_t *cx, const cond *c, entry e)
{
    slong prec = cx->prec;
    arb_t x0, r0, rp, rm, xp, alpha, beta, disc, t;
    arb_init(x0); arb_init(r0); arb_init(rp); arb_init(rm); arb_init(xp);
    arb_init(alpha); arb_init(beta); arb_init(disc); arb_init(t);
    /* the entry is the unknown: expand around its midpoint, taken as exact, so
     * that the value found carries the radii of the other entries only */
    arb_set_arf(x0, arb_midref(entry_value(cx, e)));
    override ov0 = ov1(e, x0), ov = ov1(e, xp);
    cond_eval(r0, cx, c, &ov0);
    arb_add_ui(xp, x0, 1, prec);
    cond_eval(rp, cx, c, &ov);
    arb_sub_ui(xp, x0, 1, prec);
    cond_eval(rm, cx, c, &ov);
    /* r(x0 + d) = r0 + alpha d + beta d^2 */
    arb_sub(alpha, rp, rm, prec);
    arb_mul_2exp_si(alpha, alpha, -1);
    arb_add(beta, rp, rm, prec);
    arb_mul_2exp_si(beta, beta, -1);
    arb_sub(beta, beta, r0, prec);
    int ok = 0;
    if (arb_contains_zero(beta)) {
        if (!arb_contains_zero(alpha)) {
            arb_div(t, r0, alpha, prec);
            arb_sub(x, x0, t, prec);
            ok = 1;
        }
    } else {
        /* the root nearest d = 0: d = -2 r0 / (alpha + sign(alpha) sqrt(alpha^2 - 4 beta r0)) */
        arb_sqr(disc, alpha, prec);
        arb_mul(t, beta, r0, prec);
        arb_mul_2exp_si(t, t, 2);
        arb_sub(disc, disc, t, prec);
        if (arb_is_nonnegative(disc) && !arb_contains_zero(alpha)) {
            arb_sqrt(disc, disc, prec);
            if (arb_is_negative(alpha)) arb_neg(disc, disc);
            arb_add(t, alpha, disc, prec);
            arb_mul_2exp_si(xp, r0, 1);
            arb_div(t, xp, t, prec);
            arb_sub(x, x0, t, prec);
            ok = arb_is_finite(x);
        }
    }
    arb_clear(x0); arb_clear(r0); arb_clear(rp); arb_clear(rm); arb_clear(xp);
    arb_clear(alpha); arb_clear(beta); arb_clear(disc); arb_clear(t);
    return ok;
}

/* The tableau at the midpoints of its balls (exact values), for the typo
 * diagnosis. */
typedef struct {
    arb_mat_t A, At;
    arb_ptr b, bt, c, ct;
    ctx_t cx;
} midpoints;

static void mid_vec(arb_ptr out, arb_srcptr x, slong s)
{
    for (slong i = 0; i < s; i++) arb_set_arf(out + i, arb_midref(x + i));
}

static void midpoints_init(midpoints *m, const ctx_t *cx)
{
    slong s = cx->s;
    arb_mat_init(m->A, s, s);
    arb_mat_init(m->At, s, s);
    m->b = _arb_vec_init(s);
    m->bt = _arb_vec_init(s);
    m->c = _arb_vec_init(s);
    m->ct = _arb_vec_init(s);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            arb_set_arf(arb_mat_entry(m->A, i, j), arb_midref(arb_mat_entry(cx->A, i, j)));
            arb_set_arf(arb_mat_entry(m->At, i, j), arb_midref(arb_mat_entry(cx->At, i, j)));
        }
    mid_vec(m->b, cx->b, s);
    mid_vec(m->bt, cx->bt, s);
    mid_vec(m->c, cx->c, s);
    mid_vec(m->ct, cx->ct, s);
    m->cx = *cx;
    m->cx.A = m->A;
    m->cx.At = m->At;
    m->cx.b = m->b;
    m->cx.bt = m->bt;
    m->cx.c = m->c;
    m->cx.ct = m->ct;
}

static void midpoints_clear(midpoints *m)
{
    slong s = m->cx.s;
    arb_mat_clear(m->A);
    arb_mat_clear(m->At);
    _arb_vec_clear(m->b, s);
    _arb_vec_clear(m->bt, s);
    _arb_vec_clear(m->c, s);
    _arb_vec_clear(m->ct, s);
}

/* Encloses condition c over the balls of its entries without the dependency
 * problem of plain ball arithmetic (an entry that occurs twice varies once):
 *   r(mid) +- (sum_u |dr/du| rad_u + 2 (sum_u rad_u)^2),
 * r and its derivatives taken at the midpoints of every entry u.  This is a
 * rigorous enclosure for these conditions, which are polynomials of degree <= 2
 * in the entries with coefficients of size 1 (the central difference gives
 * dr/du exactly, and the quadratic remainder is at most 2 (sum_u rad_u)^2).
 * When e is not NULL, entry e takes the value fix instead (midpoint f,
 * radius rad(fix)). */
static void cond_enclose(arb_t out, const ctx_t *cx, const ctx_t *mx, const cond *c, const entry *e,
                         const arb_t fix)
{
    slong prec = cx->prec;
    arb_t f, up, dn, u;
    arb_init(f);
    arb_init(up);
    arb_init(dn);
    arb_init(u);
    override ov = {0, {{0, 0, 0}, {0, 0, 0}}, {NULL, NULL}};
    if (e) {
        arb_set_arf(f, arb_midref(fix));
        ov = ov1(*e, f);
    }
    cond_eval(out, mx, c, &ov);
    entry buf[4];
    entry *list = cond_is_rowsum(c) ? flint_malloc(sizeof(entry) * (size_t)(cx->s + 1)) : buf;
    slong n = cond_entries(list, cx, c);
    mag_t tol, sum, g, rad;
    mag_init(tol);
    mag_init(sum);
    mag_init(g);
    mag_init(rad);
    for (slong k = 0; k < n; k++) {
        int dup = 0;
        for (slong q = 0; q < k; q++) dup |= entry_eq(list[q], list[k]);
        if (dup) continue;
        int is_e = e && entry_eq(list[k], *e);
        mag_set(rad, arb_radref(is_e ? fix : entry_value(cx, list[k])));
        if (mag_is_zero(rad)) continue;
        /* dr/du by a central difference (exact: r is at most quadratic in u) */
        override o2 = ov;
        int slot = is_e ? 0 : o2.n;
        o2.e[slot] = list[k];
        if (!is_e) o2.n++;
        arb_srcptr base = is_e ? f : get(mx, list[k].mat, list[k].i, list[k].j, NULL);
        arb_add_ui(u, base, 1, prec);
        o2.value[slot] = u;
        cond_eval(up, mx, c, &o2);
        arb_sub_ui(u, base, 1, prec);
        o2.value[slot] = u;
        cond_eval(dn, mx, c, &o2);
        arb_sub(up, up, dn, prec);
        arb_mul_2exp_si(up, up, -1);
        arb_get_mag(g, up);
        mag_mul(g, g, rad);
        mag_add(tol, tol, g);
        mag_add(sum, sum, rad);
    }
    mag_mul(sum, sum, sum);
    mag_mul_2exp_si(sum, sum, 1);
    mag_add(tol, tol, sum);
    arb_add_error_mag(out, tol);
    if (list != buf) flint_free(list);
    mag_clear(tol);
    mag_clear(sum);
    mag_clear(g);
    mag_clear(rad);
    arb_clear(f);
    arb_clear(up);
    arb_clear(dn);
    arb_clear(u);
}

/* Is condition c consistent with the data once entry e is given the value
 * fix (midpoint f, radius rho)?  Its enclosure over the data's balls (with e
 * in [f - rho, f + rho]) must contain 0. */
static int consistent_with_data(const ctx_t *cx, const ctx_t *mx, const cond *c, entry e, const arb_t fix)
{
    arb_t r;
    arb_init(r);
    cond_enclose(r, cx, mx, c, &e, fix);
    int ok = arb_is_finite(r) && arb_contains_zero(r);
    arb_clear(r);
    return ok;
}

/* Among the conditions with in_scope[k], the failed ones all involve exactly
 * one entry whose change can satisfy every in-scope condition involving it?
 * Returns 1 with *culprit and fix when that entry is unique.  The value asked
 * for is solved with the entry as an exact unknown around its midpoint (its
 * radius comes from the other entries only), and the candidate must make every
 * in-scope condition involving it consistent with the data (see
 * consistent_with_data). */
static int diagnose(entry *culprit, arb_t fix, ctx_t *cx, const ctx_t *mx, cond *conds, slong n,
                    const int *in_scope)
{
    slong first = -1;
    for (slong k = 0; k < n; k++)
        if (in_scope[k] && conds[k].status == FAILS) { first = k; break; }
    if (first < 0) return 0;
    entry *cand = flint_malloc(sizeof(entry) * (size_t)(cx->s + 4));   /* s + 1 or 4 entries */
    slong ncand = cond_entries(cand, cx, conds + first);
    /* deduplicate and intersect with every other failed condition */
    slong m = 0;
    for (slong a = 0; a < ncand; a++) {
        int dup = 0;
        for (slong q = 0; q < m; q++) dup |= entry_eq(cand[q], cand[a]);
        if (dup) continue;
        int all = 1;
        for (slong k = first + 1; k < n && all; k++)
            if (in_scope[k] && conds[k].status == FAILS) all = cond_involves(cx, conds + k, cand[a]);
        if (all) cand[m++] = cand[a];
    }
    int found = 0;
    arb_t x;
    arb_init(x);
    for (slong a = 0; a < m; a++) {
        /* the value asked by the first failed condition that can be solved */
        int solved = 0;
        for (slong k = first; k < n && !solved; k++)
            if (in_scope[k] && conds[k].status == FAILS) solved = solve_for(x, cx, conds + k, cand[a]);
        if (!solved) continue;
        /* every in-scope condition involving the entry must then hold */
        int ok = 1;
        for (slong k = 0; k < n && ok; k++) {
            if (!in_scope[k] || !cond_involves(cx, conds + k, cand[a])) continue;
            ok = consistent_with_data(cx, mx, conds + k, cand[a], x);
        }
        if (!ok) continue;
        found++;
        if (found == 1) {
            *culprit = cand[a];
            arb_set(fix, x);
        }
    }
    arb_clear(x);
    flint_free(cand);
    return found == 1;
}

/* Builds the conditions, decides them, diagnoses, and files the problems. */
static void check_rows_and_symplecticity(vigen_check_report *rep, ctx_t *cx, int claim_symplectic)
{
    slong s = cx->s, n = 0;
    slong cap = 2 + 3 * s + s * s;
    cond *conds = flint_malloc(sizeof(cond) * (size_t)cap);
    for (slong i = 0; i < s; i++) add_cond(conds, &n, C_ROWSUM_A, i, 0);
    if (cx->has_ct)
        for (slong i = 0; i < s; i++) add_cond(conds, &n, C_ROWSUM_AT, i, 0);
    add_cond(conds, &n, C_SUM_B, 0, 0);
    if (cx->has_bt) add_cond(conds, &n, C_SUM_BT, 0, 0);
    if (cx->has_bt)
        for (slong i = 0; i < s; i++) add_cond(conds, &n, C_BT_EQ_B, i, 0);
    /* with At = A the pair (i, j) and the pair (j, i) are one condition */
    for (slong i = 0; i < s; i++)
        for (slong j = cx->has_At ? 0 : i; j < s; j++) add_cond(conds, &n, C_SYMP, i, j);

    rep->row_fail = rep->row_undecided = rep->row_total = 0;
    rep->sym_fail = rep->sym_undecided = rep->sym_total = 0;
    /* the tableau at its midpoints: for the enclosures of conditions on
     * rounded entries and for the typo diagnosis */
    midpoints mid;
    midpoints_init(&mid, cx);
    const ctx_t *mx = &mid.cx;
    arb_t lin;
    arb_init(lin);
    for (slong k = 0; k < n; k++) {
        cond_eval(conds[k].r, cx, conds + k, NULL);
        if (!cond_exact(cx, conds + k)) {
            /* an entry that occurs twice (b_i in b_i a_ii + b_i a_ii - b_i b_i)
             * varies once: intersect with the second-order enclosure */
            cond_enclose(lin, cx, mx, conds + k, NULL, NULL);
            if (arb_is_finite(lin) && arb_is_finite(conds[k].r)) arb_intersection(conds[k].r, conds[k].r, lin, cx->prec);
        }
        cx->section = cond_is_rowsum(conds + k) ? VIGEN_CHECK_SECT_ROWSUM : VIGEN_CHECK_SECT_SYMPLECTIC;
        conds[k].status = cond_decide(cx, conds + k);
        conds[k].too_short = cx->last_short;
        slong *fail = cond_is_rowsum(conds + k) ? &rep->row_fail : &rep->sym_fail;
        slong *und = cond_is_rowsum(conds + k) ? &rep->row_undecided : &rep->sym_undecided;
        slong *tot = cond_is_rowsum(conds + k) ? &rep->row_total : &rep->sym_total;
        (*tot)++;
        if (conds[k].status == FAILS) (*fail)++;
        if (conds[k].status == UNDECIDED) (*und)++;
    }
    rep->consistent = tri_of(rep->row_fail, rep->row_undecided);
    rep->symplectic = tri_of(rep->sym_fail, rep->sym_undecided);
    rep->consistent_within_data = rep->consistent == VIGEN_CHECK_YES && rep->holds[VIGEN_CHECK_SECT_ROWSUM].data > 0;
    slong pair_fail = 0, pair_undecided = 0;
    for (slong k = 0; k < n; k++)
        if (conds[k].type == C_SYMP) {
            pair_fail += conds[k].status == FAILS;
            pair_undecided += conds[k].status == UNDECIDED;
        }
    rep->symplectic_separable = tri_of(pair_fail, pair_undecided);
    rep->symplectic_within_data = (rep->symplectic == VIGEN_CHECK_YES || rep->symplectic_separable == VIGEN_CHECK_YES) &&
                                  rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].data > 0;

    /* Diagnosis: over everything; then without bt = b (a splitting method
     * written as a PRK pair has bt != b by design); then over the row sums
     * alone (a method that is not symplectic says nothing about its typos). */
    int *scope = flint_malloc(sizeof(int) * (size_t)n);
    entry culprit = {0, 0, 0};
    arb_t fix;
    arb_init(fix);
    int diagnosed = 0;
    if (rep->row_fail + rep->sym_fail > 0) {
        for (slong k = 0; k < n; k++) scope[k] = 1;
        diagnosed = diagnose(&culprit, fix, cx, mx, conds, n, scope);
        if (!diagnosed && cx->has_bt) {
            for (slong k = 0; k < n; k++) scope[k] = conds[k].type != C_BT_EQ_B;
            diagnosed = diagnose(&culprit, fix, cx, mx, conds, n, scope);
        }
        if (!diagnosed && rep->row_fail > 0) {
            for (slong k = 0; k < n; k++) scope[k] = cond_is_rowsum(conds + k);
            diagnosed = diagnose(&culprit, fix, cx, mx, conds, n, scope);
        }
    }
    /* every failed or undecided pair is a problem; bt != b is one when the
     * file claims symplecticity and the claim fails (a splitting method
     * written as a PRK pair has bt != b by design) */
    int list_bt = claim_symplectic == 1 && rep->symplectic != VIGEN_CHECK_YES &&
                  rep->symplectic_separable != VIGEN_CHECK_YES;

    if (diagnosed) {
        /* one problem per kind of failed condition, each naming the entry */
        char *name = entry_name(culprit);
        int kinds_seen[2] = {0, 0};
        vigen_strbuf words;
        vigen_strbuf_init(&words);
        int nwords = 0;
        const char *seen_words[4] = {0};
        for (slong k = 0; k < n; k++) {
            if (!scope[k] || conds[k].status != FAILS) continue;
            const char *w = cond_kind_words(conds[k].type);
            int dup = 0;
            for (int q = 0; q < nwords; q++) dup |= strcmp(seen_words[q], w) == 0;
            if (!dup && nwords < 4) seen_words[nwords++] = w;
        }
        for (int q = 0; q < nwords; q++) {
            if (q > 0) vigen_strbuf_append(&words, q + 1 == nwords ? " and " : ", ");
            vigen_strbuf_append(&words, seen_words[q]);
        }
        slong digits = digits_to_separate(entry_value(cx, culprit), fix, cx->prec);
        const char *text = entry_text(cx, culprit);
        if (text && vigen_decimal_is_rounded(text)) {
            /* the repair as many digits long as the entry, where the data certify them */
            slong want = decimal_sig_digits(text), can = (slong)(arb_rel_accuracy_bits(fix) * 0.30103);
            if (want > can) want = can;
            if (want > digits) digits = want;
        }
        /* a rounded decimal is shown as the file gives it */
        char *v = text && vigen_decimal_is_rounded(text) ? vigen_strdup(text) : ball_str(entry_value(cx, culprit), digits);
        char *f = ball_str(fix, digits);
        for (slong k = 0; k < n; k++) {
            if (!scope[k] || conds[k].status != FAILS) continue;
            int kind = cond_is_rowsum(conds + k) ? VIGEN_PROBLEM_ROWSUM : VIGEN_PROBLEM_SYMPLECTIC;
            if (kinds_seen[kind]) continue;
            kinds_seen[kind] = 1;
            vigen_check_problem *p = problem_new(rep, kind);
            p->matrix = matrix_names[culprit.mat];
            p->row = culprit.i + 1;
            p->col = (culprit.mat == M_A || culprit.mat == M_AT) ? culprit.j + 1 : 0;
            p->diagnosed = 1;
            p->has_value = p->has_expected = 1;
            arb_set(p->value, entry_value(cx, culprit));
            arb_set(p->expected, fix);
            p->message = vigen_strdup_printf("%s = %s; %s %s for %s", name, v, words.data,
                                             nwords > 1 ? (nwords > 2 ? "all ask" : "both ask") : "asks", f);
        }
        free(v);
        free(f);
        free(name);
        vigen_strbuf_clear(&words);
    }

    for (slong k = 0; k < n; k++) {
        cond *c = conds + k;
        if (c->status == HOLDS) continue;
        int rowsum = cond_is_rowsum(c);
        if (c->type == C_BT_EQ_B && !list_bt) continue;
        vigen_check_problem *p = problem_new(rep, rowsum ? VIGEN_PROBLEM_ROWSUM : VIGEN_PROBLEM_SYMPLECTIC);
        p->undecided = c->status == UNDECIDED;
        p->has_value = p->has_expected = 1;
        cond_parts(p->value, p->expected, cx, c, NULL);
        if (c->type == C_SYMP) arb_set(p->value, c->r);   /* the enclosure decided on (expected 0) */
        slong digits = digits_to_separate(p->value, p->expected, cx->prec);
        char *v = ball_str(p->value, digits), *e = ball_str(p->expected, digits);
        char *d = ball_str(c->r, 6);
        const char *verdict = !p->undecided ? ""
                              : c->too_short ? "undecided, the data are too short to decide: "
                                             : "undecided at this precision: ";
        /* "defect 0.0100" or "defect in [0.00500, 0.0150]": the reader sees whether it excludes 0 */
        const char *in = d[0] == '[' ? "in " : "";
        switch (c->type) {
        case C_ROWSUM_A:
        case C_ROWSUM_AT:
            p->matrix = c->type == C_ROWSUM_A ? "A" : "At";
            p->row = c->i + 1;
            p->message = vigen_strdup_printf("%srow %ld of %s sums to %s%s but %s[%ld] = %s (defect %s%s)", verdict,
                                             (long)p->row, p->matrix, v[0] == '[' ? "a value in " : "", v,
                                             c->type == C_ROWSUM_A ? "c" : "ct", (long)p->row, e, in, d);
            break;
        case C_SUM_B:
        case C_SUM_BT:
            p->matrix = c->type == C_SUM_B ? "b" : "bt";
            p->message = vigen_strdup_printf("%ssum of %s is %s%s, not 1 (defect %s%s)", verdict, p->matrix,
                                             v[0] == '[' ? "in " : "", v, in, d);
            break;
        case C_BT_EQ_B:
            p->matrix = "bt";
            p->row = c->i + 1;
            p->message = vigen_strdup_printf("%sbt[%ld] = %s but b[%ld] = %s", verdict, (long)p->row, v,
                                             (long)p->row, e);
            break;
        default:
            p->matrix = cx->has_At ? "At" : "A";
            p->row = c->i + 1;
            p->col = c->j + 1;
            p->message = vigen_strdup_printf("%spair (%ld, %ld): b_i %s_ij + %s_j a_ji - b_i %s_j %s %s%s", verdict,
                                             (long)p->row, (long)p->col, cx->has_At ? "at" : "a",
                                             cx->has_bt ? "bt" : "b", cx->has_bt ? "bt" : "b",
                                             d[0] == '[' ? "is in" : "=", d, p->undecided ? "" : ", not 0");
            break;
        }
        free(v);
        free(e);
        free(d);
    }

    arb_clear(fix);
    arb_clear(lin);
    midpoints_clear(&mid);
    flint_free(scope);
    for (slong k = 0; k < n; k++) arb_clear(conds[k].r);
    flint_free(conds);
}

/* ------------------------------------------------------ order conditions */

static void orders_reset(vigen_check_orders *o)
{
    free(o->fail_tree);
    free(o->undecided_tree);
    o->fail_tree = o->undecided_tree = NULL;
    o->fail_order = o->undecided_order = 0;
    o->evaluated_to = 0;
    memset(&o->level, 0, sizeof(o->level));
    memset(o->count, 0, sizeof(o->count));
    memset(o->hold, 0, sizeof(o->hold));
    memset(o->fail, 0, sizeof(o->fail));
    memset(o->undecided, 0, sizeof(o->undecided));
    memset(o->hold_data, 0, sizeof(o->hold_data));
    memset(o->undecided_short, 0, sizeof(o->undecided_short));
}

/* data: for a hold, it holds within the precision of the data; for an
 * undecided condition, the data are too short to decide it. */
static void orders_record(vigen_check_orders *o, int n, int status, int data, const vigen_treeset *ts, int colour,
                          const slong *ids, int k, const arb_t value, const arb_t expected)
{
    o->count[n]++;
    if (status == HOLDS) {
        o->hold[n]++;
        o->hold_data[n] += data != 0;
        return;
    }
    vigen_strbuf sb;
    if (status == FAILS) {
        o->fail[n]++;
        if (o->fail_order) return;
        o->fail_order = n;
        vigen_strbuf_init(&sb);
        vigen_forest_tree_append(&sb, ts, colour, ids, k);
        o->fail_tree = sb.data;
        arb_set(o->fail_value, value);
        arb_set(o->fail_expected, expected);
    } else {
        o->undecided[n]++;
        o->undecided_short[n] += data != 0;
        if (o->undecided_order) return;
        o->undecided_order = n;
        vigen_strbuf_init(&sb);
        vigen_forest_tree_append(&sb, ts, colour, ids, k);
        o->undecided_tree = sb.data;
        arb_set(o->undecided_value, value);
        arb_set(o->undecided_expected, expected);
    }
}

static void orders_finish(vigen_check_orders *o, int P)
{
    int bad = 0;
    if (o->fail_order) bad = o->fail_order;
    if (o->undecided_order && (!bad || o->undecided_order < bad)) bad = o->undecided_order;
    if (!bad) {
        o->level.value = P;
        o->level.capped = 1;
        o->level.undecided = 0;
    } else {
        o->level.value = bad - 1;
        o->level.capped = 0;
        o->level.undecided = o->fail_order != bad;
    }
    /* the level rests on every condition up to it */
    o->level.within_data = 0;
    for (int n = 1; n <= o->level.value && n <= VIGEN_TREE_MAX_ORDER; n++) o->level.within_data |= o->hold_data[n] > 0;
    o->level.too_short = o->level.undecided && o->undecided[bad] > 0 && o->undecided_short[bad] == o->undecided[bad];
}

/* Every order condition of order 1..P.  Phi(F) of a forest F is the
 * componentwise product over its trees u of w(u) = M_u Phi(u) (M = A for a
 * black u, At for a white one); the condition of (colour, F) is
 * bhat . Phi(F) = 1/gamma.  w is stored for trees of order <= P - 2 (the
 * children of every tree of order <= P); for a tree u of order P - 1, which
 * occurs only as the single child of a tree of order P, the condition is
 * y . Phi(u) with the precomputed row vector y = bhat^T M_u. */
static int check_orders(vigen_check_report *rep, ctx_t *cx, int P, vigen_error *err)
{
    vigen_treeset ts;
    int rc = vigen_treeset_init(&ts, P - 1, err);
    if (rc != VIGEN_OK) return rc;
    slong s = cx->s, prec = cx->prec;
    const arb_mat_struct *M[2] = {cx->A, cx->At};
    arb_srcptr bh[2] = {cx->b, cx->bt};
    slong nstore = P >= 3 ? ts.start[P - 1] : 0;
    arb_ptr W = _arb_vec_init((nstore > 0 ? nstore : 1) * s);
    arb_ptr prod = _arb_vec_init(P * s);
    arb_ptr ones = _arb_vec_init(s);
    arb_ptr y = _arb_vec_init(4 * s);
    arb_ptr phi = _arb_vec_init(s);
    arb_t v, r, inv;
    arb_init(v);
    arb_init(r);
    arb_init(inv);
    for (slong i = 0; i < s; i++) arb_one(ones + i);
    for (int c = 0; c < 2; c++)
        for (int col = 0; col < 2; col++)
            for (slong j = 0; j < s; j++) {
                arb_ptr yj = y + (2 * c + col) * s + j;
                arb_zero(yj);
                for (slong i = 0; i < s; i++) arb_addmul(yj, bh[c] + i, arb_mat_entry(M[col], i, j), prec);
            }

    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) orders_reset(&rep->orders[f]);
    cx->section = VIGEN_CHECK_SECT_ORDER;

    for (int n = 1; n <= P; n++) {
        vigen_forest_iter it;
        vigen_forest_iter_init(&it, &ts, n - 1);
        while (vigen_forest_iter_next(&it)) {
            int k = it.k;
            const slong *ids = it.ids;
            arb_t val[2];
            arb_init(val[0]);
            arb_init(val[1]);
            if (k == 1 && ts.trees[ids[0]].order > P - 2) {
                slong u = ids[0];
                const vigen_tree *tu = ts.trees + u;
                const slong *ch = vigen_treeset_children(&ts, u);
                _arb_vec_set(phi, ones, s);
                for (int q = 0; q < tu->nchildren; q++)
                    for (slong i = 0; i < s; i++) arb_mul(phi + i, phi + i, W + ch[q] * s + i, prec);
                for (int c = 0; c < 2; c++)
                    arb_dot(val[c], NULL, 0, y + (2 * c + tu->colour) * s, 1, phi, 1, s, prec);
            } else {
                for (int d = it.changed; d < k; d++) {
                    arb_srcptr wd = W + ids[d] * s;
                    if (d == 0) _arb_vec_set(prod, wd, s);
                    else
                        for (slong i = 0; i < s; i++) arb_mul(prod + d * s + i, prod + (d - 1) * s + i, wd + i, prec);
                }
                arb_srcptr ph = k ? prod + (k - 1) * s : ones;
                for (int c = 0; c < 2; c++) arb_dot(val[c], NULL, 0, bh[c], 1, ph, 1, s, prec);
                if (n <= P - 2)
                    for (int c = 0; c < 2; c++) {
                        slong id = ts.start[n] + 2 * it.index + c;
                        for (slong i = 0; i < s; i++)
                            arb_dot(W + id * s + i, NULL, 0, arb_mat_entry(M[c], i, 0), 1, ph, 1, s, prec);
                    }
            }
            ulong gamma = vigen_forest_tree_gamma(&ts, ids, k);
            arb_one(inv);
            arb_div_ui(inv, inv, gamma, prec);
            for (int c = 0; c < 2; c++) {
                arb_sub(r, val[c], inv, prec);
                int flags = vigen_forest_tree_flags(&ts, c, ids, k);
                /* a monochromatic tree involves one part only */
                int exact = (flags & VIGEN_TREE_MONO) ? cx->ex->part[c] : cx->ex->part[0] && cx->ex->part[1];
                ctx_shape(cx, n, gamma, n, it.index, c);   /* b Phi has n factors; 1/gamma */
                int st = decide2(cx, r, exact, val[c], inv);
                int data = st == HOLDS ? cx->last_within : cx->last_short;
                orders_record(&rep->orders[VIGEN_CHECK_GENERAL], n, st, data, &ts, c, ids, k, val[c], inv);
                if (flags & VIGEN_TREE_SEPARABLE)
                    orders_record(&rep->orders[VIGEN_CHECK_SEPARABLE], n, st, data, &ts, c, ids, k, val[c], inv);
                if (flags & VIGEN_TREE_MONO)
                    orders_record(&rep->orders[c == VIGEN_TREE_BLACK ? VIGEN_CHECK_A_ALONE : VIGEN_CHECK_AT_ALONE],
                                  n, st, data, &ts, c, ids, k, val[c], inv);
            }
            arb_clear(val[0]);
            arb_clear(val[1]);
        }
        vigen_forest_iter_clear(&it);
        int all_failed = 1;
        for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
            rep->orders[f].evaluated_to = n;
            all_failed &= rep->orders[f].fail_order != 0;
        }
        if (all_failed) break;   /* nothing above can change any order */
    }
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) orders_finish(&rep->orders[f], P);

    arb_clear(v);
    arb_clear(r);
    arb_clear(inv);
    _arb_vec_clear(W, (nstore > 0 ? nstore : 1) * s);
    _arb_vec_clear(prod, P * s);
    _arb_vec_clear(ones, s);
    _arb_vec_clear(y, 4 * s);
    _arb_vec_clear(phi, s);
    vigen_treeset_clear(&ts);
    return VIGEN_OK;
}

/* ------------------------------------------------ simplifying assumptions */

typedef struct {
    ctx_t *cx;
    const arb_mat_struct *A;
    arb_srcptr b, c;
    arb_ptr cp;                  /* cp[k*s + i] = c_i^k, k = 0..cap */
    int exact;                   /* every entry of (c, A, b) of the part is exact (D) */
    int exact_B;                 /* ... of (c, b) (B) */
    int exact_C;                 /* ... of (c, A) (C) */
    int part;                    /* 0: (c, A, b), 1: (ct, At, bt) */
} part_t;

static int worst_status(int a, int b)
{
    if (a == FAILS || b == FAILS) return FAILS;
    if (a == UNDECIDED || b == UNDECIDED) return UNDECIDED;
    return HOLDS;
}

/* m += |x| |y| |z| (z may be NULL) */
static void mag_addmul3(mag_t m, const arb_t x, const arb_t y, const arb_t z)
{
    mag_t t, u;
    mag_init(t);
    mag_init(u);
    mid_mag(t, x);
    mid_mag(u, y);
    mag_mul(t, t, u);
    if (z) {
        mid_mag(u, z);
        mag_mul(t, t, u);
    }
    mag_add(m, m, t);
    mag_clear(t);
    mag_clear(u);
}

static void mag_add_arb(mag_t m, const arb_t x)
{
    mag_t t;
    mag_init(t);
    mid_mag(t, x);
    mag_add(m, m, t);
    mag_clear(t);
}

/* B(k): sum_i b_i c_i^(k-1) = 1/k */
static int assumption_B(part_t *p, int k)
{
    slong s = p->cx->s, prec = p->cx->prec;
    arb_t r, q;
    mag_t m;
    arb_init(r);
    arb_init(q);
    mag_init(m);
    arb_dot(r, NULL, 0, p->b, 1, p->cp + (k - 1) * s, 1, s, prec);
    arb_one(q);
    arb_div_ui(q, q, (ulong)k, prec);
    arb_sub(r, r, q, prec);
    for (slong i = 0; i < s; i++) mag_addmul3(m, p->b + i, p->cp + (k - 1) * s + i, NULL);
    mag_add_arb(m, q);
    ctx_shape(p->cx, k, (ulong)k, 3 * p->part, k, 0);
    int st = decide(p->cx, r, p->exact_B, m);
    arb_clear(r);
    arb_clear(q);
    mag_clear(m);
    return st;
}

/* C(k): sum_j a_ij c_j^(k-1) = c_i^k / k for every i */
static int assumption_C(part_t *p, int k)
{
    slong s = p->cx->s, prec = p->cx->prec;
    int st = HOLDS;
    arb_t r, q;
    mag_t m;
    arb_init(r);
    arb_init(q);
    mag_init(m);
    for (slong i = 0; i < s; i++) {
        arb_dot(r, NULL, 0, arb_mat_entry(p->A, i, 0), 1, p->cp + (k - 1) * s, 1, s, prec);
        arb_div_ui(q, p->cp + k * s + i, (ulong)k, prec);
        arb_sub(r, r, q, prec);
        mag_zero(m);
        for (slong j = 0; j < s; j++) mag_addmul3(m, arb_mat_entry(p->A, i, j), p->cp + (k - 1) * s + j, NULL);
        mag_add_arb(m, q);
        ctx_shape(p->cx, k, (ulong)k, 3 * p->part + 1, k, i);
        st = worst_status(st, decide(p->cx, r, p->exact_C, m));
    }
    arb_clear(r);
    arb_clear(q);
    mag_clear(m);
    return st;
}

/* D(k): sum_i b_i c_i^(k-1) a_ij = b_j (1 - c_j^k) / k for every j */
static int assumption_D(part_t *p, int k)
{
    slong s = p->cx->s, prec = p->cx->prec;
    int st = HOLDS;
    arb_t r, q, u;
    mag_t m;
    arb_init(r);
    arb_init(q);
    arb_init(u);
    mag_init(m);
    for (slong j = 0; j < s; j++) {
        arb_zero(r);
        mag_zero(m);
        for (slong i = 0; i < s; i++) {
            arb_mul(u, p->b + i, p->cp + (k - 1) * s + i, prec);
            arb_addmul(r, u, arb_mat_entry(p->A, i, j), prec);
            mag_addmul3(m, p->b + i, p->cp + (k - 1) * s + i, arb_mat_entry(p->A, i, j));
        }
        /* b_j (1 + |c_j|^k) / k bounds the right side's terms */
        arb_sub_ui(q, p->cp + k * s + j, 1, prec);
        arb_neg(q, q);
        arb_mul(q, q, p->b + j, prec);
        arb_div_ui(q, q, (ulong)k, prec);
        arb_sub(r, r, q, prec);
        arb_abs(u, p->cp + k * s + j);
        arb_add_ui(u, u, 1, prec);
        arb_mul(u, u, p->b + j, prec);
        arb_div_ui(u, u, (ulong)k, prec);
        mag_add_arb(m, u);
        ctx_shape(p->cx, k + 1, (ulong)k, 3 * p->part + 2, k, j);   /* b_j/k has fewer factors: D^1 | D^(k+1) */
        st = worst_status(st, decide(p->cx, r, p->exact, m));
    }
    arb_clear(r);
    arb_clear(q);
    arb_clear(u);
    mag_clear(m);
    return st;
}

/* Bits 0 .. k-1 of a mask of levels (bit k-1 is level k). */
static unsigned long long levels_upto(int k)
{
    return k >= 64 ? ~0ULL : k <= 0 ? 0ULL : (1ULL << k) - 1;
}

/* The level of one assumption; *data: bit k-1 set when level k holds with
 * some condition within the precision of the data (cap <= 64). */
static vigen_check_level level_of(part_t *p, int (*fn)(part_t *, int), int cap, unsigned long long *data)
{
    vigen_check_level L = {cap, 1, 0, 0, 0};
    const vigen_check_holds *h = p->cx->holds + p->cx->section;
    *data = 0;
    for (int k = 1; k <= cap; k++) {
        slong d0 = h->data, u0 = p->cx->n_undecided, s0 = p->cx->n_undecided_short;
        int st = fn(p, k);
        if (st == HOLDS) {
            if (h->data > d0) *data |= 1ULL << (k - 1);
            continue;
        }
        L.value = k - 1;
        L.capped = 0;
        L.undecided = st == UNDECIDED;
        slong u = p->cx->n_undecided - u0, sh = p->cx->n_undecided_short - s0;
        L.too_short = L.undecided && u > 0 && sh == u;
        break;
    }
    L.within_data = (*data & levels_upto(L.value)) != 0;
    return L;
}

static void check_simplifying(vigen_check_report *rep, ctx_t *cx)
{
    slong s = cx->s;
    int cap = (int)(2 * s + 1);
    if (cap < rep->max_order) cap = rep->max_order;
    if (cap > 64) cap = 64;
    rep->simplifying_cap = cap;
    cx->section = VIGEN_CHECK_SECT_SIMPLIFYING;
    for (int part = 0; part < 2; part++) {
        part_t p;
        p.cx = cx;
        p.part = part;
        p.exact = cx->ex->part_c[part];
        /* B(k) involves (c, b) only and C(k) (c, A) only: exact when those are */
        {
            const exactness *x = cx->ex;
            const unsigned char *M = part ? x->At : x->A, *w = part ? x->bt : x->b, *cc = part ? x->ct : x->c;
            int ec = 1, eb = 1, eA = 1;
            for (slong i = 0; i < s; i++) {
                ec &= cc[i];
                eb &= w[i];
            }
            for (slong k = 0; k < s * s; k++) eA &= M[k];
            p.exact_B = ec && eb;
            p.exact_C = ec && eA;
        }
        p.A = part ? cx->At : cx->A;
        p.b = part ? cx->bt : cx->b;
        p.c = part ? cx->ct : cx->c;
        p.cp = _arb_vec_init((cap + 1) * s);
        for (slong i = 0; i < s; i++) arb_one(p.cp + i);
        for (int k = 1; k <= cap; k++)
            for (slong i = 0; i < s; i++) arb_mul(p.cp + k * s + i, p.cp + (k - 1) * s + i, p.c + i, cx->prec);
        unsigned long long dB, dC, dD;
        rep->B[part] = level_of(&p, assumption_B, cap, &dB);
        rep->C[part] = level_of(&p, assumption_C, cap, &dC);
        rep->D[part] = level_of(&p, assumption_D, cap, &dD);
        /* stage order: C(q) and B(q) */
        vigen_check_level B = rep->B[part], C = rep->C[part], S;
        S.value = B.value < C.value ? B.value : C.value;
        S.capped = B.capped && C.capped;
        int fails_next = (B.value == S.value && !B.undecided && !B.capped) ||
                         (C.value == S.value && !C.undecided && !C.capped);
        S.undecided = !S.capped && !fails_next;
        S.within_data = ((dB | dC) & levels_upto(S.value)) != 0;
        /* undecided above: every assumption undecided at S.value + 1 is so for short data */
        S.too_short = S.undecided && (B.value != S.value || !B.undecided || B.too_short) &&
                      (C.value != S.value || !C.undecided || C.too_short);
        rep->stage_order[part] = S;
        _arb_vec_clear(p.cp, (cap + 1) * s);
    }
}

/* -------------------------------------------------------- claims, against */

/* What a level says about "the order is exactly p": 2 certainly, 1 possibly, 0 not. */
static int level_is(const vigen_check_level *L, int p)
{
    if (L->capped) return p >= L->value ? 1 : 0;       /* the order is >= value */
    if (L->undecided) return p == L->value ? 1 : p > L->value ? 1 : 0;   /* >= value, value + 1 undecided */
    return p == L->value ? 2 : 0;
}

/* With level_is(L, claim) = 0: is "the order is claim" certainly false?  Yes
 * when a condition of order <= claim fails (level below claim), or when every
 * condition of order claim + 1 holds exactly; not when some of these hold
 * only within the precision of the data (the exact values may fail them). */
static int order_refutes(const vigen_check_orders *o, int claim)
{
    if (o->level.value < claim) return 1;
    return claim + 1 > VIGEN_TREE_MAX_ORDER || o->hold_data[claim + 1] == 0;
}

static void check_claims(vigen_check_report *rep)
{
    if (rep->claim_order >= 0) {
        const vigen_check_orders *go = &rep->orders[VIGEN_CHECK_GENERAL], *so = &rep->orders[VIGEN_CHECK_SEPARABLE];
        const vigen_check_level *g = &go->level;
        const vigen_check_level *sp = &so->level;
        int claim = rep->claim_order, st;
        int data_above = 0;      /* undecided: order claim + 1 holds only within the data's precision */
        /* order = p means the order is p: every condition up to p holds and
         * one of order p + 1 fails (for general H, or for separable H: the
         * separable order is at least the general one) */
        int ig = level_is(g, claim), is = level_is(sp, claim);
        rep->claim_order_separable = 0;
        rep->claim_order_beyond = 0;
        rep->claim_order_within_data = 0;
        rep->claim_order_too_short = 0;
        if (ig == 2) {
            st = VIGEN_CHECK_YES;
            rep->claim_order_within_data = g->within_data;
        } else if (is == 2) {
            st = VIGEN_CHECK_YES;
            rep->claim_order_separable = 1;
            rep->claim_order_within_data = sp->within_data;
        } else if (ig || is) {
            st = VIGEN_CHECK_UNDECIDED;
            /* possible only because nothing up to max_order fails and order
             * claim + 1 is beyond what can be evaluated */
            rep->claim_order_beyond = (g->capped || sp->capped) && claim + 1 > rep->max_order &&
                                      !(g->undecided || sp->undecided);
            /* or because the conditions that decide are undecided for short data */
            rep->claim_order_too_short = !rep->claim_order_beyond && (!ig || (g->undecided && g->too_short)) &&
                                         (!is || (sp->undecided && sp->too_short)) &&
                                         ((ig && g->undecided) || (is && sp->undecided));
        } else if (!(order_refutes(go, claim) && order_refutes(so, claim))) {
            /* the order looks higher than claimed only because conditions of
             * order claim + 1 hold within the precision of rounded data: that
             * does not refute the claim (the exact values may fail them) */
            st = VIGEN_CHECK_UNDECIDED;
            data_above = 1;
        } else st = VIGEN_CHECK_NO;
        rep->claim_order_status = st;
        if (st != VIGEN_CHECK_YES) {
            vigen_check_problem *p = problem_new(rep, VIGEN_PROBLEM_CLAIM);
            p->claim = "order";
            p->undecided = st == VIGEN_CHECK_UNDECIDED;
            p->value_json = vigen_strdup_printf("%d", g->value);
            p->expected_json = vigen_strdup_printf("%d", claim);
            if (rep->claim_order_beyond)
                p->message = vigen_strdup_printf(
                    "claim order = %d: undecided: every condition up to order %d holds, and confirming that the "
                    "order is exactly %d needs the conditions of order %d (at most %d supported%s)",
                    claim, rep->max_order, claim, claim + 1, VIGEN_TREE_MAX_ORDER,
                    rep->max_order < VIGEN_TREE_MAX_ORDER ? "; --max-order 12 looks further for a lower order" : "");
            else if (data_above) {
                char *r = mag_str(rep->holds[VIGEN_CHECK_SECT_ORDER].radius);
                p->message = vigen_strdup_printf(
                    "claim order = %d: undecided: the conditions of order %d hold within the precision of the data "
                    "(radius <= %s), so the order looks higher, but their exact values may fail them",
                    claim, claim + 1, r);
                free(r);
            } else if (rep->claim_order_too_short)
                p->message = vigen_strdup_printf("claim order = %d: undecided, the data are too short to decide "
                                                 "(order >= %d; the conditions of order %d that are undecided have "
                                                 "balls containing 0 wider than 2^-%d of their terms)",
                                                 claim, g->value, g->value + 1, VIGEN_CHECK_DATA_BITS);
            else if (st == VIGEN_CHECK_UNDECIDED)
                p->message = vigen_strdup_printf("claim order = %d: undecided at this precision (order >= %d, "
                                                 "order %d undecided)", claim, g->value, g->value + 1);
            else if (g->capped)
                p->message = vigen_strdup_printf("claim order = %d is false: every condition up to order %d holds, "
                                                 "so the order is at least %d", claim, g->value, g->value);
            else if (sp->value != g->value || sp->capped != g->capped)
                p->message = vigen_strdup_printf("claim order = %d is false: the order is %d (%d%s for separable H)",
                                                 claim, g->value, sp->value, sp->capped ? " or more" : "");
            else
                p->message = vigen_strdup_printf("claim order = %d is false: the order is %d", claim, g->value);
        }
    }
    if (rep->claim_symplectic >= 0) {
        int want = rep->claim_symplectic, st;
        rep->claim_symplectic_separable = 0;
        if (want) {
            if (rep->symplectic == VIGEN_CHECK_YES) st = VIGEN_CHECK_YES;
            else if (rep->symplectic_separable == VIGEN_CHECK_YES) {
                st = VIGEN_CHECK_YES;
                rep->claim_symplectic_separable = 1;
            } else if (rep->symplectic == VIGEN_CHECK_UNDECIDED || rep->symplectic_separable == VIGEN_CHECK_UNDECIDED)
                st = VIGEN_CHECK_UNDECIDED;
            else st = VIGEN_CHECK_NO;
        } else st = rep->symplectic == VIGEN_CHECK_UNDECIDED ? VIGEN_CHECK_UNDECIDED
                    : rep->symplectic == VIGEN_CHECK_NO ? VIGEN_CHECK_YES : VIGEN_CHECK_NO;
        rep->claim_symplectic_status = st;
        rep->claim_symplectic_within_data = st == VIGEN_CHECK_YES && want && rep->symplectic_within_data;
        if (st != VIGEN_CHECK_YES) {
            vigen_check_problem *p = problem_new(rep, VIGEN_PROBLEM_CLAIM);
            p->claim = "symplectic";
            p->undecided = st == VIGEN_CHECK_UNDECIDED;
            p->value_json = vigen_strdup(rep->symplectic == VIGEN_CHECK_YES ? "true"
                                         : rep->symplectic == VIGEN_CHECK_NO ? "false" : "null");
            p->expected_json = vigen_strdup(want ? "true" : "false");
            int short_data = rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].too_short > 0;
            p->message = st == VIGEN_CHECK_UNDECIDED
                             ? vigen_strdup_printf("claim symplectic = %s: undecided%s", want ? "true" : "false",
                                                   short_data ? ", the data are too short to decide"
                                                              : " at this precision")
                             : vigen_strdup_printf("claim symplectic = %s is false", want ? "true" : "false");
        }
    }
}

/* Largest |entry| of each matrix or vector, the scale of the comparisons. */
static void entries_scale(mag_t m, const arb_srcptr *vecs, slong nvec, slong len)
{
    mag_t t;
    mag_init(t);
    mag_zero(m);
    for (slong v = 0; v < nvec; v++)
        for (slong k = 0; k < len; k++) {
            mid_mag(t, vecs[v] + k);
            mag_max(m, m, t);
        }
    mag_clear(t);
}

static void mat_scale(mag_t m, const arb_mat_struct *X, const arb_mat_struct *Y, slong s)
{
    mag_t t;
    mag_init(t);
    mag_zero(m);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            mid_mag(t, arb_mat_entry(X, i, j));
            mag_max(m, m, t);
            mid_mag(t, arb_mat_entry(Y, i, j));
            mag_max(m, m, t);
        }
    mag_clear(t);
}

static void compare_entry(vigen_check_report *rep, ctx_t *cx, const char *mat, slong i, slong j, const arb_t x,
                          const arb_t y, int exact, const mag_t scale)
{
    arb_t d;
    arb_init(d);
    arb_sub(d, x, y, cx->prec);
    ctx_shape(cx, 0, 0, 0, i, j);   /* FILE2's denominators are not in cx: no proof by denominators */
    int st = decide(cx, d, exact, scale);
    if (st == HOLDS) {
        arb_clear(d);
        return;
    }
    if (st == FAILS) rep->against_differences++;
    else rep->against_undecided++;
    vigen_check_problem *p = problem_new(rep, VIGEN_PROBLEM_AGAINST);
    p->undecided = st == UNDECIDED;
    p->matrix = mat;
    p->row = i + 1;
    p->col = j >= 0 ? j + 1 : 0;
    p->has_value = p->has_expected = 1;
    arb_set(p->value, x);
    arb_set(p->expected, y);
    slong digits = digits_to_separate(x, y, cx->prec);
    char *a = ball_str(x, digits), *b = ball_str(y, digits);
    char *name = j >= 0 ? vigen_strdup_printf("%s[%ld][%ld]", mat, (long)(i + 1), (long)(j + 1))
                        : vigen_strdup_printf("%s[%ld]", mat, (long)(i + 1));
    if (st == FAILS) {
        char *ds = ball_str(d, 6);
        p->message = vigen_strdup_printf("%s = %s here but %s there (difference %s%s)", name, a, b,
                                         ds[0] == '[' ? "in " : "", ds);
        free(ds);
    }
    else p->message = vigen_strdup_printf("%s = %s here and %s there: undecided at this precision", name, a, b);
    free(name);
    free(a);
    free(b);
    arb_clear(d);
}

/* x: the checked tableau (its context makes the decisions), y: FILE2. */
static void check_against(vigen_check_report *rep, ctx_t *x, const ctx_t *y)
{
    rep->against_checked = 1;
    rep->against_differences = 0;
    rep->against_undecided = 0;
    if (x->s != y->s) {
        rep->against_differences = 1;
        rep->against_stages = y->s;
        vigen_check_problem *p = problem_new(rep, VIGEN_PROBLEM_AGAINST);
        p->value_json = vigen_strdup_printf("%ld", (long)x->s);
        p->expected_json = vigen_strdup_printf("%ld", (long)y->s);
        p->message = vigen_strdup_printf("the tableaux have %ld and %ld stages", (long)x->s, (long)y->s);
        return;
    }
    x->section = VIGEN_CHECK_SECT_AGAINST;
    slong s = x->s;
    int p_part = x->has_At || y->has_At;
    mag_t sc;
    mag_init(sc);
    /* the scale of a comparison: the largest entry of that matrix or vector in
     * either tableau (an entry that is 0 is compared at the scale of its
     * neighbours) */
#define VEC_SCALE(X, Y)                                                                                               \
    do {                                                                                                              \
        arb_srcptr v_[2] = {(X), (Y)};                                                                                \
        entries_scale(sc, v_, 2, s);                                                                                  \
    } while (0)
#define MAT_SCALE(X, Y) mat_scale(sc, (X), (Y), s)
    const exactness *ex = x->ex, *ey = y->ex;
    VEC_SCALE(x->c, y->c);
    for (slong i = 0; i < s; i++)
        compare_entry(rep, x, "c", i, -1, x->c + i, y->c + i, ex->c[i] && ey->c[i], sc);
    MAT_SCALE(x->A, y->A);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++)
            compare_entry(rep, x, "A", i, j, arb_mat_entry(x->A, i, j), arb_mat_entry(y->A, i, j),
                          ex->A[i * s + j] && ey->A[i * s + j], sc);
    VEC_SCALE(x->b, y->b);
    for (slong i = 0; i < s; i++)
        compare_entry(rep, x, "b", i, -1, x->b + i, y->b + i, ex->b[i] && ey->b[i], sc);
    if (p_part) {
        VEC_SCALE(x->ct, y->ct);
        for (slong i = 0; i < s; i++)
            compare_entry(rep, x, "ct", i, -1, x->ct + i, y->ct + i, ex->ct[i] && ey->ct[i], sc);
        MAT_SCALE(x->At, y->At);
        for (slong i = 0; i < s; i++)
            for (slong j = 0; j < s; j++)
                compare_entry(rep, x, "At", i, j, arb_mat_entry(x->At, i, j), arb_mat_entry(y->At, i, j),
                              ex->At[i * s + j] && ey->At[i * s + j], sc);
        VEC_SCALE(x->bt, y->bt);
        for (slong i = 0; i < s; i++)
            compare_entry(rep, x, "bt", i, -1, x->bt + i, y->bt + i, ex->bt[i] && ey->bt[i], sc);
    }
#undef VEC_SCALE
#undef MAT_SCALE
    mag_clear(sc);
}

/* ------------------------------------------------------------- driver */

void vigen_check_report_init(vigen_check_report *rep)
{
    memset(rep, 0, sizeof(*rep));
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
        arb_init(rep->orders[f].fail_value);
        arb_init(rep->orders[f].fail_expected);
        arb_init(rep->orders[f].undecided_value);
        arb_init(rep->orders[f].undecided_expected);
    }
    for (int k = 0; k < VIGEN_CHECK_SECTIONS; k++) mag_init(rep->holds[k].radius);
    rep->claim_order = -1;
    rep->claim_symplectic = -1;
}

static void notes_clear(vigen_check_report *rep)
{
    for (slong k = 0; k < rep->nnotes; k++) {
        vigen_check_note *n = rep->notes + k;
        free(n->entry);
        free(n->text);
        free(n->radius);
        free(n->fraction);
        free(n->message);
    }
    free(rep->notes);
    rep->notes = NULL;
    rep->nnotes = 0;
}

void vigen_check_report_clear(vigen_check_report *rep)
{
    problems_clear(rep);
    notes_clear(rep);
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
        free(rep->orders[f].fail_tree);
        free(rep->orders[f].undecided_tree);
        arb_clear(rep->orders[f].fail_value);
        arb_clear(rep->orders[f].fail_expected);
        arb_clear(rep->orders[f].undecided_value);
        arb_clear(rep->orders[f].undecided_expected);
    }
    for (int k = 0; k < VIGEN_CHECK_SECTIONS; k++) mag_clear(rep->holds[k].radius);
    free(rep->path);
    free(rep->name);
    flint_free(rep->rational_denominator);
    flint_free(rep->quadratic_d);
    flint_free(rep->quadratic_denominator);
    memset(rep, 0, sizeof(*rep));
}

static int has_texts(const vigen_tableau *t) { return t->c_text != NULL && t->A_text != NULL && t->b_text != NULL; }

/* Decimal digits needed to see every literal of an exact expression: the
 * digits of its longest number (all digits of the mantissa, leading zeros
 * included, plus |exponent|: "1e-45" needs 46), plus, summed over the powers
 * B^k with a whole-number literal exponent k, |k| log10 B (at least |k| 0.3;
 * B the number before '^'; a parenthesised base counts |k| digits when |k| >= 10,
 * nothing for small powers such as x^2). */
static double literal_digits(const char *s)
{
    double numbers = 0, powers = 0;
    double base = -1;            /* the number just before the current position, or -1 */
    size_t i = 0, n = strlen(s);
    while (i < n) {
        char ch = s[i];
        if ((ch >= '0' && ch <= '9') || (ch == '.' && s[i + 1] >= '0' && s[i + 1] <= '9')) {
            size_t j = i;
            double nd = 0;
            while ((s[j] >= '0' && s[j] <= '9') || s[j] == '.') nd += s[j++] != '.';
            double ex = 0;
            if ((s[j] == 'e' || s[j] == 'E') &&
                ((s[j + 1] >= '0' && s[j + 1] <= '9') ||
                 ((s[j + 1] == '+' || s[j + 1] == '-') && s[j + 2] >= '0' && s[j + 2] <= '9'))) {
                j++;
                if (s[j] == '+' || s[j] == '-') j++;
                while (s[j] >= '0' && s[j] <= '9') {
                    if (ex < 1e9) ex = 10 * ex + (s[j] - '0');
                    j++;
                }
            }
            if (nd + ex > numbers) numbers = nd + ex;
            char *buf = malloc(j - i + 1);
            memcpy(buf, s + i, j - i);
            buf[j - i] = '\0';
            base = fabs(strtod(buf, NULL));
            free(buf);
            i = j;
            continue;
        }
        if (ch == '^') {
            double b = base;
            size_t j = i + 1;
            int paren = 0;
            while (s[j] == ' ' || s[j] == '(' || s[j] == '+' || s[j] == '-') paren += s[j++] == '(';
            if (s[j] >= '0' && s[j] <= '9') {
                size_t k0 = j;
                double k = 0;
                while (s[j] >= '0' && s[j] <= '9') {
                    if (k < 1e9) k = 10 * k + (s[j] - '0');
                    j++;
                }
                while (s[j] == ' ') j++;
                /* a whole number, not the start of 1/3, 2.5, 1e3 or 2^3 */
                int whole = j > k0 && s[j] != '.' && s[j] != '/' && s[j] != 'e' && s[j] != 'E' && s[j] != '^' &&
                            !(paren && s[j] != ')');
                if (whole) {
                    if (b < 0) powers += k >= 10 ? k : 0;
                    else if (b != 0 && b != 1) powers += k * FLINT_MAX(fabs(log10(b)), 0.30103);
                }
            }
            base = -1;
            i++;
            continue;
        }
        if (ch != ' ' && ch != '\t') base = -1;
        i++;
    }
    return numbers + powers;
}

/* Digits needed by the entries: the longest rounded decimal, and the literals
 * of every exact expression. */
static double entries_digits(const vigen_tableau *t)
{
    slong s = t->s;
    double d = 0;
    char **lists[6] = {t->c_text, t->b_text, t->ct_text, t->bt_text, t->A_text, t->At_text};
    slong lens[6] = {s, s, s, s, s * s, s * s};
    for (int l = 0; l < 6; l++) {
        if (lists[l] == NULL) continue;
        for (slong k = 0; k < lens[l]; k++) {
            const char *x = lists[l][k];
            if (x == NULL) continue;
            double n = vigen_decimal_is_rounded(x) ? (double)vigen_decimal_significant_digits(x) : literal_digits(x);
            if (!vigen_decimal_is_rounded(x)) {
                /* an exact part far smaller than the rest (1/2 + exp(-2000)) must
                 * be visible at the starting precision, literal or not */
                vigen_expr *e = NULL;
                vigen_error err;
                vigen_error_init(&err);
                if (vigen_expr_parse(&e, x, 0, &err) == VIGEN_OK) {
                    double span = vigen_expr_magnitude_span_bits(e) * 0.30102999566398120;
                    if (span > n) n = span;
                }
                vigen_expr_free(e);
                vigen_error_clear(&err);
            }
            if (n > d) d = n;
        }
    }
    return d;
}

/* Short decimals that look exact: a rounded decimal with at most
 * VIGEN_CHECK_NOTE_SHORT_DIGITS significant digits in a file whose longest
 * decimal has at least VIGEN_CHECK_NOTE_LONG_DIGITS.  Three digits is where
 * the rule for rounded data stops deciding on an entry alone (5 10^-3 of
 * itself at most, above 2^-10); ten digits says the file meant to be precise,
 * so a "0.5" among such entries is most likely the exact 1/2 typed as a
 * decimal.  Zeros written with an exponent ("0e-50", a certified tiny value
 * of a generated file) are meant as balls and not named. */
static void collect_notes(vigen_check_report *rep, const vigen_tableau *t)
{
    notes_clear(rep);
    if (!has_texts(t)) return;
    slong s = t->s;
    int has_At = t->has_At, has_bt = t->has_At && t->has_bt, has_ct = t->has_At && t->has_ct;
    /* in the order of the file */
    char **lists[6] = {t->c_text, t->A_text, t->b_text, has_At ? t->At_text : NULL, has_ct ? t->ct_text : NULL,
                       has_bt ? t->bt_text : NULL};
    const char *names[6] = {"c", "A", "b", "At", "ct", "bt"};
    slong lens[6] = {s, s * s, s, s * s, s, s};
    int matrix[6] = {0, 1, 0, 1, 0, 0};
    slong longest = 0;
    for (int l = 0; l < 6; l++)
        for (slong k = 0; lists[l] && k < lens[l]; k++)
            if (lists[l][k] && vigen_decimal_is_rounded(lists[l][k])) {
                slong d = vigen_decimal_significant_digits(lists[l][k]);
                if (d > longest) longest = d;
            }
    if (longest < VIGEN_CHECK_NOTE_LONG_DIGITS) return;
    slong alloc = 0;
    for (int l = 0; l < 6; l++)
        for (slong k = 0; lists[l] && k < lens[l]; k++) {
            const char *x = lists[l][k];
            if (x == NULL || !vigen_decimal_is_rounded(x)) continue;
            slong d = vigen_decimal_significant_digits(x);
            if (d > VIGEN_CHECK_NOTE_SHORT_DIGITS) continue;
            char *fraction = vigen_decimal_exact_fraction(x), *radius = vigen_decimal_half_unit(x);
            if (fraction == NULL || radius == NULL ||
                (strcmp(fraction, "0") == 0 && (strchr(x, 'e') != NULL || strchr(x, 'E') != NULL))) {
                free(fraction);
                free(radius);
                continue;
            }
            if (rep->nnotes == alloc) {
                alloc = alloc ? 2 * alloc : 8;
                rep->notes = realloc(rep->notes, sizeof(vigen_check_note) * (size_t)alloc);
            }
            vigen_check_note *n = rep->notes + rep->nnotes++;
            n->entry = matrix[l] ? vigen_strdup_printf("%s[%ld][%ld]", names[l], (long)(k / s + 1), (long)(k % s + 1))
                                 : vigen_strdup_printf("%s[%ld]", names[l], (long)(k + 1));
            /* the text without surrounding blanks */
            const char *a = x;
            while (*a == ' ' || *a == '\t') a++;
            size_t len = strlen(a);
            while (len > 0 && (a[len - 1] == ' ' || a[len - 1] == '\t')) len--;
            n->text = malloc(len + 1);
            memcpy(n->text, a, len);
            n->text[len] = '\0';
            n->digits = d;
            n->radius = radius;
            n->fraction = fraction;
            n->message = vigen_strdup_printf("%s = \"%s\" is read as %s +/- %s (%ld significant digit%s); if it is "
                                             "exact, write \"%s\"", n->entry, n->text, n->text, radius, (long)d,
                                             d == 1 ? "" : "s", fraction);
        }
}

static slong adequate_prec(const vigen_tableau *t)
{
    double d = entries_digits(t);
    if (d > 1e7) d = 1e7;
    slong p = (slong)ceil(d * 3.3219280948873623) + 64;
    if (!has_texts(t) && t->prec > p) p = t->prec;
    return p < 128 ? 128 : p;
}

/* Evaluates t at prec (texts), retrying higher on precision-dependent domain
 * errors; a tableau without texts keeps its balls. */
static int evaluate(vigen_tableau *t, slong *prec, slong max_prec, vigen_error *err)
{
    if (!has_texts(t)) {
        if (t->prec <= 0)
            return vigen_error_set(err, VIGEN_E_USAGE, "the tableau has neither entry texts nor evaluated balls");
        return VIGEN_OK;
    }
    for (;;) {
        int rc = vigen_tableau_evaluate(t, *prec, err);
        if (rc == VIGEN_OK) return VIGEN_OK;
        if (rc != VIGEN_E_DOMAIN || 2 * *prec > max_prec) return rc;
        vigen_error_clear(err);
        *prec *= 2;
    }
}

static void report_reset_round(vigen_check_report *rep)
{
    problems_clear(rep);
    rep->against_checked = 0;
    rep->against_differences = 0;
    rep->against_undecided = 0;
    for (int k = 0; k < VIGEN_CHECK_SECTIONS; k++) {
        rep->holds[k].exact = rep->holds[k].data = rep->holds[k].too_short = 0;
        mag_zero(rep->holds[k].radius);
    }
}

/* One round of every check at the precision of t (and against). */
static int check_round(vigen_check_report *rep, ctx_t *cx, vigen_tableau *t, vigen_tableau *against,
                       const exactness *ex_against, int P, vigen_error *err)
{
    report_reset_round(rep);
    if (cx->conj) conj_log_start(cx->conj, cx->conj_recording);
    check_rows_and_symplecticity(rep, cx, t->claim_symplectic);
    int rc = check_orders(rep, cx, P, err);
    if (rc != VIGEN_OK) return rc;
    check_simplifying(rep, cx);
    check_claims(rep);
    if (against) {
        ctx_t cy;
        ctx_init(&cy, against, ex_against, rep->holds);
        cy.prec = cx->prec;
        check_against(rep, cx, &cy);
    }
    return VIGEN_OK;
}

/* The conjugate of a tableau in Q(sqrt d): every entry a + b sqrt(d) becomes
 * a - b sqrt(d) (texts from ex->conj; ct and bt default as in t), with the
 * claims of t.  Evaluate it with vigen_tableau_evaluate. */
static void conj_tableau_init(vigen_tableau *tc, const vigen_tableau *t, const exactness *ex)
{
    slong s = t->s;
    vigen_tableau_init(tc, s);
    tc->has_At = t->has_At;
    tc->has_ct = t->has_At && t->has_ct;
    tc->has_bt = t->has_At && t->has_bt;
    tc->claim_order = t->claim_order;
    tc->claim_symplectic = t->claim_symplectic;
    char ***lists[6] = {&tc->c_text, &tc->b_text, &tc->ct_text, &tc->bt_text, &tc->A_text, &tc->At_text};
    slong lens[6] = {s, s, s, s, s * s, s * s};
    for (int l = 0; l < 6; l++) {
        if (ex->conj[l] == NULL) continue;
        *lists[l] = calloc((size_t)lens[l], sizeof(char *));
        for (slong k = 0; k < lens[l]; k++) (*lists[l])[k] = vigen_strdup(ex->conj[l][k]);
    }
}

/* Runs one round at prec on the conjugate tableau tc, recording in log the
 * conditions decided and the upper bounds of their values there.  Its report
 * is a scratch copy: rep (read for the settings the checks use) is untouched.
 * When tc cannot be evaluated the record stays empty: no proof this round. */
static void conj_record(conj_log *log, const vigen_check_report *rep, vigen_tableau *tc, const exactness *ex,
                        slong prec, int P)
{
    vigen_error err;
    vigen_error_init(&err);
    conj_log_start(log, 1);
    if (vigen_tableau_evaluate(tc, prec, &err) == VIGEN_OK) {
        vigen_check_report scratch;
        vigen_check_report_init(&scratch);
        scratch.s = rep->s;
        scratch.max_order = rep->max_order;
        scratch.has_At = rep->has_At;
        scratch.has_bt = rep->has_bt;
        scratch.has_ct = rep->has_ct;
        scratch.claim_order = rep->claim_order;
        scratch.claim_symplectic = rep->claim_symplectic;
        scratch.rounded_entries = rep->rounded_entries;
        scratch.exact_entries = rep->exact_entries;
        ctx_t cx;
        ctx_init(&cx, tc, ex, scratch.holds);
        cx.prec = prec;
        cx.conj = log;
        cx.conj_recording = 1;
        if (check_round(&scratch, &cx, tc, NULL, NULL, P, &err) != VIGEN_OK) log->n = 0;
        vigen_check_report_clear(&scratch);
    }
    vigen_error_clear(&err);
}

int vigen_check_tableau(vigen_check_report *rep, vigen_tableau *t, vigen_tableau *against,
                        const vigen_check_options *opt_in, vigen_error *err)
{
    vigen_check_options opt;
    if (opt_in) opt = *opt_in;
    else vigen_check_options_init(&opt);
    if (opt.max_order <= 0) opt.max_order = DEFAULT_MAX_ORDER;
    if (opt.max_prec <= 0) opt.max_prec = DEFAULT_MAX_PREC;
    if (opt.max_order > VIGEN_TREE_MAX_ORDER)
        return vigen_error_set(err, VIGEN_E_USAGE, "--max-order %d: at most %d is supported", opt.max_order,
                               VIGEN_TREE_MAX_ORDER);

    /* a claim order = p is confirmed by a failing condition of order p + 1 */
    int P = opt.max_order;
    if (t->claim_order >= 0 && t->claim_order + 1 <= VIGEN_TREE_MAX_ORDER && t->claim_order + 1 > P)
        P = t->claim_order + 1;

    free(rep->path);
    free(rep->name);
    rep->path = opt.path ? vigen_strdup(opt.path) : NULL;
    rep->name = t->name ? vigen_strdup(t->name) : NULL;
    rep->s = t->s;
    rep->max_order = P;
    rep->has_At = t->has_At;
    rep->has_bt = t->has_At && t->has_bt;
    rep->has_ct = t->has_At && t->has_ct;
    rep->claim_order = t->claim_order;
    rep->claim_symplectic = t->claim_symplectic;

    slong prec = opt.prec > 0 ? opt.prec : adequate_prec(t);
    if (against && opt.prec <= 0 && adequate_prec(against) > prec) prec = adequate_prec(against);
    /* the entries may ask for more than the cap: allow one confirmation above the start */
    slong cap = opt.max_prec > 2 * prec ? opt.max_prec : 2 * prec;
    int refinable = has_texts(t) || (against && has_texts(against));
    exactness ex, ex_against;
    exactness_init(&ex, t);
    if (against) exactness_init(&ex_against, against);
    rep->rounded_entries = ex.any_rounded;
    rep->exact_entries = ex.any_exact;
    collect_notes(rep, t);
    /* the precision at which the data's radii, not the arithmetic, make the
     * balls of conditions on rounded entries: only there is a ball too wide
     * for the rule of rounded data a verdict on the data */
    slong data_prec = adequate_prec(t);
    if (against && adequate_prec(against) > data_prec) data_prec = adequate_prec(against);
    flint_free(rep->rational_denominator);
    flint_free(rep->quadratic_d);
    flint_free(rep->quadratic_denominator);
    rep->rational_denominator = rep->quadratic_d = rep->quadratic_denominator = NULL;
    int quadratic = fmpz_cmp_ui(ex.qd, 1) > 0;
    if (fmpz_is_one(ex.qd)) rep->rational_denominator = fmpz_get_str(NULL, 10, ex.den);
    else if (quadratic) {
        rep->quadratic_d = fmpz_get_str(NULL, 10, ex.qd);
        rep->quadratic_denominator = fmpz_get_str(NULL, 10, ex.den);
    }
    /* entries in Q(sqrt d): each round is run on the conjugate tableau first,
     * for the bounds of the quadratic proof (twice the work, for these only) */
    vigen_tableau conj;
    conj_log log;
    conj_log_init(&log);
    if (quadratic) conj_tableau_init(&conj, t, &ex);
    int rc = VIGEN_OK;
    rep->rounds = 0;
    rep->prec_first = 0;
    ulong last_hash = 0;
    slong last_undecided = -1;
    /* Exact conditions that hold are confirmed only at a round of at least
     * 1024 bits (and 4 times the start), reachable below the cap: a difference
     * such as exp(-200) ~ 2^-288 that no literal reveals hides below a 128- or
     * 256-bit radius, not below a 1024-bit one. */
    slong reachable = prec;
    while (2 * reachable <= cap) reachable *= 2;
    slong min_confirm = 4 * prec > 1024 ? 4 * prec : 1024;
    if (min_confirm > reachable) min_confirm = reachable;

    for (;;) {
        rep->undecided_reason = NULL;
        rc = evaluate(t, &prec, cap, err);
        if (rc == VIGEN_OK && !has_texts(t)) prec = t->prec;
        if (rc == VIGEN_OK && against) {
            slong p2 = prec;
            rc = evaluate(against, &p2, cap, err);
            if (rc != VIGEN_OK) vigen_error_prefix(err, "--against: ");
        }
        if (rc != VIGEN_OK) break;
        rep->rounds++;
        if (rep->prec_first == 0) rep->prec_first = prec;
        rep->prec = prec;

        ctx_t cx;
        ctx_init(&cx, t, &ex, rep->holds);
        cx.prec = prec;
        if (quadratic) {
            conj_record(&log, rep, &conj, &ex, prec, P);
            cx.conj = &log;
        }
        rc = check_round(rep, &cx, t, against, against ? &ex_against : NULL, P, err);
        if (rc != VIGEN_OK) break;
        rep->proved = cx.n_proved;

        /* exact conditions that hold with a nonzero radius are confirmed when
         * the previous round, at half the precision, gave the same verdicts,
         * at min_confirm bits or more */
        int confirmed = cx.n_unconfirmed == 0 || (rep->rounds > 1 && cx.hash == last_hash && prec >= min_confirm);
        rep->undecided_left = cx.n_undecided;
        rep->undecided_short = cx.n_undecided_short;
        if (cx.n_undecided == 0 && confirmed) break;
        const char *stop = NULL;
        /* every undecided condition is on rounded data whose radii make its
         * ball too wide: more working precision cannot narrow them */
        int all_short = cx.n_undecided_exact == 0 && cx.n_undecided > 0 && cx.n_undecided == cx.n_undecided_short;
        if (all_short && confirmed && (prec >= data_prec || !refinable || 2 * prec > cap))
            stop = "the data are too short to decide: these conditions involve rounded entries, and their balls "
                   "contain 0 but are wider than 2^-10 of their terms (more working precision cannot narrow the "
                   "radii of the data; exact entries, such as \"1/2\" for \"0.5\", or more digits can)";
        else if (!refinable) stop = "the tableau has no entry texts to re-evaluate";
        else if (2 * prec > cap) stop = "the precision cap was reached";
        else if (cx.n_undecided_exact == 0 && cx.n_undecided > 0 && rep->rounds > 1 &&
                 cx.n_undecided >= last_undecided && confirmed)
            stop = "more precision does not help: the balls of the rounded entries are not finite";
        if (stop) {
            if (!confirmed) {
                /* the holding exact conditions cannot be confirmed: undecided */
                cx.strict = 1;
                cx.n_undecided = cx.n_undecided_exact = cx.n_unconfirmed = 0;
                cx.hash = 1469598103934665603ULL;
                rc = check_round(rep, &cx, t, against, against ? &ex_against : NULL, P, err);
                if (rc != VIGEN_OK) break;
                rep->undecided_left = cx.n_undecided;
                rep->undecided_short = cx.n_undecided_short;
            }
            rep->undecided_reason = stop;
            break;
        }
        last_hash = cx.hash;
        last_undecided = cx.n_undecided;
        prec *= 2;
    }
    if (quadratic) vigen_tableau_clear(&conj);
    conj_log_clear(&log);
    exactness_clear(&ex);
    if (against) exactness_clear(&ex_against);
    if (rc != VIGEN_OK) return rc;

    int code = 0;
    if (rep->consistent != VIGEN_CHECK_YES) code = 1;
    if (rep->claim_order >= 0 && rep->claim_order_status != VIGEN_CHECK_YES) code = 1;
    if (rep->claim_symplectic >= 0 && rep->claim_symplectic_status != VIGEN_CHECK_YES) code = 1;
    if (rep->against_differences > 0 || rep->against_undecided > 0) code = 1;
    rep->exit_code = code;
    return VIGEN_OK;
}

/* --------------------------------------------------------------- text */

static const char *family_title[VIGEN_CHECK_FAMILIES] = {
    "order", "order for separable H = T(p) + V(q)", "(c, A, b) alone as an RK method",
    "(ct, At, bt) alone as an RK method"};

static const char *const within_words = "within the precision of the data";

static void print_level_words(FILE *out, const vigen_check_level *L)
{
    if (L->capped) fprintf(out, "%d or more", L->value);
    else if (L->undecided) fprintf(out, "at least %d", L->value);
    else fprintf(out, "%d", L->value);
    if (L->within_data) fprintf(out, " %s", within_words);
    if (!L->capped && L->undecided)
        fprintf(out, " (order %d undecided%s)", L->value + 1,
                L->too_short ? ": the data are too short to decide" : " at this precision");
}

static void print_ball(FILE *out, const arb_t x, slong digits)
{
    char *s = ball_str(x, digits);
    fputs(s, out);
    free(s);
}

static void print_bad_tree(FILE *out, const vigen_check_orders *o, const char *indent)
{
    const vigen_check_level *L = &o->level;
    if (L->capped) return;
    int undecided = L->undecided;
    const char *tree = undecided ? o->undecided_tree : o->fail_tree;
    if (tree == NULL) return;
    fprintf(out, "%s%s tree: %s (order %d): sum bhat_i Phi_i = ", indent, undecided ? "first undecided" : "first failing",
            tree, L->value + 1);
    slong digits = digits_to_separate(undecided ? o->undecided_value : o->fail_value,
                                      undecided ? o->undecided_expected : o->fail_expected, 128);
    print_ball(out, undecided ? o->undecided_value : o->fail_value, digits);
    fputs(", 1/gamma = ", out);
    print_ball(out, undecided ? o->undecided_expected : o->fail_expected, digits);
    arb_t d;
    arb_init(d);
    arb_srcptr dv = undecided ? o->undecided_value : o->fail_value, de = undecided ? o->undecided_expected : o->fail_expected;
    arb_sub(d, dv, de, FLINT_MAX(arb_bits(dv), arb_bits(de)) + 64);
    char *ds = ball_str(d, 6);
    fprintf(out, " (defect %s%s)\n", ds[0] == '[' ? "in " : "", ds);
    free(ds);
    arb_clear(d);
}

static const char *tri_word(int v, const char *yes, const char *no)
{
    return v == VIGEN_CHECK_YES ? yes : v == VIGEN_CHECK_NO ? no : "undecided at this precision";
}

/* tri_word, saying why when undecided for short data */
static const char *tri_word_data(int v, const char *yes, const char *no, int too_short)
{
    if (v == VIGEN_CHECK_UNDECIDED && too_short) return "undecided (the data are too short to decide)";
    return tri_word(v, yes, no);
}

/* " within the precision of the data (radius <= X)" when some holding
 * condition of the section was decided on rounded entries. */
static void print_within(FILE *out, const vigen_check_holds *h)
{
    if (h->data == 0) return;
    char *r = mag_str(h->radius);
    fprintf(out, " %s (radius <= %s)", within_words, r);
    free(r);
}

/* B(4), B(4)* when it holds within the precision of the data (returns 1 then) */
static int print_assumption(FILE *out, const char *name, const vigen_check_level *L)
{
    if (L->capped) fprintf(out, "%s(>=%d)", name, L->value);
    else if (L->undecided) fprintf(out, "%s(%d, %d undecided%s)", name, L->value, L->value + 1,
                                   L->too_short ? ": data too short" : "");
    else fprintf(out, "%s(%d)", name, L->value);
    if (L->within_data) fputc('*', out);
    return L->within_data;
}

/* A long integer for the text report: its first and last digits and its
 * length ("30000...0000 (870 digits)"); short ones whole.  JSON has them whole. */
static char *short_integer(const char *digits)
{
    size_t n = strlen(digits);
    if (n <= 40) return vigen_strdup(digits);
    return vigen_strdup_printf("%.12s...%s (%lu digits)", digits, digits + n - 8, (unsigned long)n);
}

void vigen_check_print_text(FILE *out, const vigen_check_report *rep)
{
    fputs(rep->path ? rep->path : "tableau", out);
    if (rep->name && !(rep->path && strcmp(rep->path, rep->name) == 0)) fprintf(out, " (%s)", rep->name);
    fprintf(out, ": %ld stage%s, %s\n", (long)rep->s, rep->s == 1 ? "" : "s",
            rep->has_At ? "partitioned (A and At given)" : "one RK method for both parts (At = A)");
    if (rep->rational_denominator) {
        char *D = short_integer(rep->rational_denominator);
        fprintf(out, "  entries: exact rationals, common denominator D = %s; ", D);
        free(D);
    } else if (rep->quadratic_d) {
        char *D = short_integer(rep->quadratic_denominator);
        fprintf(out, "  entries: exact, in Q(sqrt(%s)): a + b sqrt(%s), common denominator D = %s; ", rep->quadratic_d,
                rep->quadratic_d, D);
        free(D);
    } else
        fprintf(out, "  entries: %s; ",
                rep->rounded_entries && rep->exact_entries ? "rounded decimals (half-ulp balls) and exact expressions"
                : rep->rounded_entries ? "rounded decimals (half-ulp balls) or balls"
                                       : "exact expressions");
    if (rep->rounds > 1)
        fprintf(out, "checked at %ld bits (%ld evaluations, from %ld bits)\n", (long)rep->prec, (long)rep->rounds,
                (long)rep->prec_first);
    else fprintf(out, "checked at %ld bits (1 evaluation)\n", (long)rep->prec);
    if (rep->rational_denominator)
        fputs("  a condition fails when its ball excludes 0; it holds, proved, when its ball lies inside\n"
              "  (-1/(D^k g), 1/(D^k g)), k entries per term and g the denominator of its constant: the value is a\n"
              "  multiple of 1/(D^k g), so 0; otherwise it is undecided\n", out);
    else if (rep->quadratic_d)
        fprintf(out, "  a condition fails when its ball excludes 0; it holds, proved, when |v| |v'| (D^k g)^2 < 1, v' the same\n"
                     "  condition on the conjugate tableau (sqrt(%s) -> -sqrt(%s)), k entries per term and g the denominator\n"
                     "  of its constant: v v' (D^k g)^2 is an integer m^2 - %s n^2, so m = n = 0 and v = 0; otherwise it\n"
                     "  holds only with a radius below 2^-(prec/2) of its terms and the same verdicts at two precisions,\n"
                     "  else it is undecided\n",
                rep->quadratic_d, rep->quadratic_d, rep->quadratic_d);
    else if (!rep->exact_entries)
        fputs("  a condition fails when its ball excludes 0 and holds, within the precision of the data, when it\n"
              "  contains 0 with a radius at most 2^-10 of its terms; a wider ball is undecided (the data are too\n"
              "  short to decide)\n", out);
    else if (!rep->rounded_entries)
        fputs("  a condition fails when its ball excludes 0; it holds when its ball contains 0 with a radius below\n"
              "  2^-(prec/2) of its terms, with the same verdicts at two precisions; otherwise it is undecided.\n"
              "  These holds are numerical confirmations, not proofs (entries outside Q and one Q(sqrt d): only\n"
              "  rational and real quadratic tableaux are proved); the precision starts above the span of the\n"
              "  entries' parts, so that a part like exp(-2000) is seen\n", out);
    else
        fputs("  a condition fails when its ball excludes 0 and holds when it contains 0: within the precision of\n"
              "  the data when it involves a rounded entry and its radius is at most 2^-10 of its terms; on exact\n"
              "  entries only with a radius below 2^-(prec/2) of its terms and the same verdicts at two precisions;\n"
              "  otherwise it is undecided\n", out);
    for (slong k = 0; k < rep->nnotes && k < 10; k++) fprintf(out, "  note: %s\n", rep->notes[k].message);
    if (rep->nnotes > 10)
        fprintf(out, "  note: ... and %ld more short decimals (all of them with --json)\n", (long)(rep->nnotes - 10));

    fprintf(out, "row sums      %s", tri_word_data(rep->consistent, "hold", "FAIL",
                                                  rep->holds[VIGEN_CHECK_SECT_ROWSUM].too_short > 0));
    if (rep->consistent == VIGEN_CHECK_YES) print_within(out, &rep->holds[VIGEN_CHECK_SECT_ROWSUM]);
    fprintf(out, " (%ld conditions: c_i = sum_j a_ij%s, sum b = 1", (long)rep->row_total,
            rep->has_ct ? ", ct_i = sum_j at_ij" : "");
    if (rep->row_fail) fprintf(out, "; %ld fail", (long)rep->row_fail);
    if (rep->row_undecided) fprintf(out, "; %ld undecided", (long)rep->row_undecided);
    fputs(")\n", out);
    fprintf(out, "symplectic    %s", tri_word_data(rep->symplectic, "yes", "no",
                                                  rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].too_short > 0));
    if (rep->symplectic == VIGEN_CHECK_YES) print_within(out, &rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC]);
    fprintf(out, " (%ld condition%s: %sb_i %s_ij + b_j a_ji - b_i b_j = 0", (long)rep->sym_total,
            rep->sym_total == 1 ? "" : "s", rep->has_bt ? "bt = b, " : "", rep->has_At ? "at" : "a");
    if (rep->sym_fail) fprintf(out, "; %ld fail", (long)rep->sym_fail);
    if (rep->sym_undecided) fprintf(out, "; %ld undecided", (long)rep->sym_undecided);
    fputs(")\n", out);
    if (rep->has_bt && rep->symplectic != VIGEN_CHECK_YES)
        fprintf(out, "              for separable H (b_i at_ij + bt_j a_ji - b_i bt_j = 0 suffices): %s\n",
                tri_word_data(rep->symplectic_separable, "yes", "no",
                              rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].too_short > 0));

    const vigen_check_orders *g = &rep->orders[VIGEN_CHECK_GENERAL];
    fputs("order         ", out);
    print_level_words(out, &g->level);
    fprintf(out, "   (orders 1..%d checked)\n", rep->max_order);
    print_bad_tree(out, g, "              ");
    if (rep->holds[VIGEN_CHECK_SECT_ORDER].data > 0) {
        char *r = mag_str(rep->holds[VIGEN_CHECK_SECT_ORDER].radius);
        fprintf(out, "              (%ld conditions hold within the precision of the data: radius <= %s)\n",
                (long)rep->holds[VIGEN_CHECK_SECT_ORDER].data, r);
        free(r);
    }
    if (rep->holds[VIGEN_CHECK_SECT_ORDER].too_short > 0)
        fprintf(out, "              (%ld conditions undecided: the data are too short to decide, their balls contain 0 "
                     "but are wider than 2^-%d of their terms)\n",
                (long)rep->holds[VIGEN_CHECK_SECT_ORDER].too_short, VIGEN_CHECK_DATA_BITS);

    fputs("  order  conditions   hold   fail  undecided |  separable     A alone    At alone\n", out);
    for (int n = 1; n <= g->evaluated_to; n++) {
        fprintf(out, "  %5d  %10ld %6ld %6ld %10ld |", n, (long)g->count[n], (long)g->hold[n], (long)g->fail[n],
                (long)g->undecided[n]);
        for (int f = 1; f < VIGEN_CHECK_FAMILIES; f++) {
            char buf[64];
            snprintf(buf, sizeof(buf), "%ld/%ld", (long)rep->orders[f].hold[n], (long)rep->orders[f].count[n]);
            fprintf(out, " %11s", buf);
        }
        fputc('\n', out);
    }
    if (g->evaluated_to + 1 == rep->max_order)
        fprintf(out, "  (order %d not evaluated: every family already fails)\n", rep->max_order);
    else if (g->evaluated_to < rep->max_order)
        fprintf(out, "  (orders %d..%d not evaluated: every family already fails)\n", g->evaluated_to + 1,
                rep->max_order);
    fputs("  (x/y: conditions holding / conditions of that family)\n", out);

    for (int f = 1; f < VIGEN_CHECK_FAMILIES; f++) {
        const vigen_check_orders *o = &rep->orders[f];
        if (f == VIGEN_CHECK_AT_ALONE && !rep->has_At) {
            fprintf(out, "%s: same as (c, A, b) (At = A)\n", family_title[f]);
            continue;
        }
        fprintf(out, "%s: ", family_title[f]);
        print_level_words(out, &o->level);
        if (f == VIGEN_CHECK_SEPARABLE && o->level.value == g->level.value && o->level.capped == g->level.capped &&
            o->level.undecided == g->level.undecided && o->level.within_data == g->level.within_data &&
            o->level.too_short == g->level.too_short) {
            fputs(" (same)\n", out);
            continue;
        }
        fputc('\n', out);
        const char *mine = o->level.undecided ? o->undecided_tree : o->fail_tree;
        const char *general = g->level.undecided ? g->undecided_tree : g->fail_tree;
        if (!(mine && general && strcmp(mine, general) == 0 && o->level.value == g->level.value))
            print_bad_tree(out, o, "  ");
    }

    fputs("simplifying assumptions\n", out);
    int starred = 0;
    for (int part = 0; part < (rep->has_At ? 2 : 1); part++) {
        fprintf(out, "  %-13s ", part ? "(ct, At, bt):" : "(c, A, b):");
        starred |= print_assumption(out, "B", &rep->B[part]);
        fputc(' ', out);
        starred |= print_assumption(out, "C", &rep->C[part]);
        fputc(' ', out);
        starred |= print_assumption(out, "D", &rep->D[part]);
        fputs(", stage order ", out);
        const vigen_check_level *S = &rep->stage_order[part];
        if (S->capped) fprintf(out, ">= %d", S->value);
        else fprintf(out, "%d", S->value);
        if (S->within_data) fputc('*', out);
        starred |= S->within_data;
        if (!S->capped && S->undecided) fputs(S->too_short ? " (undecided above: data too short)" : " (undecided above)", out);
        fputc('\n', out);
    }
    if (!rep->has_At) fputs("  (ct, At, bt):  same (At = A)\n", out);
    if (starred) {
        char *r = mag_str(rep->holds[VIGEN_CHECK_SECT_SIMPLIFYING].radius);
        fprintf(out, "  (*: holds %s, radius <= %s)\n", within_words, r);
        free(r);
    }

    if (rep->claim_order >= 0 || rep->claim_symplectic >= 0) {
        fputs("claims       ", out);
        if (rep->claim_order >= 0)
            fprintf(out, " order = %d: %s%s%s%s;", rep->claim_order,
                    rep->claim_order_beyond ? "undecided (beyond the orders that can be evaluated)"
                                            : tri_word_data(rep->claim_order_status, "holds", "FALSE",
                                                            rep->claim_order_too_short),
                    rep->claim_order_within_data ? " " : "", rep->claim_order_within_data ? within_words : "",
                    rep->claim_order_separable ? " (for separable H)" : "");
        if (rep->claim_symplectic >= 0)
            fprintf(out, " symplectic = %s: %s%s%s%s;", rep->claim_symplectic ? "true" : "false",
                    tri_word_data(rep->claim_symplectic_status, "holds", "FALSE",
                                  rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].too_short > 0),
                    rep->claim_symplectic_within_data ? " " : "",
                    rep->claim_symplectic_within_data ? within_words : "",
                    rep->claim_symplectic_separable ? " (for separable H)" : "");
        fputc('\n', out);
    }
    if (rep->against_checked && rep->against_stages > 0) {
        fprintf(out, "against       the tableaux cannot be compared: %ld stage%s here, %ld there\n", (long)rep->s,
                rep->s == 1 ? "" : "s", (long)rep->against_stages);
    } else if (rep->against_checked) {
        fprintf(out, "against       %ld entr%s differ%s beyond the certified precision",
                (long)rep->against_differences, rep->against_differences == 1 ? "y" : "ies",
                rep->against_differences == 1 ? "s" : "");
        if (rep->against_undecided) fprintf(out, ", %ld undecided", (long)rep->against_undecided);
        if (rep->holds[VIGEN_CHECK_SECT_AGAINST].data > 0) {
            char *r = mag_str(rep->holds[VIGEN_CHECK_SECT_AGAINST].radius);
            fprintf(out, " (%ld agree within the precision of the data, radius <= %s)",
                    (long)rep->holds[VIGEN_CHECK_SECT_AGAINST].data, r);
            free(r);
        }
        fputc('\n', out);
    }

    if (rep->undecided_left)
        fprintf(out, "undecided     %ld conditions at %ld bits: %s\n", (long)rep->undecided_left, (long)rep->prec,
                rep->undecided_reason ? rep->undecided_reason : "");
    if (rep->nproblems) {
        fputs("problems\n", out);
        /* symplecticity pairs: the first 20; everything else: up to 40 lines */
        slong pairs = 0, pairs_shown = 0, other_shown = 0, other_hidden = 0;
        for (slong k = 0; k < rep->nproblems; k++) {
            const vigen_check_problem *p = rep->problems + k;
            if (p->kind == VIGEN_PROBLEM_SYMPLECTIC && !p->diagnosed && p->col > 0) pairs++;
        }
        for (slong k = 0; k < rep->nproblems; k++) {
            const vigen_check_problem *p = rep->problems + k;
            /* a diagnosis is filed once per kind of condition, with one message */
            if (k > 0 && p->diagnosed && rep->problems[k - 1].diagnosed &&
                strcmp(p->message, rep->problems[k - 1].message) == 0)
                continue;
            if (p->kind == VIGEN_PROBLEM_SYMPLECTIC && !p->diagnosed && p->col > 0) {
                if (pairs_shown < 20) {
                    fprintf(out, "  %s\n", p->message);
                    if (++pairs_shown == 20 && pairs > 20)
                        fprintf(out, "  ... and %ld more pairs (all of them with --json)\n", (long)(pairs - 20));
                }
                continue;
            }
            if (other_shown < 40) {
                fprintf(out, "  %s\n", p->message);
                other_shown++;
            } else other_hidden++;
        }
        if (other_hidden) fprintf(out, "  ... and %ld more problems (all of them with --json)\n", (long)other_hidden);
    } else fputs("problems      none\n", out);
    fprintf(out, "trees: %s\n", vigen_tree_notation_help());
    int within = rep->consistent_within_data || rep->claim_order_within_data || rep->claim_symplectic_within_data;
    /* exit 1 with nothing certainly false: undecided, not failed */
    int failed = rep->consistent == VIGEN_CHECK_NO || (rep->claim_order >= 0 && rep->claim_order_status == VIGEN_CHECK_NO) ||
                 (rep->claim_symplectic >= 0 && rep->claim_symplectic_status == VIGEN_CHECK_NO) ||
                 rep->against_differences > 0;
    fprintf(out, "result        %s (exit %d)\n",
            rep->exit_code != 0 && !failed ? "NOT DECIDED: nothing is certainly false, but not everything could be "
                                             "decided (see the undecided conditions above)"
            : rep->exit_code != 0 ? "FAILED: see the problems above"
            : within ? "consistent; every stated claim holds (some only within the precision of the data)"
                     : "consistent; every stated claim holds",
            rep->exit_code);
}

/* --------------------------------------------------------------- JSON */

static void json_string(FILE *out, const char *s)
{
    fputc('"', out);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\') fprintf(out, "\\%c", *p);
        else if (*p == '\n') fputs("\\n", out);
        else if (*p < 0x20) fprintf(out, "\\u%04x", *p);
        else fputc(*p, out);
    }
    fputc('"', out);
}

static void json_ball(FILE *out, const arb_t x, slong prec)
{
    slong digits = (slong)(prec * 0.30103);
    if (digits > 60) digits = 60;
    if (digits < 10) digits = 10;
    char *s = ball_json_str(x, digits);
    json_string(out, s);
    free(s);
}

static void json_tri(FILE *out, int v)
{
    fputs(v == VIGEN_CHECK_YES ? "true" : v == VIGEN_CHECK_NO ? "false" : "null", out);
}

/* "exact": the level is certainly value; "within_data": it is value, resting
 * on conditions that hold within the precision of the data; "at_least" and
 * "at_least_within_data": everything up to the cap holds; "undecided":
 * value + 1 is undecided. */
static const char *level_status(const vigen_check_level *L)
{
    if (L->capped) return L->within_data ? "at_least_within_data" : "at_least";
    if (L->undecided) return "undecided";
    return L->within_data ? "within_data" : "exact";
}

static void json_level(FILE *out, const vigen_check_level *L)
{
    fprintf(out, "{\"value\": %d, \"status\": \"%s\", \"within_data\": %s, \"data_too_short\": %s}", L->value,
            level_status(L), L->within_data ? "true" : "false", L->undecided && L->too_short ? "true" : "false");
}

static void json_bad_tree(FILE *out, const vigen_check_orders *o, slong prec)
{
    const vigen_check_level *L = &o->level;
    const char *tree = L->capped ? NULL : L->undecided ? o->undecided_tree : o->fail_tree;
    if (tree == NULL) { fputs("null", out); return; }
    fputs("{\"tree\": ", out);
    json_string(out, tree);
    fprintf(out, ", \"order\": %d, \"undecided\": %s, \"value\": ", L->value + 1, L->undecided ? "true" : "false");
    json_ball(out, L->undecided ? o->undecided_value : o->fail_value, prec);
    fputs(", \"expected\": ", out);
    json_ball(out, L->undecided ? o->undecided_expected : o->fail_expected, prec);
    fputc('}', out);
}

void vigen_check_print_json(FILE *out, const vigen_check_report *rep)
{
    static const char *const kinds[] = {"rowsum", "symplectic", "claim", "against"};
    static const char *const family_keys[] = {"general", "separable", "A", "At"};
    const vigen_check_orders *g = &rep->orders[VIGEN_CHECK_GENERAL];
    fputs("{\"file\": ", out);
    if (rep->path) json_string(out, rep->path); else fputs("null", out);
    fputs(", \"name\": ", out);
    if (rep->name) json_string(out, rep->name); else fputs("null", out);
    fprintf(out, ", \"stages\": %ld, \"partitioned\": %s, \"precision_bits\": %ld, \"first_precision_bits\": %ld, "
                 "\"evaluations\": %ld, \"max_order\": %d,\n",
            (long)rep->s, rep->has_At ? "true" : "false", (long)rep->prec, (long)rep->prec_first, (long)rep->rounds,
            rep->max_order);
    fprintf(out, " \"rounded_entries\": %s, \"exact_entries\": %s,\n", rep->rounded_entries ? "true" : "false",
            rep->exact_entries ? "true" : "false");
    if (rep->rational_denominator)
        fprintf(out, " \"rational_denominator\": \"%s\", \"proved\": %ld,\n", rep->rational_denominator,
                (long)rep->proved);
    else if (rep->quadratic_d)
        fprintf(out, " \"quadratic_field\": \"sqrt(%s)\", \"denominator\": \"%s\", \"proved\": %ld,\n",
                rep->quadratic_d, rep->quadratic_denominator, (long)rep->proved);
    /* holds on exact entries are proofs only in the two cases above */
    fprintf(out, " \"exact_holds_are_proofs\": %s,\n",
            rep->rational_denominator || rep->quadratic_d ? "true" : "false");
    fputs(" \"rule\": \"a condition fails when its ball excludes 0 and holds when it contains 0: on rounded entries "
          "within the precision of the data, with a radius at most 2^-10 of its terms; on exact entries with a radius "
          "below 2^-(prec/2) of its terms and the same verdicts at two precisions; otherwise it is undecided\",\n",
          out);
    fprintf(out, " \"data_threshold_bits\": %d,\n", VIGEN_CHECK_DATA_BITS);
    fputs(" \"notes\": [", out);
    for (slong k = 0; k < rep->nnotes; k++) {
        const vigen_check_note *n = rep->notes + k;
        fputs(k ? ",\n  {\"entry\": " : "\n  {\"entry\": ", out);
        json_string(out, n->entry);
        fputs(", \"text\": ", out);
        json_string(out, n->text);
        fprintf(out, ", \"significant_digits\": %ld, \"radius\": ", (long)n->digits);
        json_string(out, n->radius);
        fputs(", \"exact_value\": ", out);
        json_string(out, n->fraction);
        fputs(", \"message\": ", out);
        json_string(out, n->message);
        fputc('}', out);
    }
    fputs(rep->nnotes ? "\n ],\n" : "],\n", out);
    static const char *const sect_keys[] = {"rowsum", "symplectic", "order", "simplifying", "against"};
    fputs(" \"holding\": {", out);
    for (int k = 0; k < VIGEN_CHECK_SECTIONS; k++) {
        const vigen_check_holds *h = rep->holds + k;
        if (k == VIGEN_CHECK_SECT_AGAINST && !rep->against_checked) continue;
        fprintf(out, "%s\"%s\": {\"exact\": %ld, \"within_data_precision\": %ld, \"undecided_too_short\": %ld, "
                     "\"radius\": ", k ? ", " : "", sect_keys[k], (long)h->exact, (long)h->data, (long)h->too_short);
        if (h->data) {
            char *r = mag_str(h->radius);
            json_string(out, r);
            free(r);
        } else fputs("null", out);
        fputc('}', out);
    }
    fputs("},\n", out);
    fputs(" \"consistent\": ", out);
    json_tri(out, rep->consistent);
    fputs(", \"symplectic\": ", out);
    json_tri(out, rep->symplectic);
    fputs(", \"symplectic_separable\": ", out);
    json_tri(out, rep->symplectic_separable);
    fprintf(out, ",\n \"consistent_within_data\": %s, \"symplectic_within_data\": %s",
            rep->consistent_within_data ? "true" : "false", rep->symplectic_within_data ? "true" : "false");
    fprintf(out, ",\n \"order\": %d, \"order_status\": \"%s\", \"order_within_data\": %s, \"order_separable\": %d, "
                 "\"order_separable_status\": \"%s\",\n",
            g->level.value, level_status(&g->level), g->level.within_data ? "true" : "false",
            rep->orders[VIGEN_CHECK_SEPARABLE].level.value, level_status(&rep->orders[VIGEN_CHECK_SEPARABLE].level));
    fprintf(out, " \"order_A\": %d, \"order_At\": %d,\n", rep->orders[VIGEN_CHECK_A_ALONE].level.value,
            rep->orders[VIGEN_CHECK_AT_ALONE].level.value);
    fputs(" \"orders\": {", out);
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
        const vigen_check_orders *o = &rep->orders[f];
        fprintf(out, "%s\n  \"%s\": {\"level\": ", f ? "," : "", family_keys[f]);
        json_level(out, &o->level);
        fputs(", \"first_bad_tree\": ", out);
        json_bad_tree(out, o, rep->prec);
        fputs(", \"per_order\": [", out);
        for (int n = 1; n <= o->evaluated_to; n++)
            fprintf(out, "%s{\"order\": %d, \"conditions\": %ld, \"hold\": %ld, \"fail\": %ld, \"undecided\": %ld}",
                    n > 1 ? ", " : "", n, (long)o->count[n], (long)o->hold[n], (long)o->fail[n],
                    (long)o->undecided[n]);
        fputs("]}", out);
    }
    fputs("},\n \"simplifying\": {", out);
    for (int part = 0; part < 2; part++) {
        fprintf(out, "%s\"%s\": {\"B\": ", part ? ", " : "", part ? "At" : "A");
        json_level(out, &rep->B[part]);
        fputs(", \"C\": ", out);
        json_level(out, &rep->C[part]);
        fputs(", \"D\": ", out);
        json_level(out, &rep->D[part]);
        fputs(", \"stage_order\": ", out);
        json_level(out, &rep->stage_order[part]);
        fputc('}', out);
    }
    fputs("},\n \"claims\": {", out);
    int first = 1;
    if (rep->claim_order >= 0) {
        fprintf(out, "\"order\": {\"claimed\": %d, \"holds\": ", rep->claim_order);
        json_tri(out, rep->claim_order_status);
        fprintf(out, ", \"separable_only\": %s, \"beyond_max_order\": %s, \"within_data\": %s, \"data_too_short\": %s}",
                rep->claim_order_separable ? "true" : "false", rep->claim_order_beyond ? "true" : "false",
                rep->claim_order_within_data ? "true" : "false", rep->claim_order_too_short ? "true" : "false");
        first = 0;
    }
    if (rep->claim_symplectic >= 0) {
        fprintf(out, "%s\"symplectic\": {\"claimed\": %s, \"holds\": ", first ? "" : ", ",
                rep->claim_symplectic ? "true" : "false");
        json_tri(out, rep->claim_symplectic_status);
        fprintf(out, ", \"separable_only\": %s, \"within_data\": %s}", rep->claim_symplectic_separable ? "true" : "false",
                rep->claim_symplectic_within_data ? "true" : "false");
    }
    fputs("},\n \"problems\": [", out);
    for (slong k = 0; k < rep->nproblems; k++) {
        const vigen_check_problem *p = rep->problems + k;
        fprintf(out, "%s\n  {\"kind\": \"%s\"", k ? "," : "", kinds[p->kind]);
        if (p->claim) fprintf(out, ", \"claim\": \"%s\"", p->claim);
        if (p->matrix) fprintf(out, ", \"matrix\": \"%s\"", p->matrix);
        if (p->row) fprintf(out, ", \"row\": %ld", (long)p->row);
        if (p->col) fprintf(out, ", \"col\": %ld", (long)p->col);
        if (p->has_value) { fputs(", \"value\": ", out); json_ball(out, p->value, rep->prec); }
        else if (p->value_json) fprintf(out, ", \"value\": %s", p->value_json);
        if (p->has_expected) { fputs(", \"expected\": ", out); json_ball(out, p->expected, rep->prec); }
        else if (p->expected_json) fprintf(out, ", \"expected\": %s", p->expected_json);
        if (p->undecided) fputs(", \"undecided\": true", out);
        if (p->diagnosed) fputs(", \"diagnosed\": true", out);
        fputs(", \"message\": ", out);
        json_string(out, p->message ? p->message : "");
        fputc('}', out);
    }
    fputs(rep->nproblems ? "\n ],\n" : "],\n", out);
    fputs(" \"notation\": ", out);
    json_string(out, vigen_tree_notation_help());
    if (rep->against_checked)
        fprintf(out, ",\n \"against\": {\"differences\": %ld, \"undecided\": %ld}", (long)rep->against_differences,
                (long)rep->against_undecided);
    fprintf(out, ",\n \"undecided_conditions\": %ld, \"undecided_too_short\": %ld, \"undecided_reason\": ",
            (long)rep->undecided_left, (long)rep->undecided_short);
    if (rep->undecided_reason) json_string(out, rep->undecided_reason); else fputs("null", out);
    fprintf(out, ",\n \"exit\": %d}\n", rep->exit_code);
}

/* ------------------------------------------------------- file and CLI */

static int load_file(vigen_tableau *t, const char *path, const vigen_check_options *opt, vigen_error *err)
{
    if (opt->load) return opt->load(t, path, opt->spec_digits, err);
    return vigen_tableau_load(t, path, NULL, err);
}

int vigen_check_run(const vigen_check_options *opt, FILE *out, vigen_error *err)
{
    if (opt->path == NULL) {
        vigen_error_set(err, VIGEN_E_USAGE, "no tableau file given");
        return 2;
    }
    vigen_tableau t, u;
    int rc = load_file(&t, opt->path, opt, err);
    if (rc != VIGEN_OK) return rc == VIGEN_E_MATH || rc == VIGEN_E_PRECISION ? 1 : 2;
    if (opt->against) {
        rc = load_file(&u, opt->against, opt, err);
        if (rc != VIGEN_OK) {
            vigen_tableau_clear(&t);
            return rc == VIGEN_E_MATH || rc == VIGEN_E_PRECISION ? 1 : 2;
        }
    }
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    rc = vigen_check_tableau(&rep, &t, opt->against ? &u : NULL, opt, err);
    int code;
    if (rc != VIGEN_OK) {
        vigen_error_prefix(err, "%s: ", opt->path);
        code = rc == VIGEN_E_MATH || rc == VIGEN_E_PRECISION ? 1 : 2;
    } else {
        if (opt->json) vigen_check_print_json(out, &rep);
        else vigen_check_print_text(out, &rep);
        code = rep.exit_code;
    }
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    if (opt->against) vigen_tableau_clear(&u);
    return code;
}
