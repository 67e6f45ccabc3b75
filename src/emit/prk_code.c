/* prk_code.c — the PRK variant's slot builder, second half: the C lines of
 * the stepper's blocks (stage loops, Newton blocks, extrapolation, the
 * explicit step) and the flags of its sections, from the rounded
 * coefficients of prk_data.c.  Every line is written here, the templates
 * only place them. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "emit/prk.h"
#include "support/strbuf.h"

/* ------------------------------------------------------ expression texts */

/* Whether a literal is exactly +1 or a (signed) power of two, read from its
 * text: multiplying by 1 is left out and a common power-of-two factor is
 * taken out of a sum, both exact.  The float128 spelling of a power of two
 * other than 1 is left as it is. */
static int is_one(const char *c)
{
    if (*c == '(') c++;
    while (*c == '_' || *c == ' ' || (*c >= 'A' && *c <= 'Z') || (*c >= 'a' && *c <= 'z')) c++;
    if (strncmp(c, "0x1p+0", 6) != 0) return 0;
    c += 6;
    if (*c == 'L' || *c == 'Q') c++;
    if (*c == ')') c++;
    return *c == '\0';
}

static int is_pow2(const char *c)
{
    if (*c == '(') c++;
    if (*c == '-') c++;
    if (strncmp(c, "0x1p", 4) != 0) return 0;
    c += 4;
    if (*c != '-' && *c != '+') return 0;
    c++;
    if (!(*c >= '0' && *c <= '9')) return 0;
    while (*c >= '0' && *c <= '9') c++;
    if (*c == 'L' || *c == 'Q') c++;
    if (*c == ')') c++;
    return *c == '\0';
}

/* coef * x (heap), x alone for an exact 1, NULL for "0". */
char *vigen_emit_times(const char *coef, const char *x)
{
    if (strcmp(coef, "0") == 0) return NULL;
    if (is_one(coef)) return vigen_strdup(x);
    return vigen_strdup_printf("%s * %s", coef, x);
}

/* "t0 + c h" for a node c, "t0" when it is 0. */
char *vigen_emit_at_time(const char *c)
{
    char *d = vigen_emit_times(c, "h");
    char *r = d ? vigen_strdup_printf("t0 + %s", d) : vigen_strdup("t0");
    free(d);
    return r;
}

/* "c1 * <pre>1<post> + c2 * <pre>2<post> ..." over the nonzero coefficients
 * (NULL entries); NULL when there are none. */
char *vigen_emit_lin(char *const *coefs, slong n, const char *pre, const char *post)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    for (slong j = 0; j < n; j++) {
        if (coefs[j] == NULL) continue;
        vigen_strbuf_printf(&sb, "%s%s * %s%ld%s", sb.len ? " + " : "", coefs[j], pre, (long)(j + 1), post);
    }
    return sb.data;
}

typedef struct {
    const char *coef;
    char src[40];
} hterm;

/* h times the sum of the terms; when every coefficient is the same power of
 * two c, written (c * h) * (x1 + x2 + ...): the same value bit for bit with
 * one multiplication per element instead of one per term. */
static char *hterms(const hterm *l, slong n)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "");
    int same = n > 0 && is_pow2(l[0].coef);
    for (slong k = 0; k < n && same; k++)
        if (strcmp(l[k].coef, l[0].coef) != 0) same = 0;
    if (!same) {
        vigen_strbuf_append(&sb, "h * (");
        for (slong k = 0; k < n; k++) vigen_strbuf_printf(&sb, "%s%s * %s", k ? " + " : "", l[k].coef, l[k].src);
        vigen_strbuf_append(&sb, ")");
        return sb.data;
    }
    char *ch = vigen_emit_times(l[0].coef, "h");
    if (strcmp(ch, "h") == 0) vigen_strbuf_append(&sb, "h");
    else vigen_strbuf_printf(&sb, "(%s)", ch);
    free(ch);
    if (n == 1) {
        vigen_strbuf_printf(&sb, " * %s", l[0].src);
        return sb.data;
    }
    vigen_strbuf_append(&sb, " * (");
    for (slong k = 0; k < n; k++) vigen_strbuf_printf(&sb, "%s%s", k ? " + " : "", l[k].src);
    vigen_strbuf_append(&sb, ")");
    return sb.data;
}

/* h times the sum of v_j <prefix>j[k] over the nonzero v_j; NULL if none. */
static char *hsum_vec(char *const *v, slong s, const char *prefix)
{
    hterm *l = calloc((size_t)s, sizeof *l);
    if (l == NULL) abort();
    slong n = 0;
    for (slong j = 0; j < s; j++) {
        if (v[j] == NULL) continue;
        l[n].coef = v[j];
        snprintf(l[n++].src, sizeof l[0].src, "%s%ld[k]", prefix, (long)(j + 1));
    }
    char *r = n > 0 ? hterms(l, n) : NULL;
    free(l);
    return r;
}

/* h times the sum of the terms of an explicit operation (shared with
 * batch.c). */
char *vigen_emit_hsum_op(const emit_xop *op)
{
    hterm *l = calloc((size_t)(op->nterms > 0 ? op->nterms : 1), sizeof *l);
    if (l == NULL) abort();
    for (slong k = 0; k < op->nterms; k++) {
        l[k].coef = op->terms[k].coef;
        snprintf(l[k].src, sizeof l[k].src, "X%ld[k]", op->terms[k].src);
    }
    char *r = hterms(l, op->nterms);
    free(l);
    return r;
}

/* Whether column j of m has a nonzero entry (the stage's gradient is read). */
int vigen_emit_colused(char *const *m, slong s, slong j)
{
    for (slong i = 0; i < s; i++)
        if (m[i * s + j]) return 1;
    return 0;
}

/* "<base> + h * (sum)" / "<base> - h * (sum)", or base alone. */
static char *stage_sum(const char *base, char sign, char *const *row, slong s, const char *pre, const char *post)
{
    char *sum = vigen_emit_lin(row, s, pre, post);
    char *r = sum ? vigen_strdup_printf("%s %c h * (%s)", base, sign, sum) : vigen_strdup(base);
    free(sum);
    return r;
}

/* ---------------------------------------------------------- the implicit path */

static void implicit_blocks(vigen_slots *S, const prk_coefs *K, const char *N, const char *R)
{
    slong s = K->s;
    vigen_slot *sw = vigen_slots_lines(S, "SWEEP_EVALS");
    vigen_slot *ptr = vigen_slots_lines(S, "STAGE_POINTERS");
    vigen_slot *fg = vigen_slots_lines(S, "FP_G_EVALS");
    vigen_slot *ff = vigen_slots_lines(S, "FP_F_EVALS");
    for (slong i = 1; i <= s; i++) {
        char *ti = vigen_emit_at_time(K->c[i - 1]);
        vigen_slot_line(sw, "%s_dHdp(w, %s, w->Q[%ld], w->P[%ld], w->F[%ld]);", N, ti, i - 1, i - 1, i - 1);
        vigen_slot_line(sw, "%s_dHdq(w, %s, w->Q[%ld], w->P[%ld], w->G[%ld]);", N, ti, i - 1, i - 1, i - 1);
        vigen_slot_line(ptr, "%s *const Q%ld = w->Q[%ld], *const P%ld = w->P[%ld];", R, i, i - 1, i, i - 1);
        if (vigen_emit_colused(K->a, s, i - 1)) vigen_slot_line(ptr, "const %s *const F%ld = w->F[%ld];", R, i, i - 1);
        if (vigen_emit_colused(K->at, s, i - 1)) vigen_slot_line(ptr, "const %s *const G%ld = w->G[%ld];", R, i, i - 1);
        vigen_slot_line(fg, "%s_dHdq(w, %s, Q%ld, P%ld, w->G[%ld]);", N, ti, i, i, i - 1);
        vigen_slot_line(ff, "%s_dHdp(w, %s, Q%ld, P%ld, w->F[%ld]);", N, ti, i, i, i - 1);
        free(ti);
    }

    /* fixed point: the starting stage values, then the two half sweeps */
    vigen_slot *st = vigen_slots_lines(S, "FP_START");
    for (slong i = 1; i <= s; i++) {
        char *v = stage_sum("qk", '+', K->a + (i - 1) * s, s, "F", "[k]");
        char *u = stage_sum("pk", '-', K->at + (i - 1) * s, s, "G", "[k]");
        vigen_slot_line(st, "const %s v%ld = %s;", R, i, v);
        vigen_slot_line(st, "const %s u%ld = %s;", R, i, u);
        free(v);
        free(u);
    }
    for (slong i = 1; i <= s; i++) {
        vigen_slot_line(st, "Q%ld[k] = v%ld;", i, i);
        vigen_slot_line(st, "P%ld[k] = u%ld;", i, i);
        vigen_slot_line(st, "d = %s_abs(v%ld); sq = d > sq ? d : sq;", N, i);
        vigen_slot_line(st, "d = %s_abs(u%ld); sp = d > sp ? d : sp;", N, i);
    }
    static const struct { const char *slot, *load, *grad, *var, *base, *inc, *arr; char sign; int q; } half[] = {
        { "FP_P_SWEEP", "g", "G", "u", "pk", "dp", "P", '-', 0 },
        { "FP_Q_SWEEP", "f", "F", "v", "qk", "dq", "Q", '+', 1 },
    };
    for (int h = 0; h < 2; h++) {
        vigen_slot *b = vigen_slots_lines(S, half[h].slot);
        char *const *m = half[h].q ? K->a : K->at;
        for (slong i = 1; i <= s; i++)
            if (vigen_emit_colused(m, s, i - 1)) vigen_slot_line(b, "const %s %s%ld = %s%ld[k];", R, half[h].load, i, half[h].grad, i);
        for (slong i = 1; i <= s; i++) {
            char *x = stage_sum(half[h].base, half[h].sign, m + (i - 1) * s, s, half[h].load, "");
            vigen_slot_line(b, "const %s %s%ld = %s;", R, half[h].var, i, x);
            free(x);
        }
        for (slong i = 1; i <= s; i++)
            vigen_slot_line(b, "%s = %s_inc_add(%s, %s%ld - %s%ld[k]);", half[h].inc, N, half[h].inc, half[h].var, i,
                            half[h].arr, i);
        for (slong i = 1; i <= s; i++) vigen_slot_line(b, "%s%ld[k] = %s%ld;", half[h].arr, i, half[h].var, i);
    }

    /* simplified Newton */
    vigen_slot *nb = vigen_slots_lines(S, "NEWTON_BLOCKS");
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            const char *a = K->a[i * s + j], *at = K->at[i * s + j];
            if (a || at)
                vigen_slot_line(nb, "vigen_newton_matrix_block(w->nw, %ld, %ld, (double)(h * %s), (double)(h * %s));",
                                (long)i, (long)j, a ? a : "0", at ? at : "0");
        }
    vigen_slot *ns = vigen_slots_lines(S, "NEWTON_START");
    vigen_slot *nr = vigen_slots_lines(S, "NEWTON_RHS");
    vigen_slot *nu = vigen_slots_lines(S, "NEWTON_UPDATE");
    for (slong i = 1; i <= s; i++) {
        char *q = stage_sum("q[k]", '+', K->a + (i - 1) * s, s, "F", "[k]");
        char *p = stage_sum("p[k]", '-', K->at + (i - 1) * s, s, "G", "[k]");
        vigen_slot_line(ns, "Q%ld[k] = %s;", i, q);
        vigen_slot_line(ns, "P%ld[k] = %s;", i, p);
        vigen_slot_line(nr, "rhs[%ld * n + k] = (double)(%s - Q%ld[k]);", i - 1, q, i);
        vigen_slot_line(nr, "rhs[%ld * n + k] = (double)(%s - P%ld[k]);", s + i - 1, p, i);
        free(q);
        free(p);
        vigen_slot_line(nu, "d = (%s)rhs[%ld * n + k];", R, i - 1);
        vigen_slot_line(nu, "Q%ld[k] += d;", i);
        vigen_slot_line(nu, "dq = %s_inc_add(dq, d);", N);
        vigen_slot_line(nu, "sq = %s_max(sq, %s_abs(Q%ld[k]));", N, N, i);
        vigen_slot_line(nu, "d = (%s)rhs[%ld * n + k];", R, s + i - 1);
        vigen_slot_line(nu, "P%ld[k] += d;", i);
        vigen_slot_line(nu, "dp = %s_inc_add(dp, d);", N);
        vigen_slot_line(nu, "sp = %s_max(sp, %s_abs(P%ld[k]));", N, N, i);
    }

    /* starting values: extrapolation from the previous step, or copies */
    vigen_slot *ip = vigen_slots_lines(S, "IMPLICIT_POINTERS");
    vigen_slot *sc = vigen_slots_lines(S, "START_COPIES");
    vigen_slot *ec = vigen_slots_lines(S, "EXTRAP_COPY");
    vigen_slot *ew = vigen_slots_lines(S, "EXTRAP_WEIGHTS");
    vigen_slot *ea = vigen_slots_lines(S, "EXTRAP_APPLY");
    for (slong i = 1; i <= s; i++) {
        vigen_slot_line(ip, "%s *const F%ld = w->F[%ld], *const G%ld = w->G[%ld];", R, i, i - 1, i, i - 1);
        vigen_slot_line(ip, "const %s *const Fo%ld = w->Fo[%ld], *const Go%ld = w->Go[%ld];", R, i, i - 1, i, i - 1);
        if (i >= 2) {
            vigen_slot_line(sc, "memcpy(F%ld, F1, n * sizeof(%s));", i, R);
            vigen_slot_line(sc, "memcpy(G%ld, G1, n * sizeof(%s));", i, R);
        }
        vigen_slot_line(ec, "memcpy(F%ld, Fo%ld, n * sizeof(%s));", i, i, R);
        vigen_slot_line(ec, "memcpy(G%ld, Go%ld, n * sizeof(%s));", i, i, R);
    }
    vigen_slots_flag(S, "LAGRANGE", K->lagrange);
    if (K->lagrange) {
        for (slong i = 1; i <= s; i++) {
            char *cr = vigen_emit_times(K->c[i - 1], "r");
            if (cr) vigen_slot_line(ew, "const %s x%ld = 1 + %s;", R, i, cr);
            else vigen_slot_line(ew, "const %s x%ld = 1;", R, i);
            free(cr);
        }
        for (slong i = 1; i <= s; i++)
            for (slong j = 1; j <= s; j++) {
                vigen_strbuf f;
                vigen_strbuf_init(&f);
                vigen_strbuf_append(&f, "");
                for (slong m = 1; m <= s; m++)
                    if (m != j)
                        vigen_strbuf_printf(&f, "%s(x%ld - %s) * %s", f.len ? " * " : "", i, K->c[m - 1],
                                            K->inv[(j - 1) * s + (m - 1)]);
                vigen_slot_line(ew, "const %s w%ld_%ld = %s;", R, i, j, f.data);
                vigen_strbuf_clear(&f);
            }
        char **wrow = calloc((size_t)s, sizeof *wrow);
        if (wrow == NULL) abort();
        for (slong i = 1; i <= s; i++) {
            for (slong j = 1; j <= s; j++) wrow[j - 1] = vigen_strdup_printf("w%ld_%ld", i, j);
            char *fo = vigen_emit_lin(wrow, s, "Fo", "[k]"), *go = vigen_emit_lin(wrow, s, "Go", "[k]");
            vigen_slot_line(ea, "F%ld[k] = %s;", i, fo);
            vigen_slot_line(ea, "G%ld[k] = %s;", i, go);
            free(fo);
            free(go);
            for (slong j = 0; j < s; j++) free(wrow[j]);
        }
        free(wrow);
    }

    /* the update of q and p */
    char *uq = hsum_vec(K->b, s, "F"), *up = hsum_vec(K->bt, s, "G");
    vigen_slots_flag(S, "HAS_UPDATE_Q", uq != NULL);
    vigen_slots_flag(S, "HAS_UPDATE_P", up != NULL);
    vigen_slots_text(S, "UPDATE_Q", uq ? uq : "");
    vigen_slots_text(S, "UPDATE_P", up ? up : "");
    free(uq);
    free(up);
}

/* ---------------------------------------------------------- the explicit path */

/* Whether the C text uses the identifier id (a whole word). */
static int uses_word(const char *text, const char *id)
{
    const size_t len = strlen(id);
    for (const char *c = strstr(text, id); c; c = strstr(c + 1, id)) {
        const char b = c == text ? ' ' : c[-1], a = c[len];
        const int word_b = b == '_' || (b >= '0' && b <= '9') || (b >= 'A' && b <= 'Z') || (b >= 'a' && b <= 'z');
        const int word_a = a == '_' || (a >= '0' && a <= '9') || (a >= 'A' && a <= 'Z') || (a >= 'a' && a <= 'z');
        if (!word_b && !word_a) return 1;
    }
    return 0;
}

/* The work array a name of the plan stands for, as an expression of w:
 * "q" and "p" are the caller's arrays, qs and ps the start values, X<k>
 * w->x[k] (heap). */
static char *array_ref(const char *name)
{
    if (strcmp(name, "qs") == 0) return vigen_strdup("w->qx");
    if (strcmp(name, "ps") == 0) return vigen_strdup("w->px");
    if (name[0] == 'X') return vigen_strdup_printf("w->x[%s]", name + 1);
    return vigen_strdup(name);
}

/* A loop of the explicit step (the lines of body) in a block of its own
 * that reads the pointers it uses from w just before it: no pointer is
 * held across the gradient calls, so none is saved and reloaded around
 * them (the calls may change any memory, the compiler cannot keep them in
 * registers anyway). */
static void loop_block(vigen_slot *L, const char *R, long nx, const char *ind, char *const *body, int nbody)
{
    static const struct { const char *id, *decl; } fixed[] = {
        { "qs", "%s *restrict const qs = w->qx;" },     { "ps", "%s *restrict const ps = w->px;" },
        { "cq0", "const %s *restrict const cq0 = w->cq;" }, { "cp0", "const %s *restrict const cp0 = w->cp;" },
        { "cq", "%s *restrict const cq = w->cqn;" },    { "cp", "%s *restrict const cp = w->cpn;" },
    };
    vigen_strbuf all;
    vigen_strbuf_init(&all);
    vigen_strbuf_append(&all, "");
    for (int k = 0; k < nbody; k++) vigen_strbuf_printf(&all, "%s\n", body[k]);
    vigen_slot_line(L, "%s{", ind);
    for (long x = 0; x < nx; x++) {
        char id[24];
        snprintf(id, sizeof id, "X%ld", x);
        if (uses_word(all.data, id)) vigen_slot_line(L, "%s    %s *restrict const X%ld = w->x[%ld];", ind, R, x, x);
    }
    for (size_t k = 0; k < sizeof fixed / sizeof fixed[0]; k++) {
        if (!uses_word(all.data, fixed[k].id)) continue;
        char *d = vigen_strdup_printf(fixed[k].decl, R);
        vigen_slot_line(L, "%s    %s", ind, d);
        free(d);
    }
    for (int k = 0; k < nbody; k++) vigen_slot_line(L, "%s    %s", ind, body[k]);
    vigen_slot_line(L, "%s}", ind);
    vigen_strbuf_clear(&all);
}

/* The operations of the explicit step, in order.  For a mechanical problem
 * (mech) dH/dp is M^-1 p, written inline with the diagonal im, and dH/dq is
 * -f with f the force: the stage and update sums of p change sign instead
 * of the force (the same values bit for bit), and only forces are counted. */
static void explicit_ops(vigen_slot *L, const emit_explicit *X, const char *N, const char *R, const char *SFX, int mech)
{
    /* q and p are updated in place, their start values kept in qs, ps: the
     * plan's q0 (p0) is q (p) before the update and qs (ps) after it */
    const char *q0 = "q", *p0 = "p";
    const char psign = mech ? '+' : '-';
    for (slong k = 0; k < X->nops; k++) {
        const emit_xop *op = X->ops + k;
        if (op->op == XOP_EVAL_F || op->op == XOP_EVAL_G) {
            int isf = op->op == XOP_EVAL_F;
            const char *fn = isf ? "dHdp" : "dHdq";
            char *tm = op->time == XTIME_T0 ? vigen_strdup("t0") : op->time == XTIME_T1 ? vigen_strdup("t1")
                                                                                      : vigen_emit_at_time(op->tc);
            const char *ind = op->fsal ? "    " : "";
            if (op->fsal) {
                vigen_slot_line(L, "if (w->fsal) {");
                vigen_slot_line(L, "    w->stats.fsal_reuses++;");
                vigen_slot_line(L, "} else {");
            }
            const char *qa = strcmp(op->q, "q0") == 0 ? q0 : op->q, *pa = strcmp(op->p, "p0") == 0 ? p0 : op->p;
            char *qr = array_ref(qa), *pr = array_ref(pa);
            if (!mech) {
                vigen_slot_line(L, "%s%s_%s(w, %s, %s, %s, w->x[%ld]);", ind, N, fn, tm, qr, pr, op->dst);
                vigen_slot_line(L, "%sw->stats.%s_evals++;", ind, fn);
            } else if (isf) {
                char *line = vigen_strdup_printf("for (size_t k = 0; k < n; k++) X%ld[k] = im[k] * %s[k];", op->dst, pa);
                loop_block(L, R, X->nx, ind, &line, 1);
                free(line);
            } else {
                vigen_slot_line(L, "%s%s_force(w, %s, %s, w->x[%ld]);", ind, N, tm, qr, op->dst);
                vigen_slot_line(L, "%sw->stats.dHdq_evals++;", ind);
            }
            if (op->fsal) vigen_slot_line(L, "}");
            free(qr);
            free(pr);
            free(tm);
            continue;
        }
        char *ht = vigen_emit_hsum_op(op);
        switch (op->op) {
        case XOP_STAGE_Q:
        case XOP_STAGE_P: {
            int isq = op->op == XOP_STAGE_Q;
            char *line = vigen_strdup_printf("for (size_t k = 0; k < n; k++) X%ld[k] = %s[k] %c %s;", op->dst,
                                             isq ? q0 : p0, isq ? '+' : psign, ht);
            loop_block(L, R, X->nx, "", &line, 1);
            free(line);
            break;
        }
        default: {
            /* the new q (+) or p (-; + for mech) in place, compensated or
             * not, the old value kept in qs (ps); nf, nfc: is it finite
             * (the template's NAME_nf_add; nfc sums the compensations) */
            int isq = op->op == XOP_UPDATE_Q;
            const char *x = isq ? "q" : "p";
            char sign = isq ? '+' : psign;
            char *arg = sign == '+' ? vigen_strdup(ht) : vigen_strdup_printf("-(%s)", ht);
            char *body[16];
            int nb = 0;
            body[nb++] = vigen_strdup("if (kahan) {");
            body[nb++] = vigen_strdup("    for (size_t k = 0; k < n; k++) {");
            body[nb++] = vigen_strdup_printf("        const %s x = %s[k];", R, x);
            body[nb++] = vigen_strdup_printf("        %ss[k] = x;", x);
            body[nb++] = vigen_strdup_printf("        %s[k] = vigen_twosum_next%s(x, %s, c%s0[k], &c%s[k]);", x, SFX, arg, x, x);
            body[nb++] = vigen_strdup_printf("        nfc += c%s[k];", x);
            body[nb++] = vigen_strdup("    }");
            body[nb++] = vigen_strdup("} else {");
            body[nb++] = vigen_strdup("    for (size_t k = 0; k < n; k++) {");
            body[nb++] = vigen_strdup_printf("        const %s x = %s[k];", R, x);
            body[nb++] = vigen_strdup_printf("        %ss[k] = x;", x);
            body[nb++] = vigen_strdup_printf("        %s[k] = x %c %s;", x, sign, ht);
            body[nb++] = vigen_strdup_printf("        nf = %s_nf_add(nf, %s[k]);", N, x);
            body[nb++] = vigen_strdup("    }");
            body[nb++] = vigen_strdup("}");
            loop_block(L, R, X->nx, "", body, nb);
            for (int b = 0; b < nb; b++) free(body[b]);
            if (isq) q0 = "qs";
            else p0 = "ps";
            free(arg);
            break;
        }
        }
        free(ht);
    }
}

static void explicit_blocks(vigen_slots *S, const emit_explicit *X, const char *N, const char *R, const char *SFX)
{
    vigen_slots_text(S, "EXPLICIT_WHAT", X->mode == EMIT_EXPLICIT_GENERAL ? "any H" : "separable H");
    vigen_slots_textf(S, "NEVALS_F", "%ld", X->nevals_f);
    vigen_slots_textf(S, "NEVALS_G", "%ld", X->nevals_g);
    vigen_slots_text(S, "FSAL_NOTE", X->fsal ? ", first-same-as-last gradients reused" : "");
    vigen_slots_flag(S, "FSAL", X->fsal);
    /* the exchanges read every array they move before the first write */
    vigen_slot *sw = vigen_slots_lines(S, "FSAL_SWAPS");
    if (X->nswaps > 0) {
        vigen_slot_line(sw, "{");
        for (int k = 0; k < X->nswaps; k++)
            for (int e = 0; e < 2; e++) {
                long x = X->swaps[k][e];
                int seen = 0;
                for (int j = 0; j < k * 2 + e; j++) seen |= X->swaps[j / 2][j % 2] == x;
                if (!seen) vigen_slot_line(sw, "    %s *const X%ld = w->x[%ld];", R, x, x);
            }
        for (int k = 0; k < X->nswaps; k++) {
            vigen_slot_line(sw, "    w->x[%ld] = X%ld;", X->swaps[k][0], X->swaps[k][1]);
            vigen_slot_line(sw, "    w->x[%ld] = X%ld;", X->swaps[k][1], X->swaps[k][0]);
        }
        vigen_slot_line(sw, "}");
    }
    explicit_ops(vigen_slots_lines(S, "EXPLICIT_OPS"), X, N, R, SFX, 0);
    explicit_ops(vigen_slots_lines(S, "MECH_EXPLICIT_OPS"), X, N, R, SFX, 1);
}

void vigen_emit_prk_code(vigen_slots *S, const prk_coefs *K, const char *name, int real)
{
    const vigen_emit_real_type *R = &vigen_emit_reals[real];
    const emit_explicit *X = &K->X;
    vigen_slots_flag(S, "EXPLICIT", X->mode != EMIT_EXPLICIT_NONE);
    vigen_slots_flag(S, "IMPLICIT", X->mode != EMIT_EXPLICIT_GENERAL);
    vigen_slots_textf(S, "EXPLICIT_SEPARABLE", "%d", X->mode != EMIT_EXPLICIT_NONE);
    vigen_slots_textf(S, "NX", "%ld", X->nx);
    /* arrays of length dim in the workspace block: Q, P, F, G, Fo, Go per
     * stage, cq, cp, cqn, cpn, qn, pn, 6 for the finite-difference Hessian,
     * the diagonal of M^-1 of a mechanical problem, and the explicit path's
     * work arrays */
    vigen_slots_textf(S, "NARRAYS", "%ld", 6 * (long)K->s + 6 + 6 + 1 + X->nx);
    implicit_blocks(S, K, name, R->ctype);
    explicit_blocks(S, X, name, R->ctype, R->suffix);
}
