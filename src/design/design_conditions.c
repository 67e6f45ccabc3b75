/* design_conditions.c — the order conditions of a composition of a symmetric
 * base method, as polynomials in the steps gamma_i, derived symbolically.
 *
 * A symmetric one-step method S of order q (even) is the exact flow of a
 * modified vector field with only odd powers of h (HLW GNI sec. II.3 and
 * III.5): S(h) = exp(h Y1 + h^(q+1) Y_{q+1} + h^(q+3) Y_{q+3} + ...).  Taking
 * the Y's as free generators of a Lie algebra gives the conditions that hold
 * for every such base: the composition S(gamma_s h) ... S(gamma_1 h) is
 * exp(sum_i (gamma_i h Y1 + gamma_i^(q+1) h^(q+1) Y_{q+1} + ...)) multiplied
 * out by the Baker-Campbell-Hausdorff series, here computed in the truncated
 * free associative algebra (words in the letters Y_d, a letter weighing d):
 * the product of the truncated exponentials, then its logarithm.  The
 * logarithm is a Lie element L; the method has order p when L = h Y1 up to
 * weight p.  A Lie element is zero exactly when its coefficients on the
 * Lyndon words vanish (the standard bracketing P(w) of a Lyndon word w is w
 * plus larger words: Reutenauer, Free Lie Algebras, Thm 5.1, so the
 * coefficients of the Lyndon words determine those in the Lyndon basis by a
 * unitriangular system).  The conditions are therefore: for every Lyndon
 * word w of weight <= p, the coefficient of w in L, minus 1 for w = Y1.  For
 * a symmetric composition the even weights vanish identically (the
 * composition is symmetric) and are dropped; for q = 2, p = 4 this is
 * sum gamma = 1, sum gamma^3 = 0 (Yoshida 1990; McLachlan 1995).  The
 * polynomials have exact rational coefficients (FLINT fmpq_mpoly).
 */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_mpoly.h>
#include "design/design_internal.h"
#include "support/strbuf.h"

#define MAX_LETTERS 16

/* The words of weight <= p: word w is letters[w][0 .. len[w]-1]. */
typedef struct {
    slong n, alloc;
    int (*letters)[DESIGN_WORD_MAX];
    int *len, *weight;
    int nletters;
    int letter_weight[MAX_LETTERS];
    int named;                   /* the letters are A, B (a splitting), not Y_weight */
    slong *cat;                  /* cat[a*n + b]: the word a b, or -1 (weight > p) */
} words;

static slong word_find(const words *w, const int *l, int len)
{
    for (slong i = 0; i < w->n; i++)
        if (w->len[i] == len && memcmp(w->letters[i], l, (size_t)len * sizeof(int)) == 0) return i;
    return -1;
}

static void words_add(words *w, const int *l, int len, int weight)
{
    if (w->n == w->alloc) {
        w->alloc = w->alloc ? 2 * w->alloc : 64;
        w->letters = realloc(w->letters, (size_t)w->alloc * sizeof *w->letters);
        w->len = realloc(w->len, (size_t)w->alloc * sizeof(int));
        w->weight = realloc(w->weight, (size_t)w->alloc * sizeof(int));
    }
    memcpy(w->letters[w->n], l, (size_t)len * sizeof(int));
    w->len[w->n] = len;
    w->weight[w->n] = weight;
    w->n++;
}

/* The letters of a symmetric base of order q: Y1, Y_(q+1), Y_(q+3), ...
 * of weight at most p. */
static int base_letters(int *weight, int q, int p)
{
    int n = 0;
    weight[n++] = 1;
    for (int d = q + 1; d <= p && n < MAX_LETTERS; d += 2) weight[n++] = d;
    return n;
}

/* Every word of weight <= p in the letters of these weights, by extending
 * the words in order (breadth first: a word's prefixes come before it). */
static void words_init(words *w, const int *letter_weight, int nletters, int p, int with_cat)
{
    memset(w, 0, sizeof *w);
    for (int a = 0; a < nletters; a++) w->letter_weight[w->nletters++] = letter_weight[a];
    int none[1] = {0};
    words_add(w, none, 0, 0);
    for (slong i = 0; i < w->n; i++)
        for (int a = 0; a < w->nletters; a++) {
            int wt = w->weight[i] + w->letter_weight[a];
            if (wt > p || w->len[i] + 1 > DESIGN_WORD_MAX) continue;
            int l[DESIGN_WORD_MAX];
            memcpy(l, w->letters[i], (size_t)w->len[i] * sizeof(int));
            l[w->len[i]] = a;
            words_add(w, l, w->len[i] + 1, wt);
        }
    if (!with_cat) return;
    w->cat = malloc((size_t)(w->n * w->n) * sizeof(slong));
    for (slong a = 0; a < w->n; a++)
        for (slong b = 0; b < w->n; b++) {
            slong *c = &w->cat[a * w->n + b];
            *c = -1;
            if (w->weight[a] + w->weight[b] > p) continue;
            int l[DESIGN_WORD_MAX];
            memcpy(l, w->letters[a], (size_t)w->len[a] * sizeof(int));
            memcpy(l + w->len[a], w->letters[b], (size_t)w->len[b] * sizeof(int));
            *c = word_find(w, l, w->len[a] + w->len[b]);
        }
}

static void words_clear(words *w)
{
    free(w->letters);
    free(w->len);
    free(w->weight);
    free(w->cat);
}

/* A word is Lyndon when it is strictly smaller than each of its proper
 * rotations (letters ordered by weight). */
static int is_lyndon(const int *l, int len)
{
    if (len == 0) return 0;
    for (int r = 1; r < len; r++) {
        int cmp = 0;
        for (int i = 0; i < len && cmp == 0; i++) {
            int a = l[i], b = l[(i + r) % len];
            cmp = a < b ? -1 : a > b ? 1 : 0;
        }
        if (cmp >= 0) return 0;
    }
    return 1;
}

static slong count(const int *weight, int nletters, int symmetric, int p)
{
    words w;
    words_init(&w, weight, nletters, p, 0);
    slong n = 0;
    for (slong i = 1; i < w.n; i++)
        if (is_lyndon(w.letters[i], w.len[i]) && (!symmetric || w.weight[i] % 2 == 1)) n++;
    words_clear(&w);
    return n;
}

slong design_composition_count(int symmetric, int q, int p)
{
    int weight[MAX_LETTERS];
    return count(weight, base_letters(weight, q, p), symmetric, p);
}

slong design_splitting_count(int symmetric, int p)
{
    static const int weight[2] = {1, 1};
    return count(weight, 2, symmetric, p);
}

slong design_stage_unknown(slong i, int stages, int symmetric)
{
    if (!symmetric) return i;
    return i < stages - 1 - i ? i : stages - 1 - i;
}

/* An element of the algebra: one polynomial per word. */
typedef fmpq_mpoly_struct *elem;

static elem elem_new(const words *w, const fmpq_mpoly_ctx_t ctx)
{
    elem e = malloc((size_t)w->n * sizeof *e);
    for (slong i = 0; i < w->n; i++) fmpq_mpoly_init(e + i, ctx);
    return e;
}

static void elem_free(elem e, const words *w, const fmpq_mpoly_ctx_t ctx)
{
    for (slong i = 0; i < w->n; i++) fmpq_mpoly_clear(e + i, ctx);
    free(e);
}

/* out = x y (out distinct from x and y), truncated at weight p. */
static void elem_mul(elem out, const elem x, const elem y, const words *w, const fmpq_mpoly_ctx_t ctx)
{
    fmpq_mpoly_t t;
    fmpq_mpoly_init(t, ctx);
    for (slong i = 0; i < w->n; i++) fmpq_mpoly_zero(out + i, ctx);
    for (slong a = 0; a < w->n; a++) {
        if (fmpq_mpoly_is_zero(x + a, ctx)) continue;
        for (slong b = 0; b < w->n; b++) {
            slong c = w->cat[a * w->n + b];
            if (c < 0 || fmpq_mpoly_is_zero(y + b, ctx)) continue;
            fmpq_mpoly_mul(t, x + a, y + b, ctx);
            fmpq_mpoly_add(out + c, out + c, t, ctx);
        }
    }
    fmpq_mpoly_clear(t, ctx);
}

/* out += c x */
static void elem_addmul(elem out, const elem x, const fmpq_t c, const words *w, const fmpq_mpoly_ctx_t ctx)
{
    fmpq_mpoly_t t;
    fmpq_mpoly_init(t, ctx);
    for (slong i = 0; i < w->n; i++) {
        fmpq_mpoly_scalar_mul_fmpq(t, x + i, c, ctx);
        fmpq_mpoly_add(out + i, out + i, t, ctx);
    }
    fmpq_mpoly_clear(t, ctx);
}

/* The truncated series of x (no constant term) up to x^p: exp, 1 + sum x^k/k!
 * (is_log 0), or log(1 + x) = sum (-1)^(k+1) x^k / k (is_log 1). */
static void elem_series(elem out, const elem x, int is_log, int p, const words *w, const fmpq_mpoly_ctx_t ctx)
{
    elem pw = elem_new(w, ctx), tmp = elem_new(w, ctx);
    for (slong i = 0; i < w->n; i++) {
        fmpq_mpoly_zero(out + i, ctx);
        fmpq_mpoly_set(pw + i, x + i, ctx);
    }
    if (!is_log) fmpq_mpoly_one(out + 0, ctx);
    fmpq_t c, fact;
    fmpz_t kz;
    fmpq_init(c);
    fmpq_init(fact);
    fmpz_init(kz);
    fmpq_one(fact);
    for (int k = 1; k <= p; k++) {
        if (is_log) fmpq_set_si(c, k % 2 ? 1 : -1, (ulong)k);
        else {
            fmpz_set_si(kz, k);
            fmpq_div_fmpz(fact, fact, kz);
            fmpq_set(c, fact);
        }
        elem_addmul(out, pw, c, w, ctx);
        if (k < p) {
            elem_mul(tmp, pw, x, w, ctx);
            elem t = pw;
            pw = tmp;
            tmp = t;
        }
    }
    fmpq_clear(c);
    fmpq_clear(fact);
    fmpz_clear(kz);
    elem_free(pw, w, ctx);
    elem_free(tmp, w, ctx);
}

static void poly_from_mpoly(design_poly *d, const fmpq_mpoly_t m, slong k, const fmpq_mpoly_ctx_t ctx)
{
    d->k = k;
    d->nterms = fmpq_mpoly_length(m, ctx);
    d->coef = _fmpq_vec_init(d->nterms > 0 ? d->nterms : 1);
    d->coef_d = malloc((size_t)(d->nterms > 0 ? d->nterms : 1) * sizeof(double));
    d->exp = calloc((size_t)((d->nterms > 0 ? d->nterms : 1) * k), sizeof(slong));
    d->degree = d->nterms > 0 ? fmpq_mpoly_total_degree_si(m, ctx) : 0;
    for (slong t = 0; t < d->nterms; t++) {
        fmpq_mpoly_get_term_coeff_fmpq(d->coef + t, m, t, ctx);
        d->coef_d[t] = fmpq_get_d(d->coef + t);
        fmpq_mpoly_get_term_exp_si(d->exp + t * k, m, t, ctx);
    }
}

static char *word_text(const words *w, slong i)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    for (int j = 0; j < w->len[i]; j++)
        if (w->named) vigen_strbuf_printf(&sb, "%s%c", j ? " " : "", 'A' + w->letters[i][j]);
        else vigen_strbuf_printf(&sb, "%sY%d", j ? " " : "", w->letter_weight[w->letters[i][j]]);
    return sb.data;
}

/* One factor of the product: exp(sum over letters a of x[var[a]]^pow[a] a)
 * (var[a] < 0: the letter is absent). */
typedef struct {
    slong var[MAX_LETTERS];
    int pow[MAX_LETTERS];
} factor;

/* The conditions of the product of the factors (applied in order) against
 * the target sum of the letters target[a] = 1: the Lyndon coefficients of the
 * logarithm minus the target's, those identically zero dropped. */
static int build(design_system *sys, const int *letter_weight, int nletters, int named, const factor *f, slong nf,
                 const int *target, slong k, int p)
{
    words w;
    words_init(&w, letter_weight, nletters, p, 1);
    w.named = named;
    fmpq_mpoly_ctx_t ctx;
    fmpq_mpoly_ctx_init(ctx, k, ORD_LEX);
    elem prod = elem_new(&w, ctx), x = elem_new(&w, ctx), e = elem_new(&w, ctx), t = elem_new(&w, ctx);
    fmpq_mpoly_one(prod + 0, ctx);
    for (slong i = 0; i < nf; i++) {
        for (slong j = 0; j < w.n; j++) fmpq_mpoly_zero(x + j, ctx);
        for (int a = 0; a < w.nletters; a++) {
            int one[1] = {a};
            slong at = word_find(&w, one, 1);
            if (at < 0 || f[i].var[a] < 0) continue;
            fmpq_mpoly_gen(x + at, f[i].var[a], ctx);
            fmpq_mpoly_pow_ui(x + at, x + at, (ulong)f[i].pow[a], ctx);
        }
        elem_series(e, x, 0, p, &w, ctx);
        elem_mul(t, prod, e, &w, ctx);
        elem s = prod;
        prod = t;
        t = s;
    }
    fmpq_mpoly_zero(prod + 0, ctx);   /* log(1 + Z) with Z = prod - 1 */
    elem_series(e, prod, 1, p, &w, ctx);
    fmpq_mpoly_t one, dm;
    fmpq_mpoly_init(one, ctx);
    fmpq_mpoly_init(dm, ctx);
    fmpq_mpoly_one(one, ctx);
    for (int a = 0; a < w.nletters; a++) {
        int l[1] = {a};
        slong at = word_find(&w, l, 1);
        if (at >= 0 && target[a]) fmpq_mpoly_sub(e + at, e + at, one, ctx);
    }
    sys->k = k;
    sys->cond = calloc((size_t)w.n, sizeof(design_poly));
    sys->dcond = calloc((size_t)(w.n * k), sizeof(design_poly));
    sys->what = calloc((size_t)w.n, sizeof(char *));
    sys->h_degree = calloc((size_t)w.n, sizeof(int));
    for (slong i = 1; i < w.n; i++) {
        if (!is_lyndon(w.letters[i], w.len[i]) || fmpq_mpoly_is_zero(e + i, ctx)) continue;
        slong n = sys->n++;
        poly_from_mpoly(&sys->cond[n], e + i, k, ctx);
        for (slong j = 0; j < k; j++) {
            fmpq_mpoly_derivative(dm, e + i, j, ctx);
            poly_from_mpoly(&sys->dcond[n * k + j], dm, k, ctx);
        }
        sys->what[n] = word_text(&w, i);
        sys->h_degree[n] = w.weight[i];
    }
    fmpq_mpoly_clear(one, ctx);
    fmpq_mpoly_clear(dm, ctx);
    elem_free(prod, &w, ctx);
    elem_free(x, &w, ctx);
    elem_free(e, &w, ctx);
    elem_free(t, &w, ctx);
    fmpq_mpoly_ctx_clear(ctx);
    words_clear(&w);
    return VIGEN_OK;
}

int design_composition_conditions(design_system *sys, int stages, int symmetric, int q, int p, vigen_error *err)
{
    memset(sys, 0, sizeof *sys);
    if (p > VIGEN_DESIGN_MAX_ORDER || p < 1 || q < 2 || q % 2)
        return vigen_error_set(err, VIGEN_E_USAGE, "order %d with a base of order %d is outside what design handles",
                               p, q);
    int weight[MAX_LETTERS], target[MAX_LETTERS] = {1};
    int nletters = base_letters(weight, q, p);
    factor *f = calloc((size_t)stages, sizeof *f);
    for (int i = 0; i < stages; i++)
        for (int a = 0; a < nletters; a++) {
            f[i].var[a] = design_stage_unknown(i, stages, symmetric);
            f[i].pow[a] = weight[a];
        }
    int rc = build(sys, weight, nletters, 0, f, stages, target, symmetric ? (stages + 1) / 2 : stages, p);
    free(f);
    return rc;
}

slong design_splitting_unknowns(int kicks, int symmetric)
{
    return symmetric ? (kicks + 2) / 2 + (kicks + 1) / 2 : 2 * kicks + 1;
}

slong design_substep_unknown(slong i, int kicks, int symmetric)
{
    slong n = 2 * kicks + 1;                 /* drift, kick, ..., kick, drift */
    if (symmetric && i > n - 1 - i) i = n - 1 - i;
    slong drifts = symmetric ? (kicks + 2) / 2 : kicks + 1;
    return i % 2 == 0 ? i / 2 : drifts + i / 2;
}

int design_splitting_conditions(design_system *sys, int kicks, int symmetric, int p, vigen_error *err)
{
    memset(sys, 0, sizeof *sys);
    if (p > VIGEN_DESIGN_MAX_ORDER || p < 1)
        return vigen_error_set(err, VIGEN_E_USAGE, "order %d is outside what design handles", p);
    static const int weight[2] = {1, 1}, target[2] = {1, 1};
    slong n = 2 * kicks + 1;
    factor *f = calloc((size_t)n, sizeof *f);
    for (slong i = 0; i < n; i++) {
        int letter = (int)(i % 2);           /* A (drift) on even substeps, B (kick) on odd */
        f[i].var[letter] = design_substep_unknown(i, kicks, symmetric);
        f[i].var[1 - letter] = -1;
        f[i].pow[letter] = 1;
    }
    int rc = build(sys, weight, 2, 1, f, n, target, design_splitting_unknowns(kicks, symmetric), p);
    free(f);
    return rc;
}
