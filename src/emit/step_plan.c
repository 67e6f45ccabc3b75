/* step_plan.c — the structure of a PRK step (see step_plan.h): classes of equal
 * rows, the dependency graph and its order (Kahn's algorithm), first same
 * as last, and the explicit step as a list of operations with correctly
 * rounded merged coefficients. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "emit/step_plan.h"
#include "support/strbuf.h"

enum { K_TEMP = 0, K_ZERO = 1, K_END = 2 };

static int same_entry(const arb_t x, const char *tx, const arb_t y, const char *ty)
{
    if (tx && ty && strcmp(tx, ty) == 0) return 1;
    return arb_is_exact(x) && arb_is_exact(y) && arb_equal(x, y);
}

static int rows_equal(const emit_ctx *E, const arb_mat_t M, char **texts, slong i, slong k)
{
    for (slong j = 0; j < E->s; j++)
        if (!same_entry(arb_mat_entry(M, i, j), texts[i * E->s + j], arb_mat_entry(M, k, j), texts[k * E->s + j]))
            return 0;
    return 1;
}

static int row_zero(const emit_ctx *E, const arb_mat_t M, slong i)
{
    for (slong j = 0; j < E->s; j++)
        if (!arb_is_zero(arb_mat_entry(M, i, j))) return 0;
    return 1;
}

static int row_is(const emit_ctx *E, const arb_mat_t M, char **texts, slong i, arb_srcptr v, char **vt)
{
    for (slong j = 0; j < E->s; j++)
        if (!same_entry(arb_mat_entry(M, i, j), texts[i * E->s + j], v + j, vt[j])) return 0;
    return 1;
}

typedef struct {
    slong s, nq, np, nf, ng, N;
    slong *qcls, *pcls, *qrep, *prep, *fcls, *gcls, *frep, *grep;
    int *qkind, *pkind;
    char *dep;          /* N x N: dep[a * N + b] = node a needs node b */
    char *need;
    slong *order, norder;
    int general;
} plan;

static void plan_free(plan *P)
{
    free(P->qcls); free(P->pcls); free(P->qrep); free(P->prep);
    free(P->fcls); free(P->gcls); free(P->frep); free(P->grep);
    free(P->qkind); free(P->pkind); free(P->dep); free(P->need); free(P->order);
    memset(P, 0, sizeof *P);
}

static slong *salloc(slong n) { slong *p = calloc((size_t)(n > 0 ? n : 1), sizeof(slong)); if (!p) abort(); return p; }

/* node ids */
static slong id_qv(const plan *P, slong c) { (void)P; return c; }
static slong id_pv(const plan *P, slong c) { return P->nq + c; }
static slong id_fn(const plan *P, slong f) { return P->nq + P->np + f; }
static slong id_gn(const plan *P, slong g) { return P->nq + P->np + P->nf + g; }
static slong id_uq(const plan *P) { return P->N - 2; }
static slong id_up(const plan *P) { return P->N - 1; }

static slong value_q(const plan *P, slong c)
{
    return P->qkind[c] == K_TEMP ? id_qv(P, c) : P->qkind[c] == K_END ? id_uq(P) : -1;
}
static slong value_p(const plan *P, slong c)
{
    return P->pkind[c] == K_TEMP ? id_pv(P, c) : P->pkind[c] == K_END ? id_up(P) : -1;
}

/* merged coefficient of node f (stages with cls[j] == f) in row r of M, or of vector v */
static void merged(arb_t res, const emit_ctx *E, const arb_mat_t M, arb_srcptr v, slong r, const slong *cls, slong f)
{
    arb_zero(res);
    for (slong j = 0; j < E->s; j++)
        if (cls[j] == f) arb_add(res, res, M ? arb_mat_entry(M, r, j) : v + j, E->prec);
}

static void classify(slong s, slong *cls, slong *rep, slong *count, int (*eq)(const void *, slong, slong), const void *ctx)
{
    *count = 0;
    for (slong i = 0; i < s; i++) {
        cls[i] = -1;
        for (slong c = 0; c < *count; c++)
            if (eq(ctx, rep[c], i)) { cls[i] = c; break; }
        if (cls[i] < 0) { rep[*count] = i; cls[i] = (*count)++; }
    }
}

static int eq_qrow(const void *ctx, slong i, slong k) { const emit_ctx *E = ctx; return rows_equal(E, E->A, E->t->A_text, i, k); }
static int eq_prow(const void *ctx, slong i, slong k) { const emit_ctx *E = ctx; return rows_equal(E, E->At, E->At_text, i, k); }
static int eq_stage(const void *ctx, slong i, slong k) { return eq_qrow(ctx, i, k) && eq_prow(ctx, i, k); }

static void mark_need(plan *P, slong a)
{
    if (P->need[a]) return;
    P->need[a] = 1;
    for (slong b = 0; b < P->N; b++)
        if (P->dep[a * P->N + b]) mark_need(P, b);
}

/* Builds the dependency graph for separable (general = 0) or any H and sorts
 * it; returns 1 when acyclic (explicit). */
static int plan_build(plan *P, emit_ctx *E, int general)
{
    slong s = E->s;
    memset(P, 0, sizeof *P);
    P->s = s;
    P->general = general;
    P->qcls = salloc(s); P->qrep = salloc(s); P->pcls = salloc(s); P->prep = salloc(s);
    P->fcls = salloc(s); P->frep = salloc(s); P->gcls = salloc(s); P->grep = salloc(s);
    classify(s, P->qcls, P->qrep, &P->nq, eq_qrow, E);
    classify(s, P->pcls, P->prep, &P->np, eq_prow, E);
    P->qkind = calloc((size_t)P->nq, sizeof(int));
    P->pkind = calloc((size_t)P->np, sizeof(int));
    if (!P->qkind || !P->pkind) abort();
    for (slong c = 0; c < P->nq; c++)
        P->qkind[c] = row_zero(E, E->A, P->qrep[c]) ? K_ZERO
                      : row_is(E, E->A, E->t->A_text, P->qrep[c], E->b, E->t->b_text) ? K_END : K_TEMP;
    for (slong c = 0; c < P->np; c++)
        P->pkind[c] = row_zero(E, E->At, P->prep[c]) ? K_ZERO
                      : row_is(E, E->At, E->At_text, P->prep[c], E->bt, E->bt_text) ? K_END : K_TEMP;
    if (general) {
        classify(s, P->fcls, P->frep, &P->nf, eq_stage, E);
        memcpy(P->gcls, P->fcls, (size_t)s * sizeof(slong));
        memcpy(P->grep, P->frep, (size_t)s * sizeof(slong));
        P->ng = P->nf;
    } else {
        memcpy(P->fcls, P->pcls, (size_t)s * sizeof(slong));
        memcpy(P->frep, P->prep, (size_t)s * sizeof(slong));
        P->nf = P->np;
        memcpy(P->gcls, P->qcls, (size_t)s * sizeof(slong));
        memcpy(P->grep, P->qrep, (size_t)s * sizeof(slong));
        P->ng = P->nq;
    }
    P->N = P->nq + P->np + P->nf + P->ng + 2;
    slong N = P->N;
    P->dep = calloc((size_t)(N * N), 1);
    P->need = calloc((size_t)N, 1);
    P->order = salloc(N);
    if (!P->dep || !P->need) abort();
    arb_t m;
    arb_init(m);
    for (slong c = 0; c < P->nq; c++) {
        if (P->qkind[c] != K_TEMP) continue;
        for (slong f = 0; f < P->nf; f++) {
            merged(m, E, E->A, NULL, P->qrep[c], P->fcls, f);
            if (!vigen_emit_tiny_zero(E, m)) P->dep[id_qv(P, c) * N + id_fn(P, f)] = 1;
        }
    }
    for (slong c = 0; c < P->np; c++) {
        if (P->pkind[c] != K_TEMP) continue;
        for (slong g = 0; g < P->ng; g++) {
            merged(m, E, E->At, NULL, P->prep[c], P->gcls, g);
            if (!vigen_emit_tiny_zero(E, m)) P->dep[id_pv(P, c) * N + id_gn(P, g)] = 1;
        }
    }
    for (slong f = 0; f < P->nf; f++) {
        merged(m, E, NULL, E->b, 0, P->fcls, f);
        if (!vigen_emit_tiny_zero(E, m)) P->dep[id_uq(P) * N + id_fn(P, f)] = 1;
        slong r = P->frep[f], v;
        if ((v = value_p(P, P->pcls[r])) >= 0) P->dep[id_fn(P, f) * N + v] = 1;
        if (general && (v = value_q(P, P->qcls[r])) >= 0) P->dep[id_fn(P, f) * N + v] = 1;
    }
    for (slong g = 0; g < P->ng; g++) {
        merged(m, E, NULL, E->bt, 0, P->gcls, g);
        if (!vigen_emit_tiny_zero(E, m)) P->dep[id_up(P) * N + id_gn(P, g)] = 1;
        slong r = P->grep[g], v;
        if ((v = value_q(P, P->qcls[r])) >= 0) P->dep[id_gn(P, g) * N + v] = 1;
        if (general && (v = value_p(P, P->pcls[r])) >= 0) P->dep[id_gn(P, g) * N + v] = 1;
    }
    arb_clear(m);
    mark_need(P, id_uq(P));
    mark_need(P, id_up(P));
    /* Kahn's algorithm; updates of q and p as late as possible, otherwise
     * the lowest id first (deterministic). */
    char *done = calloc((size_t)N, 1);
    if (!done) abort();
    slong nneed = 0;
    for (slong a = 0; a < N; a++) nneed += P->need[a];
    P->norder = 0;
    while (P->norder < nneed) {
        slong best = -1;
        for (int pass = 0; pass < 2 && best < 0; pass++)
            for (slong a = 0; a < N && best < 0; a++) {
                if (!P->need[a] || done[a]) continue;
                int upd = a == id_uq(P) || a == id_up(P);
                if (upd != pass) continue;
                int ready = 1;
                for (slong b = 0; b < N; b++)
                    if (P->dep[a * N + b] && !done[b]) { ready = 0; break; }
                if (ready) best = a;
            }
        if (best < 0) break;
        done[best] = 1;
        P->order[P->norder++] = best;
    }
    free(done);
    return P->norder == nneed;
}

/* Kind of the point a gradient node is evaluated at: K_ZERO = (t0, q0, p0)
 * side, K_END = (t1, q1, p1) side, K_TEMP otherwise. */
static int f_point(const plan *P, slong f)
{
    slong r = P->frep[f];
    if (!P->general) return P->pkind[P->pcls[r]];
    int qk = P->qkind[P->qcls[r]], pk = P->pkind[P->pcls[r]];
    return qk == pk ? qk : K_TEMP;
}
static int g_point(const plan *P, slong g)
{
    slong r = P->grep[g];
    if (!P->general) return P->qkind[P->qcls[r]];
    int qk = P->qkind[P->qcls[r]], pk = P->pkind[P->pcls[r]];
    return qk == pk ? qk : K_TEMP;
}

static const char *qptr(const plan *P, slong c, const slong *buf, char *tmp, size_t n)
{
    if (P->qkind[c] == K_ZERO) return "q0";
    if (P->qkind[c] == K_END) return "q";
    snprintf(tmp, n, "X%ld", (long)buf[id_qv(P, c)]);
    return tmp;
}
static const char *pptr(const plan *P, slong c, const slong *buf, char *tmp, size_t n)
{
    if (P->pkind[c] == K_ZERO) return "p0";
    if (P->pkind[c] == K_END) return "p";
    snprintf(tmp, n, "X%ld", (long)buf[id_pv(P, c)]);
    return tmp;
}

/* The nonzero merged coefficients of row r of M (or of vector v) over the
 * classes cls, as terms on the work arrays of the nodes id(P, f). */
static int plan_terms(emit_xop *op, emit_ctx *E, const plan *P, const arb_mat_t M, arb_srcptr v, slong r,
                     const slong *cls, slong ncls, slong (*id)(const plan *, slong), const slong *buf,
                     const char *label)
{
    arb_t m;
    arb_init(m);
    int rc = VIGEN_OK;
    op->terms = calloc((size_t)(ncls > 0 ? ncls : 1), sizeof *op->terms);
    if (op->terms == NULL) abort();
    for (slong f = 0; f < ncls && rc == VIGEN_OK; f++) {
        merged(m, E, M, v, r, cls, f);
        if (vigen_emit_tiny_zero(E, m)) continue;
        char *lit = NULL;
        rc = vigen_emit_literal(&lit, E, m, -1, label);
        if (rc != VIGEN_OK || lit == NULL) { free(lit); continue; }
        op->terms[op->nterms].coef = lit;
        op->terms[op->nterms++].src = (long)buf[id(P, f)];
    }
    arb_clear(m);
    return rc;
}

/* The explicit step of an acyclic plan. */
static int plan_explicit(emit_explicit *X, emit_ctx *E, const plan *P)
{
    slong N = P->N;
    slong *buf = salloc(N);
    slong nx = 0;
    for (slong k = 0; k < P->norder; k++) {
        slong a = P->order[k];
        if (a != id_uq(P) && a != id_up(P)) buf[a] = nx++;
    }
    /* first same as last */
    slong fs = -1, fe = -1, gs = -1, ge = -1;
    for (slong f = 0; f < P->nf; f++) {
        if (!P->need[id_fn(P, f)]) continue;
        if (f_point(P, f) == K_ZERO) fs = f;
        if (f_point(P, f) == K_END) fe = f;
    }
    for (slong g = 0; g < P->ng; g++) {
        if (!P->need[id_gn(P, g)]) continue;
        if (g_point(P, g) == K_ZERO) gs = g;
        if (g_point(P, g) == K_END) ge = g;
    }
    int fsal_f = fs >= 0 && fe >= 0, fsal_g = gs >= 0 && ge >= 0;
    /* gradient evaluations per step, in the order of the explicit step */
    long nevf = 0, nevg = 0;
    for (slong k = 0; k < P->norder; k++) {
        slong a = P->order[k];
        if (a == id_uq(P) || a == id_up(P)) continue;
        if (a >= P->nq + P->np + P->nf) nevg++;
        else if (a >= P->nq + P->np) nevf++;
    }
    X->mode = P->general ? EMIT_EXPLICIT_GENERAL : EMIT_EXPLICIT_SEPARABLE;
    X->nx = (long)(nx > 0 ? nx : 1);
    X->fsal = fsal_f || fsal_g;
    X->nevals_f = nevf - fsal_f;
    X->nevals_g = nevg - fsal_g;
    X->nswaps = 0;
    if (fsal_f) {
        X->swaps[X->nswaps][0] = (long)buf[id_fn(P, fs)];
        X->swaps[X->nswaps++][1] = (long)buf[id_fn(P, fe)];
    }
    if (fsal_g) {
        X->swaps[X->nswaps][0] = (long)buf[id_gn(P, gs)];
        X->swaps[X->nswaps++][1] = (long)buf[id_gn(P, ge)];
    }
    X->ops = calloc((size_t)(P->norder > 0 ? P->norder : 1), sizeof *X->ops);
    if (X->ops == NULL) abort();
    int rc = VIGEN_OK;
    char t1[32], t2[32];
    for (slong k = 0; k < P->norder && rc == VIGEN_OK; k++) {
        slong a = P->order[k];
        emit_xop *op = X->ops + X->nops++;
        if (a == id_uq(P)) {
            op->op = XOP_UPDATE_Q;
            rc = plan_terms(op, E, P, NULL, E->b, 0, P->fcls, P->nf, id_fn, buf, "b (merged)");
        } else if (a == id_up(P)) {
            op->op = XOP_UPDATE_P;
            rc = plan_terms(op, E, P, NULL, E->bt, 0, P->gcls, P->ng, id_gn, buf, "bt (merged)");
        } else if (a < P->nq) {
            op->op = XOP_STAGE_Q;
            op->dst = (long)buf[a];
            rc = plan_terms(op, E, P, E->A, NULL, P->qrep[a], P->fcls, P->nf, id_fn, buf, "A row (merged)");
        } else if (a < P->nq + P->np) {
            slong c = a - P->nq;
            op->op = XOP_STAGE_P;
            op->dst = (long)buf[a];
            rc = plan_terms(op, E, P, E->At, NULL, P->prep[c], P->gcls, P->ng, id_gn, buf, "At row (merged)");
        } else {
            int isf = a < P->nq + P->np + P->nf;
            slong e = isf ? a - P->nq - P->np : a - P->nq - P->np - P->nf;
            slong r = isf ? P->frep[e] : P->grep[e];
            const char *qa, *pa;
            if (isf && !P->general) { qa = "q"; pa = pptr(P, P->pcls[r], buf, t2, sizeof t2); }
            else if (!isf && !P->general) { qa = qptr(P, P->qcls[r], buf, t1, sizeof t1); pa = "p"; }
            else { qa = qptr(P, P->qcls[r], buf, t1, sizeof t1); pa = pptr(P, P->pcls[r], buf, t2, sizeof t2); }
            int qk = P->qkind[P->qcls[r]];
            op->op = isf ? XOP_EVAL_F : XOP_EVAL_G;
            op->dst = (long)buf[a];
            snprintf(op->q, sizeof op->q, "%s", qa);
            snprintf(op->p, sizeof op->p, "%s", pa);
            if (qk == K_ZERO) op->time = XTIME_T0;
            else if (qk == K_END) op->time = XTIME_T1;
            else {
                char *lit = NULL;
                rc = vigen_emit_literal(&lit, E, E->c + r, vigen_emit_entry_ref(E, PART_C, r, 0), NULL);
                op->time = XTIME_C;
                op->tc = lit ? lit : vigen_strdup("0");
            }
            op->fsal = (isf && fsal_f && e == fs) || (!isf && fsal_g && e == gs);
        }
    }
    free(buf);
    return rc;
}

void vigen_emit_explicit_clear(emit_explicit *X)
{
    for (slong k = 0; k < X->nops; k++) {
        for (slong j = 0; j < X->ops[k].nterms; j++) free(X->ops[k].terms[j].coef);
        free(X->ops[k].terms);
        free(X->ops[k].tc);
    }
    free(X->ops);
    memset(X, 0, sizeof *X);
}

int vigen_emit_plan(emit_explicit *X, emit_ctx *E)
{
    memset(X, 0, sizeof *X);
    plan P;
    int rc = VIGEN_OK;
    for (int general = 1; general >= 0; general--) {
        int acyclic = plan_build(&P, E, general);
        if (acyclic) rc = plan_explicit(X, E, &P);
        plan_free(&P);
        if (acyclic) return rc;
    }
    X->mode = EMIT_EXPLICIT_NONE;
    return VIGEN_OK;
}
