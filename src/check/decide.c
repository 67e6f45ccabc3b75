/* decide.c — the certified decision on one condition: fails, holds (proved,
 * confirmed, or within the precision of the data) or undecided, with the
 * evaluation context every check goes through and the record of the conjugate
 * tableau that the quadratic proof uses.  The rules are stated in check.h.
 */
#include <string.h>
#include "check/check_internal.h"

static int cond_tag_eq(const cond_tag *x, const cond_tag *y)
{
    return x->section == y->section && x->k == y->k && x->g == y->g && x->id[0] == y->id[0] &&
           x->id[1] == y->id[1] && x->id[2] == y->id[2];
}

void chk_conj_log_init(conj_log *log) { memset(log, 0, sizeof(*log)); }

void chk_conj_log_clear(conj_log *log)
{
    for (slong k = 0; k < log->alloc; k++) mag_clear(log->bound + k);
    flint_free(log->bound);
    flint_free(log->tag);
}

/* Starts a round: recording afresh, or replaying from the first decision. */
void chk_conj_log_start(conj_log *log, int recording)
{
    if (recording) log->n = 0;
    log->pos = 0;
    log->in_step = 1;
}

void chk_ctx_init(ctx_t *cx, const vigen_tableau *t, const exactness *ex, vigen_check_holds *holds)
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
void chk_ctx_shape(ctx_t *cx, slong k, ulong g, slong a, slong b, slong c)
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
void chk_mid_mag(mag_t m, const arb_t x) { arf_get_mag(m, arb_midref(x)); }

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
int chk_decide(ctx_t *cx, const arb_t r, int exact, const mag_t scale)
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

/* chk_decide() with the scale |a| + |b| of a comparison a = b. */
int chk_decide2(ctx_t *cx, const arb_t r, int exact, const arb_t a, const arb_t b)
{
    mag_t m, t;
    mag_init(m);
    mag_init(t);
    chk_mid_mag(m, a);
    chk_mid_mag(t, b);
    mag_add(m, m, t);
    int v = chk_decide(cx, r, exact, m);
    mag_clear(m);
    mag_clear(t);
    return v;
}

int chk_tri_of(slong fail, slong undecided)
{
    return fail ? VIGEN_CHECK_NO : undecided ? VIGEN_CHECK_UNDECIDED : VIGEN_CHECK_YES;
}

