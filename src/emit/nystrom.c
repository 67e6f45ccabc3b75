/* nystrom.c — the PRK variant's mechanical implicit step: the Nystrom form
 * of the tableau and the C lines of its blocks.
 *
 * For H = 1/2 p^T M^-1 p + V(t, q), the PRK stage gradients are
 * F_j = M^-1 P_j and G_j = -f_j, with f_j = f(t0 + c_j h, Q_j) the force at
 * stage j.  Substituting P_j = p + h sum_k at_jk f_k into
 * Q_i = q + h sum_j a_ij F_j and q1 = q + h sum_j b_j F_j gives, with
 * v = M^-1 p,
 *     Q_i = q + h (sum_j a_ij) v + h^2 M^-1 sum_k (A At)_ik f_k,
 *     q1  = q + h (sum_j b_j) v  + h^2 M^-1 sum_k (b^T At)_k f_k,
 *     p1  = p + h sum_k bt_k f_k:
 * stage unknowns for the positions only, one force per stage and sweep.
 * The row sums, A At, sum b and b^T At are computed here in ball arithmetic
 * from the tableau's balls and rounded like every other coefficient. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "emit/prk.h"
#include "support/strbuf.h"

static char **strv0(slong n)
{
    char **v = calloc((size_t)(n > 0 ? n : 1), sizeof *v);
    if (v == NULL) abort();
    return v;
}

void vigen_emit_nys_clear(nys_coefs *Y, slong s)
{
    char **vs[3] = { Y->ca, Y->bat, Y->aat };
    slong ns[3] = { s, s, s * s };
    for (int k = 0; k < 3; k++) {
        if (vs[k] == NULL) continue;
        for (slong i = 0; i < ns[k]; i++) free(vs[k][i]);
        free(vs[k]);
    }
    if (Y->inv1)
        for (slong i = 0; i < s; i++) free(Y->inv1[i]);
    free(Y->inv1);
    free(Y->sb);
    memset(Y, 0, sizeof *Y);
}

int vigen_emit_nys_round(nys_coefs *Y, emit_ctx *E)
{
    slong s = E->s;
    memset(Y, 0, sizeof *Y);
    Y->ca = strv0(s);
    Y->bat = strv0(s);
    Y->aat = strv0(s * s);
    arb_t x;
    arb_init(x);
    arb_mat_t P;
    arb_mat_init(P, s, s);
    arb_mat_mul(P, E->A, E->At, E->prec);
    int rc = VIGEN_OK;
    for (slong i = 0; i < s && rc == VIGEN_OK; i++) {
        arb_zero(x);
        for (slong j = 0; j < s; j++) arb_add(x, x, arb_mat_entry(E->A, i, j), E->prec);
        rc = vigen_emit_literal(Y->ca + i, E, x, -1, "sum_j A[i][j] (Nystrom)");
    }
    for (slong i = 0; i < s && rc == VIGEN_OK; i++)
        for (slong j = 0; j < s && rc == VIGEN_OK; j++)
            rc = vigen_emit_literal(Y->aat + i * s + j, E, arb_mat_entry(P, i, j), -1, "(A At)[i][j] (Nystrom)");
    if (rc == VIGEN_OK) {
        arb_zero(x);
        for (slong j = 0; j < s; j++) arb_add(x, x, E->b + j, E->prec);
        rc = vigen_emit_literal(&Y->sb, E, x, -1, "sum b (Nystrom)");
    }
    for (slong k = 0; k < s && rc == VIGEN_OK; k++) {
        arb_zero(x);
        for (slong i = 0; i < s; i++) arb_addmul(x, E->b + i, arb_mat_entry(E->At, i, k), E->prec);
        rc = vigen_emit_literal(Y->bat + k, E, x, -1, "(b^T At)[k] (Nystrom)");
    }
    /* the start force: a node at 1 besides distinct c_j, none of them 1 */
    int distinct = s >= 2;
    for (slong i = 0; i < s && distinct; i++) {
        arb_sub_ui(x, E->c + i, 1, E->prec);
        if (arb_contains_zero(x)) distinct = 0;
        for (slong j = 0; j < i && distinct; j++)
            if (arb_overlaps(E->c + i, E->c + j)) distinct = 0;
    }
    if (distinct && rc == VIGEN_OK) {
        Y->inv1 = strv0(s);
        for (slong j = 0; j < s && rc == VIGEN_OK; j++) {
            arb_sub_ui(x, E->c + j, 1, E->prec);
            arb_inv(x, x, E->prec);
            rc = vigen_emit_literal(Y->inv1 + j, E, x, -1, "1/(c_j - 1)");
        }
    }
    arb_mat_clear(P);
    arb_clear(x);
    return rc;
}

static int same_literal(const char *a, const char *b)
{
    return a == b || (a && b && strcmp(a, b) == 0);
}

int vigen_emit_nys_fsal(const prk_coefs *K)
{
    const nys_coefs *Y = &K->Y;
    const slong s = K->s;
    char *c1 = vigen_emit_times(K->c[0], "h"), *cs = vigen_emit_times(K->c[s - 1], "h");
    int fsal = s >= 2 && c1 == NULL && cs && strcmp(cs, "h") == 0 && Y->ca[0] == NULL
               && same_literal(Y->ca[s - 1], Y->sb) && !vigen_emit_colused(Y->aat, s, s - 1) && Y->bat[s - 1] == NULL;
    for (slong j = 0; j < s && fsal; j++)
        fsal = Y->aat[j] == NULL && same_literal(Y->aat[(s - 1) * s + j], Y->bat[j]);
    free(c1);
    free(cs);
    return fsal;
}

/* "<a> * <x> + <b> * <y>" where each part may be missing; "0" when both are. */
static char *sum2(char *a, char *b)
{
    char *r = a && b ? vigen_strdup_printf("%s + %s", a, b) : vigen_strdup(a ? a : b ? b : "0");
    free(a);
    free(b);
    return r;
}

/* hv * ca + m * (sum_k row_k x<k>): the increment of a position, with
 * hv = h v[k] and m = h^2 M^-1[k] in the generated loops. */
static char *increment(const char *ca, char *const *row, slong s, const char *pre, const char *post)
{
    char *a = ca ? vigen_emit_times(ca, "hv") : NULL;
    char *sum = vigen_emit_lin(row, s, pre, post);
    char *b = sum ? vigen_strdup_printf("m * (%s)", sum) : NULL;
    free(sum);
    return sum2(a, b);
}

/* The fixed-point sweep on stage bases: stage i's position is
 * base_i + m * (sum_j (A At)_ij x_j), base_i = qk + ca_i * hv formed once
 * per step into w->F[i-1] (qk itself when ca_i = 0) -- the same sums, in
 * the same order, as the one-expression form of increment(), so the same
 * bits. */
static void nys_base_code(vigen_slots *S, const nys_coefs *Y, slong s, int lagrange, int fsal, const char *R,
                          const char *N)
{
    /* first same as last: the last stage's position is q1, whose force is
     * taken at the new q after the solve; no sweep moves it */
    const slong swept = fsal ? s - 1 : s;
    vigen_slot *bp = vigen_slots_lines(S, "NYS_BASE_POINTERS");
    vigen_slot *st = vigen_slots_lines(S, "NYS_START");
    vigen_slot *sf = vigen_slots_lines(S, "NYS_START_F");
    vigen_slot *sx = vigen_slots_lines(S, "NYS_START_FO");
    vigen_slot *xl = vigen_slots_lines(S, "NYS_XW_LOAD");
    vigen_slot *sw = vigen_slots_lines(S, "NYS_SWEEP");
    char **wrow = strv0(s);
    for (slong j = 1; j <= s; j++) {
        if (!vigen_emit_colused(Y->aat, s, j - 1)) continue;
        vigen_slot_line(sw, "const %s x%ld = f%ld[k];", R, j, j);
        /* unused when no stage is swept (Lobatto IIIA-IIIB s = 2: velocity Verlet) */
        if (swept < s) vigen_slot_line(sw, "(void)x%ld;", j);
        vigen_slot_line(sf, "const %s x%ld = f%ld[k];", R, j, j);
        if (!lagrange) continue;
        /* the extrapolated start force of stage j, as MECH_EXTRAP_APPLY
         * forms it (the same sum: the same bits), not stored */
        for (slong l = 1; l <= s; l++) {
            vigen_slot_line(xl, "const %s w%ld_%ld = xw[%ld];", R, j, l, (long)((j - 1) * s + l - 1));
            wrow[l - 1] = vigen_strdup_printf("w%ld_%ld", j, l);
        }
        char *fo = vigen_emit_lin(wrow, s, "fo", "[k]");
        vigen_slot_line(sx, "const %s x%ld = %s;", R, j, fo);
        free(fo);
        for (slong l = 0; l < s; l++) free(wrow[l]);
    }
    free(wrow);
    for (slong j = 1; lagrange && j <= s; j++)
        vigen_slot_line(bp, "const %s *const fo%ld = w->Go[%ld];", R, j, j - 1);
    for (slong i = 1; i <= s; i++) {
        const char *ca = Y->ca[i - 1];
        char *sum = vigen_emit_lin(Y->aat + (i - 1) * s, s, "x", "");
        char *base = ca ? vigen_emit_times(ca, "hv") : NULL;
        if (base) {
            vigen_slot_line(bp, "%s *const b%ld = w->F[%ld];", R, i, i - 1);
            vigen_slot_line(st, "const %s u%ld = qk + %s;", R, i, base);
            vigen_slot_line(st, "b%ld[k] = u%ld;", i, i);
        }
        char *u = base ? vigen_strdup_printf("u%ld", i) : vigen_strdup("qk");
        char *b = base ? vigen_strdup_printf("b%ld[k]", i) : vigen_strdup("q[k]");
        if (sum) {
            vigen_slot_line(st, "const %s y%ld = %s + m * (%s);", R, i, u, sum);
            if (i <= swept) vigen_slot_line(sw, "const %s y%ld = %s + m * (%s);", R, i, b, sum);
        } else {
            /* no term at all: q + 0, as increment() writes it (-0 becomes
             * +0), set at the start and never moved by a sweep */
            vigen_slot_line(st, "const %s y%ld = %s%s;", R, i, u, base ? "" : " + 0");
            if (base && i <= swept) vigen_slot_line(sw, "const %s y%ld = %s;", R, i, b);
        }
        if ((sum || base) && i <= swept) {
            vigen_slot_line(sw, "dq = %s_inc_add(dq, y%ld - Q%ld[k]);", N, i, i);
            vigen_slot_line(sw, "Q%ld[k] = y%ld;", i, i);
        }
        free(u);
        free(b);
        free(base);
        free(sum);
    }
}

void vigen_emit_nys_batch_code(vigen_slots *S, const prk_coefs *K, const char *N)
{
    /* first same as last: the last stage is not swept (nys_base_code) */
    const slong s = K->s, swept = vigen_emit_nys_fsal(K) ? s - 1 : s;
    vigen_slot *sw = vigen_slots_lines(S, "MECH_SWEEP_STORE");
    for (slong i = 1; i <= swept; i++) vigen_slot_line(sw, "dq = %s_inc_add(dq, y%ld - Q%ld[k]);", N, i, i);
    for (slong i = 1; i <= swept; i++) vigen_slot_line(sw, "Q%ld[k] = y%ld;", i, i);
    if (swept < s) vigen_slot_line(sw, "(void)y%ld;", (long)s);
}

void vigen_emit_nys_code(vigen_slots *S, const prk_coefs *K, const char *N, int real)
{
    const char *R = vigen_emit_reals[real].ctype;
    const nys_coefs *Y = &K->Y;
    slong s = K->s;
    vigen_slot *ptr = vigen_slots_lines(S, "MECH_POINTERS");
    vigen_slot *fc = vigen_slots_lines(S, "MECH_FORCES");
    vigen_slot *st = vigen_slots_lines(S, "MECH_STAGES");
    vigen_slot *ss = vigen_slots_lines(S, "MECH_START_STORE");
    vigen_slot *nb = vigen_slots_lines(S, "MECH_NEWTON_BLOCKS");
    vigen_slot *nr = vigen_slots_lines(S, "MECH_NEWTON_RHS");
    vigen_slot *nu = vigen_slots_lines(S, "MECH_NEWTON_UPDATE");
    /* a stage at q itself (no term: Lobatto's first) has the same force in
     * every sweep: evaluated once, before them */
    vigen_slot *cf = vigen_slots_lines(S, "NYS_CONST_FORCES");
    slong nconst = 0;
    /* first same as last (vigen_emit_nys_fsal): the first stage's force is the previous
     * step's last, at the same t and q, when there is one; the last
     * stage's force is not evaluated in the sweeps (it enters no stage) but
     * once at the new q, by @NAME@_mech_implicit (NYS_END_FORCE) */
    const int fsal = vigen_emit_nys_fsal(K);
    vigen_slots_flag(S, "NYS_FSAL", fsal);
    vigen_slots_textf(S, "NYS_END_FORCE", "%s_force(w, t1, q, w->G[%ld]);", N, (long)(s - 1));
    vigen_slots_textf(S, "NYS_LAST", "%ld", (long)(s - 1));
    for (slong i = 1; i <= s; i++) {
        char *ti = vigen_emit_at_time(K->c[i - 1]);
        int fixed = Y->ca[i - 1] == NULL;
        for (slong j = 0; j < s && fixed; j++) fixed = Y->aat[(i - 1) * s + j] == NULL;
        nconst += fixed;
        vigen_slot_line(ptr, "%s *const Q%ld = w->Q[%ld];", R, i, i - 1);
        if (vigen_emit_colused(Y->aat, s, i - 1)) vigen_slot_line(ptr, "const %s *const f%ld = w->G[%ld];", R, i, i - 1);
        if (fsal && i == 1) {
            vigen_slot_line(cf, "%s_first_force(w, t0, Q1);", N);
        } else if (!(fsal && i == s)) {
            vigen_slot_line(fixed ? cf : fc, "%s_force(w, %s, Q%ld, w->G[%ld]);", N, ti, i, i - 1);
        }
        free(ti);
    }
    if (fsal)
        vigen_slots_textf(S, "NYS_FORCE_COUNT", "%ld * sweeps", (long)(s - nconst - 1));
    else
        vigen_slots_textf(S, "NYS_FORCE_COUNT", "%ld * sweeps + %ld", (long)(s - nconst), (long)nconst);
    for (slong j = 1; j <= s; j++)
        if (vigen_emit_colused(Y->aat, s, j - 1)) vigen_slot_line(st, "const %s x%ld = f%ld[k];", R, j, j);
    for (slong i = 1; i <= s; i++) {
        char *inc = increment(Y->ca[i - 1], Y->aat + (i - 1) * s, s, "x", "");
        vigen_slot_line(st, "const %s y%ld = qk + %s;", R, i, inc);
        free(inc);
        vigen_slot_line(ss, "Q%ld[k] = y%ld;", i, i);
        vigen_slot_line(ss, "d = %s_abs(y%ld); sq = d > sq ? d : sq;", N, i);
        vigen_slot_line(nr, "rhs[%ld * n + k] = (double)(y%ld - Q%ld[k]);", i - 1, i, i);
        vigen_slot_line(nu, "d = (%s)rhs[%ld * n + k];", R, i - 1);
        vigen_slot_line(nu, "Q%ld[k] += d;", i);
        vigen_slot_line(nu, "dq = %s_inc_add(dq, d);", N);
        vigen_slot_line(nu, "sq = %s_max(sq, %s_abs(Q%ld[k]));", N, N, i);
    }
    nys_base_code(S, Y, s, K->lagrange, fsal, R, N);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++)
            if (Y->aat[i * s + j])
                vigen_slot_line(nb, "vigen_newton_matrix_block(w->nw, %ld, %ld, (double)(h2 * %s), 0.0);", (long)i,
                                (long)j, Y->aat[i * s + j]);

    /* starting forces: extrapolated, copied, or the force at (t0, q) */
    vigen_slot *ip = vigen_slots_lines(S, "MECH_IMPLICIT_POINTERS");
    vigen_slot *ea = vigen_slots_lines(S, "MECH_EXTRAP_APPLY");
    vigen_slot *ec = vigen_slots_lines(S, "MECH_EXTRAP_COPY");
    vigen_slot *sc = vigen_slots_lines(S, "MECH_START_COPIES");
    vigen_slot *xs = vigen_slots_lines(S, "MECH_XW_STORE");
    vigen_slot *xa = vigen_slots_lines(S, "MECH_XW_LOAD");
    char **wrow = strv0(s);
    for (slong i = 1; i <= s; i++) {
        vigen_slot_line(ip, "%s *const f%ld = w->G[%ld];", R, i, i - 1);
        vigen_slot_line(ip, "const %s *const fo%ld = w->Go[%ld];", R, i, i - 1);
        vigen_slot_line(ec, "memcpy(f%ld, fo%ld, n * sizeof(%s));", i, i, R);
        if (i >= 2) vigen_slot_line(sc, "memcpy(f%ld, f1, n * sizeof(%s));", i, R);
        if (!K->lagrange) continue;
        for (slong j = 1; j <= s; j++) {
            vigen_slot_line(xs, "w->xw[%ld] = w%ld_%ld;", (long)((i - 1) * s + j - 1), i, j);
            vigen_slot_line(xa, "const %s w%ld_%ld = xw[%ld];", R, i, j, (long)((i - 1) * s + j - 1));
            wrow[j - 1] = vigen_strdup_printf("w%ld_%ld", i, j);
        }
        char *fo = vigen_emit_lin(wrow, s, "fo", "[k]");
        vigen_slot_line(ea, "f%ld[k] = %s;", i, fo);
        free(fo);
        for (slong j = 0; j < s; j++) free(wrow[j]);
    }
    free(wrow);

    /* the start force f(t0, q) in fe as node 1 (the end of the previous
     * step): the weights of the s + 1 nodes are those of the s nodes times
     * (x_i - 1)/(c_j - 1), and for node 1 the product of (x_i - c_m)/(1 - c_m) */
    vigen_slots_flag(S, "MECH_START_FORCE", Y->inv1 != NULL);
    vigen_slot *fw = vigen_slots_lines(S, "MECH_FORCE_WEIGHTS");
    vigen_slot *fa = vigen_slots_lines(S, "MECH_FORCE_APPLY");
    for (slong i = 1; Y->inv1 && i <= s; i++) {
        vigen_strbuf e;
        vigen_strbuf_init(&e);
        for (slong j = 1; j <= s; j++) {
            vigen_slot_line(fw, "const %s u%ld_%ld = w%ld_%ld * (x%ld - 1) * %s;", R, i, j, i, j, i, Y->inv1[j - 1]);
            vigen_strbuf_printf(&e, "%s(x%ld - %s) * %s", e.len ? " * " : "", i, K->c[j - 1], Y->inv1[j - 1]);
        }
        /* 1/(1 - c_m) = -1/(c_m - 1): the sign of the product of s of them */
        vigen_slot_line(fw, "const %s u%ld_e = %s%s%s;", R, i, s % 2 ? "-(" : "", e.data, s % 2 ? ")" : "");
        vigen_strbuf_clear(&e);
        vigen_strbuf_init(&e);
        for (slong j = 1; j <= s; j++) vigen_strbuf_printf(&e, "u%ld_%ld * fo%ld[k] + ", i, j, j);
        vigen_slot_line(fa, "f%ld[k] = %su%ld_e * fe[k];", i, e.data, i);
        vigen_strbuf_clear(&e);
    }

    /* the new state */
    char *uq = increment(Y->sb, Y->bat, s, "f", "[k]");
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    for (slong j = 0; j < s; j++)
        if (K->bt[j]) vigen_strbuf_printf(&sb, "%s%s * f%ld[k]", sb.len ? " + " : "", K->bt[j], (long)(j + 1));
    char *up = sb.data ? vigen_strdup_printf("h * (%s)", sb.data) : vigen_strdup("0");
    vigen_strbuf_clear(&sb);
    vigen_slots_text(S, "MECH_UPDATE_Q", uq);
    vigen_slots_text(S, "MECH_UPDATE_P", up);
    free(uq);
    free(up);
}
