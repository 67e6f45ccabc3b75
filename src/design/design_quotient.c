/* design_quotient.c — the order conditions of a kick/drift splitting modulo
 * a subspace of the free Lie algebra on A (drifts) and B (kicks).
 *
 * The logarithm of a splitting is h (A + B) + sum_n h^n L_n, L_n a Lie
 * element of degree n.  Plain order p asks L_n = 0 (n = 2..p): one condition
 * per Lyndon word (design_conditions.c).  Two families ask less:
 *
 *  - Nystrom H = p^2/2 + V(q): the vector fields of T and V satisfy
 *    relations, first [B,[B,[B,A]]] = 0 ({V,{V,{V,T}}} = 0: {V,T} is linear
 *    in p, {V,{V,T}} depends on q only); in general two Lie elements that
 *    are functions of q commute (generators(), below), so L_n need only lie
 *    in the ideal I of those relations (McLachlan 1995; Blanes & Moan 2002;
 *    Blanes & Casas, A Concise Introduction to Geometric Numerical
 *    Integration, sec. 3.4).
 *  - a kernel of effective order 4 (processed, P K P^-1): L_n need only lie
 *    in [A + B, Lie_(n-1)] + I, the part a processor removes (Blanes, Casas
 *    & Ros 1999; Butcher's effective order).
 *
 * In both, L_n must lie in a subspace U_n.  The Lyndon coefficients are
 * coordinates on Lie_n (Reutenauer, Free Lie Algebras, Thm 5.1), so U_n is
 * spanned by the Lyndon coordinates of its generators, brought to reduced
 * echelon form R with pivot words P.  For each non-pivot Lyndon word w,
 *     phi_w(L) = c_w(L) - sum_i R[i][w] c_(P_i)(L)
 * vanishes on U_n (R[i][P_j] = delta_ij), and these functionals cut out U_n
 * exactly: they are the conditions, dim Lie_n - dim U_n of them.
 *
 * Words of degree n are integers below 2^n, letter j (from the left) bit
 * n-1-j, A = 0 and B = 1, so that the integer order is the lexicographic
 * order with A < B.  Lie elements are integer vectors over the words.
 */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_mat.h>
#include "design/design_internal.h"

static int is_lyndon_bits(ulong w, int n)
{
    ulong mask = n >= 64 ? ~0UL : (1UL << n) - 1;
    for (int r = 1; r < n; r++) {
        ulong rot = ((w << r) | (w >> (n - r))) & mask;
        if (rot <= w) return 0;
    }
    return n > 0;
}

/* out = [x, y] (x of degree m, y of degree n; out of degree m + n) */
static void bracket(fmpz *out, const fmpz *x, int m, const fmpz *y, int n)
{
    _fmpz_vec_zero(out, (slong)1 << (m + n));
    for (ulong a = 0; a < (1UL << m); a++) {
        if (fmpz_is_zero(x + a)) continue;
        for (ulong b = 0; b < (1UL << n); b++) {
            if (fmpz_is_zero(y + b)) continue;
            fmpz_addmul(out + ((a << n) | b), x + a, y + b);
            fmpz_submul(out + ((b << m) | a), x + a, y + b);
        }
    }
}

/* cur (degree d, room for 2^n) <- [l_1, [l_2, ..., [l_m, cur]]] with l_i
 * bit i-1 of seq; returns the new degree. */
static int ad_letters(fmpz *cur, int d, ulong seq, int m, int n)
{
    fmpz *next = _fmpz_vec_init((slong)1 << n), *letter = _fmpz_vec_init(2);
    for (int i = m - 1; i >= 0; i--) {
        _fmpz_vec_zero(letter, 2);
        fmpz_one(letter + ((seq >> i) & 1));
        bracket(next, letter, 1, cur, d);
        d++;
        _fmpz_vec_set(cur, next, (slong)1 << d);
    }
    _fmpz_vec_clear(next, (slong)1 << n);
    _fmpz_vec_clear(letter, 2);
    return d;
}

/* The left-normed brackets [l_1, [l_2, ..., l_d]] of the letter sequences
 * with i letters A and i + 1 letters B, d = 2i + 1: they span the Lie
 * elements of p-degree 0 of that degree (functions of q only: B = V has
 * p-degree 0, each bracket with T adds one, each with V removes one).
 * Returns their number; rows (2^d entries each) into *out. */
static slong p0_elements(fmpz **out, int d)
{
    slong nw = (slong)1 << d, count = 0, i = (d - 1) / 2;
    *out = _fmpz_vec_init(nw * (1L << d));
    for (ulong seq = 0; seq < (1UL << d); seq++) {
        if ((slong)__builtin_popcountl(seq) != i + 1) continue;   /* bit set: B */
        fmpz *v = *out + count * nw;
        fmpz_one(v + (seq & 1));                    /* the last letter, then the others around it */
        ad_letters(v, 1, seq >> 1, d - 1, d);
        if (!_fmpz_vec_is_zero(v, nw)) count++;
        else _fmpz_vec_zero(v, nw);
    }
    return count;
}

/* Rows of integer vectors over the words of one degree (nw of them). */
typedef struct {
    fmpz *rows;
    slong nw, count, alloc;
} gen_rows;

static void push_row(gen_rows *g, const fmpz *v)
{
    if (g->count == g->alloc) {
        fmpz *grown = _fmpz_vec_init(2 * g->alloc * g->nw);
        _fmpz_vec_set(grown, g->rows, g->alloc * g->nw);
        _fmpz_vec_clear(g->rows, g->alloc * g->nw);
        g->rows = grown;
        g->alloc *= 2;
    }
    _fmpz_vec_set(g->rows + g->count++ * g->nw, v, g->nw);
}

/* The generators of U_n (mods as in design_internal.h) as rows of integer
 * vectors over the words of degree n, into g.
 *
 * Nystrom: T = p^2/2 and V(q) realise A and B as functions polynomial in p;
 * a Lie element with i letters A and j letters B has p-degree i + 1 - j, and
 * two elements of p-degree 0 (functions of q) commute.  The relations are
 * the ideal generated by [X, Y] for X, Y of p-degree 0; its degree n is
 * spanned by [l_1, ..., [l_m, [X, Y]]] with letters l (ad of a bracket is a
 * commutator of ad's).  [B,[B,[B,A]]] = [B, [B,[B,A]]] is the first (degree
 * 4); [[B,[B,A]], Y] with Y of degree 5 the next new one (degree 8).
 * Processed: [A + B, v] for v the left-normed brackets of n - 1 letters,
 * which span Lie_(n-1). */
static void generators(gen_rows *g, int n, unsigned mods)
{
    slong nw = (slong)1 << n;
    g->nw = nw;
    g->count = 0;
    g->alloc = 16;
    g->rows = _fmpz_vec_init(g->alloc * nw);
    fmpz *cur = _fmpz_vec_init(nw);
    if (mods & DESIGN_MOD_NYSTROM) {
        fmpz *p0[DESIGN_QUOTIENT_MAX_DEGREE + 1] = {0};
        slong np0[DESIGN_QUOTIENT_MAX_DEGREE + 1] = {0};
        for (int d = 1; d < n; d += 2) np0[d] = p0_elements(&p0[d], d);
        for (int dx = 1; dx < n; dx += 2)
            for (int dy = dx; dx + dy <= n; dy += 2)
                for (slong a = 0; a < np0[dx]; a++)
                    for (slong b = dx == dy ? a + 1 : 0; b < np0[dy]; b++) {
                        int m = n - dx - dy;
                        for (ulong seq = 0; seq < (1UL << m); seq++) {
                            _fmpz_vec_zero(cur, nw);
                            bracket(cur, p0[dx] + a * ((slong)1 << dx), dx, p0[dy] + b * ((slong)1 << dy), dy);
                            ad_letters(cur, dx + dy, seq, m, n);
                            if (_fmpz_vec_is_zero(cur, nw)) continue;
                            push_row(g, cur);
                        }
                    }
        for (int d = 1; d < n; d += 2)
            if (p0[d]) _fmpz_vec_clear(p0[d], ((slong)1 << d) * (1L << d));
    }
    if ((mods & DESIGN_MOD_PROCESSED) && n >= 2) {
        fmpz *sum = _fmpz_vec_init(2), *v = _fmpz_vec_init(nw);
        fmpz_one(sum + 0);
        fmpz_one(sum + 1);
        /* [A + B, [l_1, ..., [l_(n-2), last]]] */
        for (ulong seq = 0; seq < (1UL << (n - 2)); seq++)
            for (int last = 0; last < 2; last++) {
                _fmpz_vec_zero(v, nw);
                fmpz_one(v + last);
                int d = ad_letters(v, 1, seq, n - 2, n);
                bracket(cur, sum, 1, v, d);
                push_row(g, cur);
            }
        _fmpz_vec_clear(v, nw);
        _fmpz_vec_clear(sum, 2);
    }
    _fmpz_vec_clear(cur, nw);
}

/* The conditions of degree n into out (appended). */
static void degree_conditions(design_combos *out, int n, unsigned mods)
{
    slong nw = (slong)1 << n, nl = 0;
    ulong *lyndon = malloc((size_t)nw * sizeof(ulong));
    for (ulong w = 0; w < (ulong)nw; w++)
        if (is_lyndon_bits(w, n)) lyndon[nl++] = w;
    gen_rows gr = {NULL, nw, 0, 0};
    if (n >= 2) generators(&gr, n, mods);
    slong ng = gr.count;
    const fmpz *gen = gr.rows;
    fmpq_mat_t R;
    fmpq_mat_init(R, ng > 0 ? ng : 1, nl);
    for (slong g = 0; g < ng; g++)
        for (slong c = 0; c < nl; c++) {
            fmpz_set(fmpq_mat_entry_num(R, g, c), gen + g * nw + lyndon[c]);
            fmpz_one(fmpq_mat_entry_den(R, g, c));
        }
    slong rank = ng > 0 ? fmpq_mat_rref(R, R) : 0;
    slong *pivot = malloc((size_t)(rank + 1) * sizeof(slong));
    char *is_pivot = calloc((size_t)nl, 1);
    for (slong i = 0; i < rank; i++) {
        slong c = 0;
        while (fmpq_is_zero(fmpq_mat_entry(R, i, c))) c++;
        pivot[i] = c;
        is_pivot[c] = 1;
    }
    for (slong c = 0; c < nl; c++) {
        if (is_pivot[c]) continue;
        out->c = realloc(out->c, (size_t)(out->n + 1) * sizeof *out->c);
        design_combo *co = &out->c[out->n++];
        co->degree = n;
        co->word = malloc((size_t)(rank + 1) * sizeof(ulong));
        co->alloc = rank + 1;
        co->coef = _fmpq_vec_init(co->alloc);
        co->nterms = 0;
        co->word[co->nterms] = lyndon[c];
        fmpq_one(co->coef + co->nterms++);
        for (slong i = 0; i < rank; i++) {
            if (fmpq_is_zero(fmpq_mat_entry(R, i, c))) continue;
            co->word[co->nterms] = lyndon[pivot[i]];
            fmpq_neg(co->coef + co->nterms++, fmpq_mat_entry(R, i, c));
        }
    }
    free(pivot);
    free(is_pivot);
    fmpq_mat_clear(R);
    if (gr.rows) _fmpz_vec_clear(gr.rows, gr.alloc * nw);
    free(lyndon);
}

int design_quotient_conditions(design_combos *out, int p, int symmetric, unsigned mods)
{
    memset(out, 0, sizeof *out);
    if (p > DESIGN_QUOTIENT_MAX_DEGREE) return VIGEN_E_USAGE;
    for (int n = 1; n <= p; n++)
        if (!symmetric || n % 2 == 1) degree_conditions(out, n, mods);
    return VIGEN_OK;
}

slong design_quotient_count(int p, int symmetric, unsigned mods)
{
    design_combos c;
    if (design_quotient_conditions(&c, p, symmetric, mods) != VIGEN_OK) return -1;
    slong n = c.n;
    design_combos_clear(&c);
    return n;
}

void design_combos_clear(design_combos *c)
{
    for (slong i = 0; i < c->n; i++) {
        free(c->c[i].word);
        _fmpq_vec_clear(c->c[i].coef, c->c[i].alloc);
    }
    free(c->c);
    memset(c, 0, sizeof *c);
}

void design_quotient_processor(ulong *word, fmpq_t scale)
{
    /* g = [A+B, [A,B]], of degree 3 */
    fmpz *ab = _fmpz_vec_init(4), *g = _fmpz_vec_init(8), *a = _fmpz_vec_init(2), *b = _fmpz_vec_init(2),
         *sum = _fmpz_vec_init(2);
    fmpz_one(a + 0);
    fmpz_one(b + 1);
    fmpz_one(sum + 0);
    fmpz_one(sum + 1);
    bracket(ab, a, 1, b, 1);
    bracket(g, sum, 1, ab, 2);
    for (ulong w = 0; w < 8; w++)
        if (is_lyndon_bits(w, 3) && !fmpz_is_zero(g + w)) {
            *word = w;
            fmpq_set_si(scale, 1, 1);
            fmpq_div_fmpz(scale, scale, g + w);
            break;
        }
    _fmpz_vec_clear(ab, 4);
    _fmpz_vec_clear(g, 8);
    _fmpz_vec_clear(a, 2);
    _fmpz_vec_clear(b, 2);
    _fmpz_vec_clear(sum, 2);
}
