/* expr_quad.c — the arithmetic of a + b sqrt(d) in Q and in one real
 * quadratic field Q(sqrt d), with square roots of rationals by factoring
 * (the exact rule of sqrt in functions.def), giving up on values that
 * outgrow the size limits.  expr_exact.c walks trees with it. */
#include "core/expr_internal.h"
#include <flint/fmpz_factor.h>
#include <flint/ulong_extras.h>

/* Size beyond which a "rational" value is not worth treating as one. */
#define EXPR_RAT_MAX_BITS 65536

/* sqrt(p/q) is reduced to m sqrt(d)/q, d squarefree, by factoring p and q:
 * trial division by the primes below EXPR_QUAD_TRIAL_BOUND, then fmpz_factor
 * on a cofactor of at most EXPR_QUAD_MAX_FACTOR_BITS bits, which it factors
 * at once; a larger cofactor that is not a perfect square is refused rather
 * than factored slowly. */
#define EXPR_QUAD_TRIAL_BOUND 4096
#define EXPR_QUAD_MAX_FACTOR_BITS 64

void expr_quad_init(expr_quad *x)
{
    fmpq_init(x->a);
    fmpq_init(x->b);
    fmpz_init_set_ui(x->d, 1);
}

void expr_quad_clear(expr_quad *x)
{
    fmpq_clear(x->a);
    fmpq_clear(x->b);
    fmpz_clear(x->d);
}

static void quad_normalise(expr_quad *x)
{
    if (fmpq_is_zero(x->b)) fmpz_one(x->d);
}

static int fmpq_small(const fmpq_t q)
{
    return fmpz_bits(fmpq_numref(q)) <= EXPR_RAT_MAX_BITS && fmpz_bits(fmpq_denref(q)) <= EXPR_RAT_MAX_BITS;
}

int expr_quad_small(const expr_quad *x) { return fmpq_small(x->a) && fmpq_small(x->b); }

/* The field of x op y: d when both lie in Q(sqrt d) (one may be rational);
 * 0 when they need two different square roots. */
static int quad_field(fmpz_t d, const expr_quad *x, const expr_quad *y)
{
    if (fmpz_is_one(x->d)) fmpz_set(d, y->d);
    else if (fmpz_is_one(y->d) || fmpz_equal(x->d, y->d)) fmpz_set(d, x->d);
    else return 0;
    return 1;
}

/* res = x + sign y (sign = +1 or -1); res may alias x or y. */
int expr_quad_add(expr_quad *res, const expr_quad *x, const expr_quad *y, int sign)
{
    if (!quad_field(res->d, x, y)) return 0;
    if (sign > 0) {
        fmpq_add(res->a, x->a, y->a);
        fmpq_add(res->b, x->b, y->b);
    } else {
        fmpq_sub(res->a, x->a, y->a);
        fmpq_sub(res->b, x->b, y->b);
    }
    quad_normalise(res);
    return 1;
}

void expr_quad_swap(expr_quad *x, expr_quad *y)
{
    fmpq_swap(x->a, y->a);
    fmpq_swap(x->b, y->b);
    fmpz_swap(x->d, y->d);
}

/* res = x y = (x_a y_a + d x_b y_b) + (x_a y_b + x_b y_a) sqrt(d); res may alias. */
int expr_quad_mul(expr_quad *res, const expr_quad *x, const expr_quad *y)
{
    expr_quad r;
    expr_quad_init(&r);
    int ok = quad_field(r.d, x, y);
    if (ok) {
        fmpq_t t;
        fmpq_init(t);
        fmpq_mul(r.a, x->a, y->a);
        fmpq_mul(t, x->b, y->b);
        fmpq_mul_fmpz(t, t, r.d);
        fmpq_add(r.a, r.a, t);
        fmpq_mul(r.b, x->a, y->b);
        fmpq_mul(t, x->b, y->a);
        fmpq_add(r.b, r.b, t);
        fmpq_clear(t);
        quad_normalise(&r);
        expr_quad_swap(res, &r);
    }
    expr_quad_clear(&r);
    return ok;
}

/* x = 1/x = (a - b sqrt d)/(a^2 - d b^2); 0 when x = 0 (the norm vanishes
 * only then, d not being a square). */
int expr_quad_inv(expr_quad *x)
{
    if (fmpq_is_zero(x->a) && fmpq_is_zero(x->b)) return 0;
    fmpq_t nrm, t;
    fmpq_init(nrm);
    fmpq_init(t);
    fmpq_mul(nrm, x->a, x->a);
    fmpq_mul(t, x->b, x->b);
    fmpq_mul_fmpz(t, t, x->d);
    fmpq_sub(nrm, nrm, t);
    fmpq_div(x->a, x->a, nrm);
    fmpq_div(x->b, x->b, nrm);
    fmpq_neg(x->b, x->b);
    fmpq_clear(nrm);
    fmpq_clear(t);
    return 1;
}

/* m *= p^(e/2), d *= p^(e mod 2): the prime power p^e split into a square
 * and a squarefree part. */
static void square_part_add(fmpz_t m, fmpz_t d, const fmpz_t p, ulong e)
{
    fmpz_t t;
    fmpz_init(t);
    fmpz_pow_ui(t, p, e / 2);
    fmpz_mul(m, m, t);
    if (e % 2) fmpz_mul(d, d, p);
    fmpz_clear(t);
}

/* n = m^2 d with d squarefree, for n > 0.  The primes below
 * EXPR_QUAD_TRIAL_BOUND are divided out (10^60 = 2^60 5^60 is then done);
 * what is left must be a square or small enough to factor at once, else 0. */
static int square_part(fmpz_t m, fmpz_t d, const fmpz_t n)
{
    fmpz_t c, p;
    fmpz_init_set(c, n);
    fmpz_init(p);
    fmpz_one(m);
    fmpz_one(d);
    n_primes_t it;
    n_primes_init(it);
    for (ulong q = n_primes_next(it); q < EXPR_QUAD_TRIAL_BOUND && !fmpz_is_one(c); q = n_primes_next(it)) {
        fmpz_set_ui(p, q);
        slong e = fmpz_remove(c, c, p);
        if (e > 0) square_part_add(m, d, p, (ulong)e);
    }
    n_primes_clear(it);
    int ok = 1;
    fmpz_sqrtrem(p, c, c);   /* p = floor(sqrt(c)), c = the remainder */
    if (fmpz_is_zero(c)) fmpz_mul(m, m, p);
    else {
        fmpz_mul(p, p, p);
        fmpz_add(c, c, p);   /* the cofactor again */
        ok = fmpz_bits(c) <= EXPR_QUAD_MAX_FACTOR_BITS;
        if (ok) {
            fmpz_factor_t f;
            fmpz_factor_init(f);
            fmpz_factor(f, c);
            for (slong i = 0; i < f->num; i++) square_part_add(m, d, f->p + i, f->exp[i]);
            fmpz_factor_clear(f);
        }
    }
    fmpz_clear(c);
    fmpz_clear(p);
    return ok;
}

/* x = sqrt(x) for a rational x = p/q >= 0 in lowest terms: with p = m_p^2 d_p
 * and q = m_q^2 d_q, sqrt(p/q) = sqrt(p q)/q = m_p m_q sqrt(d_p d_q)/q, and
 * d_p d_q is squarefree since p and q are coprime (sqrt(2/3) = sqrt(6)/3;
 * sqrt(2/10^60) = sqrt(2)/10^30, the large q being a square). */
int expr_quad_sqrt(expr_quad *x)
{
    if (!fmpz_is_one(x->d) || fmpq_sgn(x->a) < 0) return 0;
    if (fmpq_is_zero(x->a)) return 1;
    fmpz_t mp, dp, mq, dq;
    fmpz_init(mp);
    fmpz_init(dp);
    fmpz_init(mq);
    fmpz_init(dq);
    int ok = square_part(mp, dp, fmpq_numref(x->a)) && square_part(mq, dq, fmpq_denref(x->a));
    if (ok) {
        expr_quad r;
        expr_quad_init(&r);
        fmpz_mul(mp, mp, mq);
        fmpq_set_fmpz_frac(r.b, mp, fmpq_denref(x->a));   /* m_p m_q / q */
        fmpz_mul(r.d, dp, dq);
        if (fmpz_is_one(r.d)) fmpq_swap(r.a, r.b);        /* a rational: the value itself */
        expr_quad_swap(x, &r);
        expr_quad_clear(&r);
    }
    fmpz_clear(mp);
    fmpz_clear(dp);
    fmpz_clear(mq);
    fmpz_clear(dq);
    return ok;
}

/* x = x^k by squaring, giving up as soon as a value outgrows the size limits. */
int expr_quad_pow(expr_quad *x, slong k)
{
    if (k < 0 && !expr_quad_inv(x)) return 0;
    ulong e = k < 0 ? (ulong)(-k) : (ulong)k;
    expr_quad r;
    expr_quad_init(&r);
    fmpq_one(r.a);
    int ok = 1;
    while (e && ok) {
        if (e & 1) ok = expr_quad_mul(&r, &r, x) && expr_quad_small(&r);
        e >>= 1;
        if (e && ok) ok = expr_quad_mul(x, x, x) && expr_quad_small(x);
    }
    if (ok) expr_quad_swap(x, &r);
    expr_quad_clear(&r);
    return ok;
}
