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
    int neg;                     /* the factor's steps negated (an inverse's substep) */
} factor;

/* The logarithm of the product of the factors (applied in order), in the
 * words w of weight <= p: *e, one polynomial in k unknowns per word, with the
 * target subtracted (the letters a with target[a] = 1, each minus 1). */
static elem bch_log(const words *w, const factor *f, slong nf, const int *target, int p, const fmpq_mpoly_ctx_t ctx)
{
    elem prod = elem_new(w, ctx), x = elem_new(w, ctx), e = elem_new(w, ctx), t = elem_new(w, ctx);
    fmpq_mpoly_one(prod + 0, ctx);
    for (slong i = 0; i < nf; i++) {
        for (slong j = 0; j < w->n; j++) fmpq_mpoly_zero(x + j, ctx);
        for (int a = 0; a < w->nletters; a++) {
            int one[1] = {a};
            slong at = word_find(w, one, 1);
            if (at < 0 || f[i].var[a] < 0) continue;
            fmpq_mpoly_gen(x + at, f[i].var[a], ctx);
            fmpq_mpoly_pow_ui(x + at, x + at, (ulong)f[i].pow[a], ctx);
            if (f[i].neg) fmpq_mpoly_neg(x + at, x + at, ctx);
        }
        elem_series(e, x, 0, p, w, ctx);
        elem_mul(t, prod, e, w, ctx);
        elem s = prod;
        prod = t;
        t = s;
    }
    fmpq_mpoly_zero(prod + 0, ctx);   /* log(1 + Z) with Z = prod - 1 */
    elem_series(e, prod, 1, p, w, ctx);
    fmpq_mpoly_t one;
    fmpq_mpoly_init(one, ctx);
    fmpq_mpoly_one(one, ctx);
    for (int a = 0; a < w->nletters; a++) {
        int l[1] = {a};
        slong at = word_find(w, l, 1);
        if (at >= 0 && target[a]) fmpq_mpoly_sub(e + at, e + at, one, ctx);
    }
    fmpq_mpoly_clear(one, ctx);
    elem_free(prod, w, ctx);
    elem_free(x, w, ctx);
    elem_free(t, w, ctx);
    return e;
}

/* The word of w that the bit word b of degree d is (design_combo), or -1. */
static slong bits_find(const words *w, ulong b, int d)
{
    int l[DESIGN_WORD_MAX];
    for (int j = 0; j < d; j++) l[j] = (int)((b >> (d - 1 - j)) & 1);
    return word_find(w, l, d);
}

/* Appends the condition m = 0 (what, of h-degree deg) to sys, unless m is
 * identically zero. */
static void take(design_system *sys, const fmpq_mpoly_t m, char *what, int deg, const fmpq_mpoly_ctx_t ctx)
{
    if (fmpq_mpoly_is_zero(m, ctx)) {
        free(what);
        return;
    }
    slong n = sys->n++, k = sys->k;
    sys->cond = realloc(sys->cond, (size_t)sys->n * sizeof(design_poly));
    sys->dcond = realloc(sys->dcond, (size_t)(sys->n * k) * sizeof(design_poly));
    sys->what = realloc(sys->what, (size_t)sys->n * sizeof(char *));
    sys->h_degree = realloc(sys->h_degree, (size_t)sys->n * sizeof(int));
    poly_from_mpoly(&sys->cond[n], m, k, ctx);
    fmpq_mpoly_t dm;
    fmpq_mpoly_init(dm, ctx);
    for (slong j = 0; j < k; j++) {
        fmpq_mpoly_derivative(dm, m, j, ctx);
        poly_from_mpoly(&sys->dcond[n * k + j], dm, k, ctx);
    }
    fmpq_mpoly_clear(dm, ctx);
    sys->what[n] = what;
    sys->h_degree[n] = deg;
}

/* The combination of combo c of the coefficients in e into m. */
static void combo_eval(fmpq_mpoly_t m, const design_combo *c, const elem e, const words *w, const fmpq_mpoly_ctx_t ctx)
{
    fmpq_mpoly_t t;
    fmpq_mpoly_init(t, ctx);
    fmpq_mpoly_zero(m, ctx);
    for (slong i = 0; i < c->nterms; i++) {
        slong at = bits_find(w, c->word[i], c->degree);
        if (at < 0) continue;
        fmpq_mpoly_scalar_mul_fmpq(t, e + at, c->coef + i, ctx);
        fmpq_mpoly_add(m, m, t, ctx);
    }
    fmpq_mpoly_clear(t, ctx);
}

/* Whether the Lyndon word i is asked by the generalized order r[0..nr-1]
 * (nr 0: every word is): its length is at most r_j, j its letters B (1),
 * r_j the last entry beyond the list; the words of one letter always. */
static int graded(const words *w, slong i, const int *r, int nr)
{
    if (nr == 0 || w->len[i] == 1) return 1;
    int j = 0;
    for (int l = 0; l < w->len[i]; l++) j += w->letters[i][l] == 1;
    if (j == 0) return 0;
    return w->len[i] <= r[j <= nr ? j - 1 : nr - 1];
}

/* The conditions of the product of the factors against the target sum of
 * the letters target[a] = 1, in k unknowns, appended to sys: the Lyndon
 * coefficients of the logarithm (combos NULL) asked by the generalized
 * order r[0..nr-1] (graded), or the combinations of combos; those
 * identically zero dropped. */
static int build(design_system *sys, const int *letter_weight, int nletters, int named, const factor *f, slong nf,
                 const int *target, slong k, int p, const design_combos *combos, const int *r, int nr)
{
    words w;
    words_init(&w, letter_weight, nletters, p, 1);
    w.named = named;
    fmpq_mpoly_ctx_t ctx;
    fmpq_mpoly_ctx_init(ctx, k, ORD_LEX);
    elem e = bch_log(&w, f, nf, target, p, ctx);
    sys->k = k;
    if (combos == NULL) {
        for (slong i = 1; i < w.n; i++)
            if (is_lyndon(w.letters[i], w.len[i]) && graded(&w, i, r, nr))
                take(sys, e + i, word_text(&w, i), w.weight[i], ctx);
    } else {
        fmpq_mpoly_t m;
        fmpq_mpoly_init(m, ctx);
        for (slong i = 0; i < combos->n; i++) {
            combo_eval(m, &combos->c[i], e, &w, ctx);
            take(sys, m, word_text(&w, bits_find(&w, combos->c[i].word[0], combos->c[i].degree)),
                 combos->c[i].degree, ctx);
        }
        fmpq_mpoly_clear(m, ctx);
    }
    elem_free(e, &w, ctx);
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
    int rc = build(sys, weight, nletters, 0, f, stages, target, symmetric ? (stages + 1) / 2 : stages, p, NULL, NULL,
                   0);
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

/* The factors of the splitting drift, kick, ..., drift with kicks kicks. */
static factor *splitting_factors(int kicks, int symmetric)
{
    slong n = 2 * kicks + 1;
    factor *f = calloc((size_t)n, sizeof *f);
    for (slong i = 0; i < n; i++) {
        int letter = (int)(i % 2);           /* A (drift) on even substeps, B (kick) on odd */
        f[i].var[letter] = design_substep_unknown(i, kicks, symmetric);
        f[i].var[1 - letter] = -1;
        f[i].pow[letter] = 1;
    }
    return f;
}

static const int split_weight[2] = {1, 1}, split_target[2] = {1, 1};

/* The conditions of the splitting in nvars unknowns (its own first). */
static int splitting_build(design_system *sys, int kicks, int symmetric, int p, unsigned mods, slong nvars,
                           const int *r, int nr, vigen_error *err)
{
    memset(sys, 0, sizeof *sys);
    if (p > VIGEN_DESIGN_MAX_ORDER || p < 1)
        return vigen_error_set(err, VIGEN_E_USAGE, "order %d is outside what design handles", p);
    design_combos combos;
    if (mods && design_quotient_conditions(&combos, p, symmetric, mods) != VIGEN_OK)
        return vigen_error_set(err, VIGEN_E_USAGE, "order %d is outside what design handles", p);
    factor *f = splitting_factors(kicks, symmetric);
    int rc = build(sys, split_weight, 2, 1, f, 2 * kicks + 1, split_target, nvars, p, mods ? &combos : NULL, r,
               nr);
    free(f);
    if (mods) design_combos_clear(&combos);
    return rc;
}

int design_splitting_conditions(design_system *sys, int kicks, int symmetric, int p, unsigned mods, vigen_error *err)
{
    return splitting_build(sys, kicks, symmetric, p, mods, design_splitting_unknowns(kicks, symmetric), NULL, 0, err);
}

int design_flows_conditions(design_system *sys, int kicks, int symmetric, const int *r, int nr, vigen_error *err)
{
    int p = 0;
    for (int j = 0; j < nr; j++) p = r[j] > p ? r[j] : p;
    return splitting_build(sys, kicks, symmetric, p, 0, design_splitting_unknowns(kicks, symmetric), r, nr, err);
}

int design_processed_conditions(design_system *sys, int kicks, unsigned mods, vigen_error *err)
{
    slong kx = design_splitting_unknowns(kicks, 1), k = kx + DESIGN_CORRECTOR_UNKNOWNS;
    int rc = splitting_build(sys, kicks, 1, 4, mods | DESIGN_MOD_PROCESSED, k, NULL, 0, err);
    if (rc != VIGEN_OK) return rc;
    words w;
    words_init(&w, split_weight, 2, 3, 1);
    w.named = 1;
    fmpq_mpoly_ctx_t ctx;
    fmpq_mpoly_ctx_init(ctx, k, ORD_LEX);
    /* mu: the kernel's h^3 term is mu [A+B,[A,B]] (its conditions hold) */
    factor *f = splitting_factors(kicks, 1);
    elem ek = bch_log(&w, f, 2 * kicks + 1, split_target, 3, ctx);
    free(f);
    ulong mu_word;
    fmpq_t scale;
    fmpq_init(scale);
    design_quotient_processor(&mu_word, scale);
    fmpq_mpoly_t mu;
    fmpq_mpoly_init(mu, ctx);
    fmpq_mpoly_scalar_mul_fmpq(mu, ek + bits_find(&w, mu_word, 3), scale, ctx);
    /* the corrector drift y1, kick y2, drift y3, kick y4, ... */
    factor *g = calloc(DESIGN_CORRECTOR_UNKNOWNS, sizeof *g);
    for (slong i = 0; i < DESIGN_CORRECTOR_UNKNOWNS; i++) {
        int letter = (int)(i % 2);
        g[i].var[letter] = kx + i;
        g[i].var[1 - letter] = -1;
        g[i].pow[letter] = 1;
    }
    static const int none[2] = {0, 0};
    elem ec = bch_log(&w, g, DESIGN_CORRECTOR_UNKNOWNS, none, 3, ctx);
    free(g);
    /* log C = t h (A + B) + mu h^2 [A,B] + (t/2) h^3 X3 + O(h^4), X3 the
     * kernel's h^3 term (docs/design.md): the word A B has coefficient 1 in
     * [A,B] = AB - BA.  t = DESIGN_CORRECTOR_T, not 0, so that no partial
     * sum of the step C K C^-1 vanishes (the checker then decides its
     * symplecticity on decimals) */
    fmpq_mpoly_t m, one;
    fmpq_mpoly_init(m, ctx);
    fmpq_mpoly_init(one, ctx);
    fmpq_t t;
    fmpq_init(t);
    fmpq_set_si(t, DESIGN_CORRECTOR_T_NUM, DESIGN_CORRECTOR_T_DEN);
    for (slong i = 1; i < w.n; i++) {
        if (!is_lyndon(w.letters[i], w.len[i])) continue;
        fmpq_mpoly_set(m, ec + i, ctx);
        if (w.len[i] == 1) {
            fmpq_mpoly_set_fmpq(one, t, ctx);
            fmpq_mpoly_sub(m, m, one, ctx);
        } else if (w.len[i] == 2) {
            fmpq_mpoly_sub(m, m, mu, ctx);
        } else {
            fmpq_t half;
            fmpq_init(half);
            fmpq_div_2exp(half, t, 1);
            fmpq_mpoly_scalar_mul_fmpq(one, ek + i, half, ctx);
            fmpq_mpoly_sub(m, m, one, ctx);
            fmpq_clear(half);
        }
        char *word = word_text(&w, i);
        take(sys, m, vigen_strdup_printf("corrector %s", word), w.weight[i], ctx);
        free(word);
    }
    fmpq_mpoly_clear(m, ctx);
    fmpq_mpoly_clear(one, ctx);
    fmpq_clear(t);
    fmpq_mpoly_clear(mu, ctx);
    fmpq_clear(scale);
    elem_free(ek, &w, ctx);
    elem_free(ec, &w, ctx);
    fmpq_mpoly_ctx_clear(ctx);
    words_clear(&w);
    return VIGEN_OK;
}
