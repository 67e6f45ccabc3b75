/* stability.c — the linear stability interval of the method on the harmonic
 * oscillator q' = p, p' = -omega^2 q (check.h, vigen_check_stability).
 *
 * With x = h omega, y = x^2, p~ = p / omega and M = A At, the stages
 * Q = q0 1 + x A P~, P~ = p~0 1 - x At Q give (I + y M) Q = q0 1 + x p~0 A 1
 * and the step (q1, p~1) = R(x) (q0, p~0) with, for K = (I + y M)^-1,
 *   R11 = 1 - y b^T At K 1,          R12 = x (b^T 1 - y b^T At K A 1),
 *   R21 = -x bt^T K 1,               R22 = 1 - y bt^T K A 1.
 * K = adj / D with D(y) = det(I + y M) = sum_j c_j y^j, the c_j those of the
 * characteristic polynomial of N = -M, and adj(I + y M) = sum_j y^j B_j with
 * B_j = sum_{i<=j} c_(j-i) N^i (Faddeev-LeVerrier), so every entry is a
 * polynomial in y over D, computed without division.
 *
 * The step is stable when both eigenvalues of R lie in the closed unit disk,
 * for the 2x2 matrix (Jury): 1 - tr + det >= 0, 1 + tr + det >= 0, det <= 1.
 * A symplectic method has det R = 1 and the condition is |tr R| <= 2, i.e.
 * y G / D in [0, 4] with G = b^T At adj 1 + bt^T adj A 1.  The interval ends
 * at the first positive root, where a sign changes, of one of these
 * polynomials (or of D, a pole).  The roots are certified by arb: every
 * complex root isolated (acb_poly_find_roots, then acb_poly_validate_roots on
 * midpoints whose nearly real roots are put on the real axis: an isolating
 * box symmetric about the axis holds one root of a real polynomial, which is
 * then real), so each positive real root is simple and a sign change.
 * A symplectic RK method (At = A, bt = b) maps z = q + i p~ to r(-ix) z with
 * |r(ix)| = 1 (it preserves |z|^2): it is stable wherever D != 0, and the
 * trace condition, touched at double roots (Gauss), is not needed.
 */
#include "check/check_internal.h"
#include <acb_poly.h>
#include <arb_poly.h>

/* sum_j y^j sum_{i<=j} c_(j-i) u^T N^i v, for j < s: u^T adj(I + y M) v */
static void adj_poly(arb_poly_t out, const arb_mat_t N, const arb_poly_t ch, arb_srcptr u, arb_srcptr v, slong s,
                     slong prec)
{
    arb_ptr m = _arb_vec_init(s), w = _arb_vec_init(s), t = _arb_vec_init(s);
    _arb_vec_set(w, v, s);
    for (slong i = 0; i < s; i++) {
        arb_dot(m + i, NULL, 0, u, 1, w, 1, s, prec);   /* m_i = u^T N^i v */
        for (slong r = 0; r < s; r++) arb_dot(t + r, NULL, 0, arb_mat_entry(N, r, 0), 1, w, 1, s, prec);   /* N w */
        _arb_vec_set(w, t, s);
    }
    arb_poly_zero(out);
    arb_t acc, c;
    arb_init(acc);
    arb_init(c);
    for (slong j = 0; j < s; j++) {
        arb_zero(acc);
        for (slong i = 0; i <= j; i++) {
            arb_poly_get_coeff_arb(c, ch, s - (j - i));   /* c_(j-i): coefficient of lambda^(s-(j-i)) */
            arb_addmul(acc, c, m + i, prec);
        }
        arb_poly_set_coeff_arb(out, j, acc);
    }
    arb_clear(acc);
    arb_clear(c);
    _arb_vec_clear(m, s);
    _arb_vec_clear(w, s);
    _arb_vec_clear(t, s);
}

/* The positive real roots of p, each simple and certified, appended to
 * roots (sorted later).  Returns 0 when they cannot be certified (*why set):
 * a leading coefficient that may be 0, a lowest nonzero coefficient that may
 * be 0 (a root at 0 of unknown multiplicity), roots not isolated (a multiple
 * root, or two roots too close for the precision).  Exact zero coefficients
 * at the bottom are a root at y = 0, divided out.  *sign0: the sign of p just
 * right of 0 (+1, -1). */
static int positive_roots(arb_ptr roots, slong *nroots, const arb_poly_t p_in, int *sign0, slong prec,
                          const char **why)
{
    arb_poly_t p;
    arb_poly_init(p);
    arb_poly_set(p, p_in);
    slong len = arb_poly_length(p);
    int ok = 1;
    if (len == 0) {
        *why = "a stability polynomial may vanish identically";
        ok = 0;
        goto done;
    }
    slong low = 0;
    while (low < len && arb_is_zero(p->coeffs + low)) low++;
    arb_poly_shift_right(p, p, low);
    len = arb_poly_length(p);
    if (arb_contains_zero(p->coeffs + len - 1) || arb_contains_zero(p->coeffs)) {
        *why = "a coefficient of a stability polynomial cannot be told from 0 (degree or multiplicity at 0 "
               "unknown)";
        ok = 0;
        goto done;
    }
    *sign0 = arb_is_positive(p->coeffs) ? 1 : -1;
    slong deg = len - 1;
    if (deg == 0) goto done;
    {
        acb_poly_t q;
        acb_poly_init(q);
        acb_poly_set_arb_poly(q, p);
        acb_ptr z = _acb_vec_init(deg);
        acb_poly_find_roots(z, q, NULL, 0, prec);
        /* midpoints, nearly real ones on the axis */
        for (slong k = 0; k < deg; k++) {
            acb_get_mid(z + k, z + k);
            mag_t re, im;
            mag_init(re);
            mag_init(im);
            arf_get_mag(re, arb_midref(acb_realref(z + k)));
            arf_get_mag(im, arb_midref(acb_imagref(z + k)));
            mag_mul_2exp_si(re, re, -(prec / 2));
            if (mag_cmp(im, re) <= 0) arb_zero(acb_imagref(z + k));
            mag_clear(re);
            mag_clear(im);
        }
        slong isolated = _acb_poly_validate_roots(z, q->coeffs, q->length, prec);
        if (isolated < deg) {
            *why = "the roots of a stability polynomial could not be isolated (a multiple root, where |tr R| "
                   "touches 2, or roots closer than the precision)";
            ok = 0;
        }
        for (slong k = 0; ok && k < deg; k++) {
            /* a box centred on the axis (put there above): symmetric about it */
            if (!arf_is_zero(arb_midref(acb_imagref(z + k)))) {
                if (arb_contains_zero(acb_imagref(z + k))) {
                    *why = "a root of a stability polynomial could not be shown real or not real";
                    ok = 0;
                }
                continue;
            }
            if (arb_is_positive(acb_realref(z + k))) arb_set(roots + (*nroots)++, acb_realref(z + k));
            else if (!arb_is_negative(acb_realref(z + k))) {
                *why = "a real root of a stability polynomial cannot be told from 0";
                ok = 0;
            }
        }
        _acb_vec_clear(z, deg);
        acb_poly_clear(q);
    }
done:
    arb_poly_clear(p);
    return ok;
}

/* Entries rational with common denominator den: a coefficient that is a
 * polynomial of degree <= K in the entries is m / den^K for an integer m; a
 * ball of it that holds a single integer after multiplying by den^K is that
 * value (exactly 0 when m = 0, so that degrees and roots at 0 are certain). */
static void snap_rational(arb_poly_t p, const fmpz_t den, slong K, slong prec)
{
    fmpz_t dk, m;
    fmpz_init(dk);
    fmpz_init(m);
    fmpz_pow_ui(dk, den, (ulong)K);
    arb_t y;
    arb_init(y);
    for (slong k = 0; k < p->length; k++) {
        arb_mul_fmpz(y, p->coeffs + k, dk, prec);
        if (mag_cmp_2exp_si(arb_radref(y), -2) >= 0) continue;
        arf_get_fmpz(m, arb_midref(y), ARF_RND_NEAR);
        if (!arb_contains_fmpz(y, m)) continue;
        arb_set_fmpz(p->coeffs + k, m);
        arb_div_fmpz(p->coeffs + k, p->coeffs + k, dk, prec);
    }
    _arb_poly_normalise(p);
    arb_clear(y);
    fmpz_clear(dk);
    fmpz_clear(m);
}

/* out = a b - c d, or + when sign > 0 */
static void poly_muladd(arb_poly_t out, const arb_poly_t a, const arb_poly_t b, const arb_poly_t c,
                        const arb_poly_t d, int sign, slong prec)
{
    arb_poly_t t;
    arb_poly_init(t);
    arb_poly_mul(t, c, d, prec);
    arb_poly_mul(out, a, b, prec);
    if (sign > 0) arb_poly_add(out, out, t, prec);
    else arb_poly_sub(out, out, t, prec);
    arb_poly_clear(t);
}

/* Sets the coefficients of y^k, k < kmax, to exact 0 where their balls contain
 * 0 (a ball that excludes 0 is left: the caller's premise is then false).
 * Used for 1 - det R = O(y^((p+1)/2)) on a method of order p. */
static void zero_low(arb_poly_t p, slong kmax)
{
    for (slong k = 0; k < kmax && k < arb_poly_length(p); k++)
        if (arb_contains_zero(p->coeffs + k)) arb_zero(p->coeffs + k);
    _arb_poly_normalise(p);
}

int chk_stability(chk_round *rd, vigen_error *err)
{
    (void)err;
    vigen_check_report *rep = rd->rep;
    const ctx_t *cx = rd->cx;
    vigen_check_stability *st = &rep->stability;
    slong s = cx->s, prec = cx->prec;
    st->status = VIGEN_CHECK_STAB_UNDECIDED;
    st->reason = NULL;
    arb_zero(st->x);
    int symplectic = rep->symplectic == VIGEN_CHECK_YES || rep->symplectic_separable == VIGEN_CHECK_YES;
    /* one RK method for both parts: At = A and bt = b (the same balls) */
    int rk = arb_mat_equal(cx->A, cx->At);
    for (slong i = 0; i < s; i++) rk &= arb_equal(cx->b + i, cx->bt + i);

    arb_mat_t M, N;
    arb_mat_init(M, s, s);
    arb_mat_init(N, s, s);
    arb_mat_mul(M, cx->A, cx->At, prec);
    arb_mat_neg(N, M);
    arb_poly_t ch, D, al, be, ga, de, G, E, J1, J2, J3, t1, t2;
    arb_poly_init(ch);
    arb_poly_init(D);
    arb_poly_init(al);
    arb_poly_init(be);
    arb_poly_init(ga);
    arb_poly_init(de);
    arb_poly_init(G);
    arb_poly_init(E);
    arb_poly_init(J1);
    arb_poly_init(J2);
    arb_poly_init(J3);
    arb_poly_init(t1);
    arb_poly_init(t2);
    arb_mat_charpoly(ch, N, prec);
    for (slong j = 0; j <= s; j++) {
        arb_t c;
        arb_init(c);
        arb_poly_get_coeff_arb(c, ch, s - j);
        arb_poly_set_coeff_arb(D, j, c);
        arb_clear(c);
    }
    arb_ptr one = _arb_vec_init(s), a1 = _arb_vec_init(s), atb = _arb_vec_init(s);
    for (slong i = 0; i < s; i++) arb_one(one + i);
    for (slong i = 0; i < s; i++) {
        arb_dot(a1 + i, NULL, 0, arb_mat_entry(cx->A, i, 0), 1, one, 1, s, prec);      /* A 1 */
        arb_zero(atb + i);   /* (b^T At)_i */
        for (slong k = 0; k < s; k++) arb_addmul(atb + i, cx->b + k, arb_mat_entry(cx->At, k, i), prec);
    }
    adj_poly(al, N, ch, atb, one, s, prec);      /* b^T At adj 1 */
    adj_poly(be, N, ch, cx->bt, a1, s, prec);    /* bt^T adj A 1 */
    adj_poly(ga, N, ch, atb, a1, s, prec);       /* b^T At adj A 1 */
    adj_poly(de, N, ch, cx->bt, one, s, prec);   /* bt^T adj 1 */
    arb_t sb;
    arb_init(sb);
    for (slong i = 0; i < s; i++) arb_add(sb, sb, cx->b + i, prec);

    /* the polynomials whose first positive sign change ends the interval */
    arb_poly_struct *cand[4];
    int ncand = 0;
    arb_poly_add(G, al, be, prec);
    if (symplectic && rk) {
        cand[ncand++] = D;
    } else if (symplectic) {
        arb_poly_shift_left(t1, G, 1);             /* y G */
        arb_poly_scalar_mul_2exp_si(E, D, 2);      /* 4 D - y G */
        arb_poly_sub(E, E, t1, prec);
        cand[ncand++] = D;
        cand[ncand++] = G;
        cand[ncand++] = E;
    } else {
        /* J1 = (1 - tr + det) D^2 / y = y al be + (sb D - y ga) de */
        arb_poly_scalar_mul(t1, D, sb, prec);
        arb_poly_shift_left(t2, ga, 1);
        arb_poly_sub(t1, t1, t2, prec);            /* sb D - y ga */
        arb_poly_shift_left(t2, al, 1);
        poly_muladd(J1, t2, be, t1, de, 1, prec);
        /* J3 = (1 - det) D^2 / y = D G - y al be - (sb D - y ga) de */
        poly_muladd(J3, D, G, t2, be, -1, prec);
        arb_poly_mul(t2, t1, de, prec);
        arb_poly_sub(J3, J3, t2, prec);
        /* J2 = (1 + tr + det) D^2 = 4 D^2 - 2 y D G + y J1 ... written out */
        arb_poly_mul(J2, D, D, prec);
        arb_poly_scalar_mul_2exp_si(J2, J2, 2);
        arb_poly_mul(t2, D, G, prec);
        arb_poly_shift_left(t2, t2, 1);
        arb_poly_scalar_mul_2exp_si(t2, t2, 1);
        arb_poly_sub(J2, J2, t2, prec);
        arb_poly_shift_left(t2, J1, 1);
        arb_poly_add(J2, J2, t2, prec);
        /* a method of order p: det R = 1 + O(x^(p+1)), so J3 = O(y^((p+1)/2 - 1)) */
        int p = rep->orders[VIGEN_CHECK_SEPARABLE].level.value;
        zero_low(J3, (p + 1) / 2 + ((p + 1) % 2) - 1);
        cand[ncand++] = D;
        cand[ncand++] = J1;
        cand[ncand++] = J2;
        cand[ncand++] = J3;
    }
    /* rational entries: every coefficient is a polynomial of degree at most
     * 4 s + 8 in them (products of two factors of degree <= 2 s + 4) */
    if (cx->ex && !fmpz_is_zero(cx->ex->den) && fmpz_is_one(cx->ex->qd))
        for (int k = 0; k < ncand; k++) snap_rational(cand[k], cx->ex->den, 4 * s + 8, prec);
    arb_ptr roots = _arb_vec_init(4 * (2 * s + 4));
    slong nroots = 0;
    int ok = 1, unstable0 = 0, area = 0;
    for (int k = 0; k < ncand && ok; k++) {
        int sign0 = 1;
        /* 1 - det R exactly 0 for every h omega (a condition met with
         * equality, never a sign change): the step preserves area on the
         * oscillator although the tableau is not symplectic, e.g. a
         * reducible tableau whose reduced method is symplectic (Lobatto IIIB
         * alone, c = (0, 1), is the implicit midpoint rule with its stage
         * written twice) */
        if (cand[k] == J3 && arb_poly_length(J3) == 0) {
            area = 1;
            continue;
        }
        ok = positive_roots(roots, &nroots, cand[k], &sign0, prec, &st->reason);
        if (!ok && cand[k] == J3 && arb_poly_length(J3) > 0) {
            int all_zero = 1;
            for (slong i = 0; i < arb_poly_length(J3); i++) all_zero &= arb_contains_zero(J3->coeffs + i);
            if (all_zero)
                st->reason = "1 - det R may vanish for every h omega (the step may preserve area on the oscillator "
                             "although the tableau is not symplectic), which balls cannot show: give the entries "
                             "exactly (fractions, sqrt) to decide it";
        }
        /* D's sign does not matter (it cancels in D^2 and in G/D, E/D with the
         * sign of G and E right of 0); the others must start positive */
        if (ok && sign0 < 0 && cand[k] != D) unstable0 = 1;
    }
    if (!ok) st->status = VIGEN_CHECK_STAB_UNDECIDED;
    else if (unstable0) {
        st->status = VIGEN_CHECK_STAB_BOUNDED;
        arb_zero(st->x);
        st->reason = "unstable for every small h omega";
    } else if (nroots == 0) {
        st->status = VIGEN_CHECK_STAB_UNBOUNDED;
        st->reason = rk && symplectic ? "a symplectic RK method: |r(ix)| = 1, and det(I + x^2 A^2) has no positive root"
                     : area ? "det R = 1 for every h omega (exactly) and |tr R| < 2: no positive root of the "
                              "stability polynomials"
                            : "no positive root of the stability polynomials";
    } else {
        slong first = 0;
        for (slong k = 1; k < nroots; k++)
            if (arf_cmp(arb_midref(roots + k), arb_midref(roots + first)) < 0) first = k;
        int clear = 1;   /* the first root is below every other one */
        for (slong k = 0; k < nroots; k++)
            if (k != first && !arb_lt(roots + first, roots + k)) clear = 0;
        if (!clear) st->reason = "two stability polynomials have roots that cannot be told apart";
        else {
            st->status = VIGEN_CHECK_STAB_BOUNDED;
            arb_sqrt(st->x, roots + first, prec);
            st->reason = area ? "det R = 1 for every h omega (exactly); the first sign change of 2 -+ tr R"
                              : "the first sign change of a stability polynomial";
        }
    }
    _arb_vec_clear(roots, 4 * (2 * s + 4));
    arb_clear(sb);
    _arb_vec_clear(one, s);
    _arb_vec_clear(a1, s);
    _arb_vec_clear(atb, s);
    arb_poly_clear(ch);
    arb_poly_clear(D);
    arb_poly_clear(al);
    arb_poly_clear(be);
    arb_poly_clear(ga);
    arb_poly_clear(de);
    arb_poly_clear(G);
    arb_poly_clear(E);
    arb_poly_clear(J1);
    arb_poly_clear(J2);
    arb_poly_clear(J3);
    arb_poly_clear(t1);
    arb_poly_clear(t2);
    arb_mat_clear(M);
    arb_mat_clear(N);
    return VIGEN_OK;
}
