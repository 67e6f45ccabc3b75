/* emit.c — `vigen emit`: correctly rounded coefficients, the structure of the
 * tableau (explicit paths, shared stages, first same as last) and the data
 * table the stepper templates are rendered with.  No C is written here: the
 * C comes from templates/stepper.[ch].in. */
#include <errno.h>
#include <sys/stat.h> /* mkdir */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <sys/stat.h>
#include <unistd.h>
#endif
#include <arb.h>
#include <arb_mat.h>
#include "vigen/check.h"
#include "vigen/emit.h"
#include "method/galerkin.h"
#include "vigen/method.h"
#include "lua/spec.h"
#include "emit/template.h"

#ifndef VIGEN_VERSION
#define VIGEN_VERSION "unknown"
#endif

/* ------------------------------------------------------------ names, texts */

static int is_c_keyword(const char *s)
{
    static const char *const kw[] = {
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum",
        "extern", "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return",
        "short", "signed", "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void",
        "volatile", "while", "bool", "true", "false", "asm", "typeof", "main", NULL
    };
    for (int k = 0; kw[k]; k++)
        if (strcmp(s, kw[k]) == 0) return 1;
    return 0;
}

char *vigen_emit_identifier(const char *name)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    if (name[0] == '\0' || !((name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= 'a' && name[0] <= 'z')))
        vigen_strbuf_append(&sb, "m_");
    for (const char *c = name; *c; c++) {
        char ch = *c;
        int ok = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_';
        vigen_strbuf_appendn(&sb, ok ? &ch : "_", 1);
    }
    if (is_c_keyword(sb.data)) vigen_strbuf_append(&sb, "_");
    return sb.data;
}

/* Printable ASCII safe inside a C comment and a C string literal: no comment
 * opener or closer, no trigraph, no backslash, no double quote; at most
 * maxlen characters. */
static char *safe_text(const char *s, size_t maxlen)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "");
    char prev = 0;
    size_t n = 0;
    for (const unsigned char *c = (const unsigned char *)s; *c && n < maxlen; c++, n++) {
        char ch = (*c >= 0x20 && *c <= 0x7e) ? (char)*c : '_';
        if (ch == '\\') ch = '/';
        if (ch == '"') ch = '\'';
        if ((prev == '*' && ch == '/') || (prev == '/' && ch == '*') || (prev == '?' && ch == '?'))
            vigen_strbuf_append(&sb, " ");
        vigen_strbuf_appendn(&sb, &ch, 1);
        prev = ch;
    }
    if (*s && n >= maxlen && strlen(s) > maxlen) vigen_strbuf_append(&sb, " ...");
    return sb.data;
}

/* Tableau names go into a string literal too: [A-Za-z0-9_.+-] only. */
static char *safe_name(const char *s)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "");
    for (const char *c = s; *c && sb.len < 100; c++) {
        char ch = *c;
        int ok = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_' ||
                 ch == '.' || ch == '+' || ch == '-';
        vigen_strbuf_appendn(&sb, ok ? &ch : "_", 1);
    }
    return sb.data;
}

/* FNV-1a 64 of the canonical tableau text (see emit.h). */
static void digest_add(unsigned long long *h, const char *text)
{
    for (const unsigned char *c = (const unsigned char *)text; *c; c++) {
        *h ^= *c;
        *h *= 1099511628211ULL;
    }
    *h ^= (unsigned char)'\n';
    *h *= 1099511628211ULL;
}

static void digest_texts(unsigned long long *h, char **texts, slong n)
{
    if (texts == NULL) { digest_add(h, "-"); return; }
    for (slong k = 0; k < n; k++) digest_add(h, texts[k]);
}

static unsigned long long tableau_digest(const vigen_tableau *t)
{
    unsigned long long h = 14695981039346656037ULL;
    char num[32];
    digest_add(&h, "vigen-tableau-v1");
    digest_add(&h, t->name ? t->name : "");
    snprintf(num, sizeof num, "%ld", (long)t->s);
    digest_add(&h, num);
    digest_texts(&h, t->c_text, t->s);
    digest_texts(&h, t->A_text, t->s * t->s);
    digest_texts(&h, t->b_text, t->s);
    digest_texts(&h, t->At_text, t->s * t->s);
    digest_texts(&h, t->ct_text, t->s);
    digest_texts(&h, t->bt_text, t->s);
    return h;
}

/* ------------------------------------------------------- correct rounding */

/* The entries of the tableau in file order: c, A, b, At, bt.  A coefficient
 * is either one of them (a reference, "ref", into this flat numbering) or
 * derived from several (ref = -1: merged sums, 1/(c_j - c_m)). */
enum { PART_C, PART_A, PART_B, PART_AT, PART_BT };

/* marks[ref] of the current pass */
enum { MARK_INEXACT = 1, MARK_ZERO = 2 };

typedef struct {
    const vigen_tableau *t;
    slong s, prec, bits;
    int real, allow_inexact, inexact_done;
    arb_ptr c, b, bt;
    arb_mat_t A, At;
    char **At_text, **bt_text;    /* At = A and bt = b when absent */
    unsigned char *marks;         /* per entry, reset at every pass */
    slong inexact_derived;        /* derived coefficients rounded from midpoints */
    int fail_kind;                /* 1: ball straddles a rounding boundary, 2: contains zero */
    slong fail_ref;
    char fail_label[64];
    vigen_error *err;
} emit_ctx;

static slong n_entries(slong s) { return 3 * s + 2 * s * s; }

/* The reference of entry (i, j) of a part (j ignored for vectors); At and bt
 * are A and b when the file leaves them out. */
static slong entry_ref(const emit_ctx *E, int part, slong i, slong j)
{
    slong s = E->s;
    if (part == PART_AT && !E->t->has_At) part = PART_A;
    if (part == PART_BT && !E->t->has_bt) part = PART_B;
    switch (part) {
    case PART_C: return i;
    case PART_A: return s + i * s + j;
    case PART_B: return s + s * s + i;
    case PART_AT: return 2 * s + s * s + i * s + j;
    default: return 2 * s + 2 * s * s + i;
    }
}

/* Label ("A[2][1]"), text in the file and current ball of an entry. */
static void entry_describe(const emit_ctx *E, slong ref, char *label, size_t n, const char **text, arb_srcptr *value)
{
    const vigen_tableau *t = E->t;
    slong s = E->s;
    const char *name;
    const char *tx;
    arb_srcptr v;
    slong i, j = -1;
    if (ref < s) { name = "c"; i = ref; tx = t->c_text[i]; v = E->c + i; }
    else if (ref < s + s * s) { name = "A"; i = (ref - s) / s; j = (ref - s) % s; tx = t->A_text[i * s + j]; v = arb_mat_entry(E->A, i, j); }
    else if (ref < 2 * s + s * s) { name = "b"; i = ref - s - s * s; tx = t->b_text[i]; v = E->b + i; }
    else if (ref < 2 * s + 2 * s * s) {
        name = "At"; i = (ref - 2 * s - s * s) / s; j = (ref - 2 * s - s * s) % s;
        tx = E->At_text[i * s + j]; v = arb_mat_entry(E->At, i, j);
    } else { name = "bt"; i = ref - 2 * s - 2 * s * s; tx = E->bt_text[i]; v = E->bt + i; }
    if (j >= 0) snprintf(label, n, "%s[%ld][%ld]", name, (long)(i + 1), (long)(j + 1));
    else snprintf(label, n, "%s[%ld]", name, (long)(i + 1));
    if (text) *text = tx;
    if (value) *value = v;
}

/* A ball around zero small enough to be taken as an exact zero. */
static int tiny_zero(const emit_ctx *E, const arb_t x)
{
    if (arb_is_zero(x)) return 1;
    if (!arb_contains_zero(x)) return 0;
    return mag_cmp_2exp_si(arb_radref(x), -(E->bits + 20)) < 0;
}

static int coef_zero(const emit_ctx *E, const arb_t x) { return tiny_zero(E, x); }

/* Records why x cannot be rounded (the message is rewritten with advice by
 * precision_message once more precision has not helped). */
static int refuse(emit_ctx *E, int kind, slong ref, const char *label)
{
    E->fail_kind = kind;
    E->fail_ref = ref;
    snprintf(E->fail_label, sizeof E->fail_label, "%s", label);
    return vigen_error_set(E->err, VIGEN_E_PRECISION, "%s: %s", label,
                           kind == 1 ? "the value is not known well enough to round it correctly"
                                     : "the ball contains zero; it cannot be rounded to the target type");
}

/* Formats x correctly rounded to the target type as a C literal in *out, or
 * NULL for an exact zero.  ref names the entry x is (or -1 for a derived
 * coefficient, then described by label).  Returns VIGEN_E_PRECISION when the
 * ball straddles a rounding boundary.  Exact zeros taken from tiny balls and
 * entries rounded as written (--allow-inexact) are marked, not reported:
 * vigen_emit_render reports them once, after the last pass. */
static int literal(char **out, emit_ctx *E, const arb_t x, slong ref, const char *label)
{
    *out = NULL;
    char lab[64];
    if (ref >= 0) entry_describe(E, ref, lab, sizeof lab, NULL, NULL);
    else snprintf(lab, sizeof lab, "%s", label);
    if (arb_is_zero(x)) return VIGEN_OK;
    if (arb_contains_zero(x)) {
        if (tiny_zero(E, x)) {
            if (ref >= 0) E->marks[ref] |= MARK_ZERO;
            else
                vigen_warn("%s is only known to lie within %.3g of zero; emitted as an exact 0", lab,
                           mag_get_d(arb_radref(x)));
            return VIGEN_OK;
        }
        return refuse(E, 2, ref, lab);
    }
    arf_t lo, hi;
    arf_init(lo);
    arf_init(hi);
    arb_get_lbound_arf(lo, x, E->prec + 64);
    arb_get_ubound_arf(hi, x, E->prec + 64);
    arf_set_round(lo, lo, E->bits, ARF_RND_NEAR);
    arf_set_round(hi, hi, E->bits, ARF_RND_NEAR);
    int rc = VIGEN_OK;
    if (!arf_equal(lo, hi) && E->allow_inexact && E->inexact_done) {
        arf_set_round(lo, arb_midref(x), E->bits, ARF_RND_NEAR);
        arf_set(hi, lo);
        if (ref >= 0) E->marks[ref] |= MARK_INEXACT;
        else E->inexact_derived++;
    }
    if (!arf_equal(lo, hi)) {
        rc = refuse(E, 1, ref, lab);
    } else if (arf_cmpabs_2exp_si(lo, -1000) < 0 || arf_cmpabs_2exp_si(lo, 1000) > 0) {
        rc = vigen_error_set(E->err, VIGEN_E_DOMAIN, "%s: magnitude outside [2^-1000, 2^1000]", lab);
    } else {
        fmpz_t m, e, fr;
        fmpz_init(m);
        fmpz_init(e);
        fmpz_init(fr);
        arf_get_fmpz_2exp(m, e, lo);
        int neg = fmpz_sgn(m) < 0;
        fmpz_abs(m, m);
        slong k = (slong)fmpz_bits(m);
        slong ex = fmpz_get_si(e) + k - 1;
        slong f = k - 1, pad = (4 - f % 4) % 4;
        vigen_strbuf sb;
        vigen_strbuf_init(&sb);
        vigen_strbuf_append(&sb, "");
        if (f == 0) {
            vigen_strbuf_printf(&sb, "0x1p%+ld", (long)ex);
        } else {
            fmpz_set(fr, m);
            fmpz_clrbit(fr, (ulong)(k - 1));
            fmpz_mul_2exp(fr, fr, (ulong)pad);
            char *hex = fmpz_get_str(NULL, 16, fr);
            slong nd = (f + pad) / 4, len = (slong)strlen(hex);
            vigen_strbuf_append(&sb, "0x1.");
            for (slong z = len; z < nd; z++) vigen_strbuf_append(&sb, "0");
            vigen_strbuf_append(&sb, hex);
            vigen_strbuf_printf(&sb, "p%+ld", (long)ex);
            flint_free(hex);
        }
        const char *mag = sb.data;
        if (E->real == VIGEN_REAL_DOUBLE) *out = neg ? vigen_strdup_printf("(-%s)", mag) : vigen_strdup(mag);
        else if (E->real == VIGEN_REAL_LONG_DOUBLE)
            *out = neg ? vigen_strdup_printf("(-%sL)", mag) : vigen_strdup_printf("%sL", mag);
        else
            *out = neg ? vigen_strdup_printf("(-(__extension__ %sQ))", mag) : vigen_strdup_printf("(__extension__ %sQ)", mag);
        vigen_strbuf_clear(&sb);
        fmpz_clear(m);
        fmpz_clear(e);
        fmpz_clear(fr);
    }
    arf_clear(lo);
    arf_clear(hi);
    return rc;
}

/* --------------------------------------------------------- data table text */

static void put_key(vigen_strbuf *sb, const char *key) { vigen_strbuf_printf(sb, "%s = ", key); }

static void put_str(vigen_strbuf *sb, const char *key, const char *value)
{
    put_key(sb, key);
    vigen_template_quote(sb, value);
    vigen_strbuf_append(sb, ",\n");
}

static void put_int(vigen_strbuf *sb, const char *key, long value) { vigen_strbuf_printf(sb, "%s = %ld,\n", key, value); }

static void put_bool(vigen_strbuf *sb, const char *key, int value)
{
    vigen_strbuf_printf(sb, "%s = %s,\n", key, value ? "true" : "false");
}

/* A literal or false. */
static void put_lit(vigen_strbuf *sb, const char *lit)
{
    if (lit) vigen_template_quote(sb, lit);
    else vigen_strbuf_append(sb, "false");
}

/* Appends the literal of x (or false), failing on precision. */
static int put_coef(vigen_strbuf *sb, emit_ctx *E, const arb_t x, slong ref, const char *label)
{
    char *lit = NULL;
    int rc = literal(&lit, E, x, ref, label);
    if (rc != VIGEN_OK) return rc;
    put_lit(sb, lit);
    free(lit);
    return VIGEN_OK;
}

static int put_vec(vigen_strbuf *sb, emit_ctx *E, const char *key, arb_srcptr v, int part, int zero_text)
{
    put_key(sb, key);
    vigen_strbuf_append(sb, "{ ");
    for (slong i = 0; i < E->s; i++) {
        char *lit = NULL;
        int rc = literal(&lit, E, v + i, entry_ref(E, part, i, 0), NULL);
        if (rc != VIGEN_OK) return rc;
        if (lit == NULL && zero_text) vigen_template_quote(sb, "0");
        else put_lit(sb, lit);
        free(lit);
        vigen_strbuf_append(sb, ", ");
    }
    vigen_strbuf_append(sb, "},\n");
    return VIGEN_OK;
}

static int put_mat(vigen_strbuf *sb, emit_ctx *E, const char *key, const arb_mat_t m, int part)
{
    put_key(sb, key);
    vigen_strbuf_append(sb, "{\n");
    for (slong i = 0; i < E->s; i++) {
        vigen_strbuf_append(sb, "  { ");
        for (slong j = 0; j < E->s; j++) {
            int rc = put_coef(sb, E, arb_mat_entry(m, i, j), entry_ref(E, part, i, j), NULL);
            if (rc != VIGEN_OK) return rc;
            vigen_strbuf_append(sb, ", ");
        }
        vigen_strbuf_append(sb, "},\n");
    }
    vigen_strbuf_append(sb, "},\n");
    return VIGEN_OK;
}

/* ------------------------------------------------------ explicit structure */

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
            if (!coef_zero(E, m)) P->dep[id_qv(P, c) * N + id_fn(P, f)] = 1;
        }
    }
    for (slong c = 0; c < P->np; c++) {
        if (P->pkind[c] != K_TEMP) continue;
        for (slong g = 0; g < P->ng; g++) {
            merged(m, E, E->At, NULL, P->prep[c], P->gcls, g);
            if (!coef_zero(E, m)) P->dep[id_pv(P, c) * N + id_gn(P, g)] = 1;
        }
    }
    for (slong f = 0; f < P->nf; f++) {
        merged(m, E, NULL, E->b, 0, P->fcls, f);
        if (!coef_zero(E, m)) P->dep[id_uq(P) * N + id_fn(P, f)] = 1;
        slong r = P->frep[f], v;
        if ((v = value_p(P, P->pcls[r])) >= 0) P->dep[id_fn(P, f) * N + v] = 1;
        if (general && (v = value_q(P, P->qcls[r])) >= 0) P->dep[id_fn(P, f) * N + v] = 1;
    }
    for (slong g = 0; g < P->ng; g++) {
        merged(m, E, NULL, E->bt, 0, P->gcls, g);
        if (!coef_zero(E, m)) P->dep[id_up(P) * N + id_gn(P, g)] = 1;
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

static int put_terms(vigen_strbuf *sb, emit_ctx *E, const plan *P, const arb_mat_t M, arb_srcptr v, slong r,
                     const slong *cls, slong ncls, slong (*id)(const plan *, slong), const slong *buf,
                     const char *label)
{
    arb_t m;
    arb_init(m);
    int rc = VIGEN_OK;
    vigen_strbuf_append(sb, "terms = { ");
    for (slong f = 0; f < ncls && rc == VIGEN_OK; f++) {
        merged(m, E, M, v, r, cls, f);
        if (coef_zero(E, m)) continue;
        char *lit = NULL;
        rc = literal(&lit, E, m, -1, label);
        if (rc != VIGEN_OK || lit == NULL) { free(lit); continue; }
        vigen_strbuf_append(sb, "{ coef = ");
        vigen_template_quote(sb, lit);
        vigen_strbuf_printf(sb, ", src = \"X%ld\" }, ", (long)buf[id(P, f)]);
        free(lit);
    }
    vigen_strbuf_append(sb, "}");
    arb_clear(m);
    return rc;
}

/* Writes the explicit-path fields of the data table. */
static int put_explicit(vigen_strbuf *sb, emit_ctx *E, const plan *P, const char *mode)
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
    /* does anything read q0 (p0) after q (p) is updated? */
    int copy_q0 = 0, copy_p0 = 0, after_uq = 0, after_up = 0;
    long nevf = 0, nevg = 0;
    for (slong k = 0; k < P->norder; k++) {
        slong a = P->order[k];
        if (a == id_uq(P)) { after_uq = 1; continue; }
        if (a == id_up(P)) { after_up = 1; continue; }
        int reads_q0 = 0, reads_p0 = 0;
        if (a < P->nq) reads_q0 = 1;
        else if (a < P->nq + P->np) reads_p0 = 1;
        else if (a < P->nq + P->np + P->nf) {
            slong r = P->frep[a - P->nq - P->np];
            reads_p0 = P->pkind[P->pcls[r]] == K_ZERO;
            reads_q0 = P->general && P->qkind[P->qcls[r]] == K_ZERO;
            nevf++;
        } else {
            slong r = P->grep[a - P->nq - P->np - P->nf];
            reads_q0 = P->qkind[P->qcls[r]] == K_ZERO;
            reads_p0 = P->general && P->pkind[P->pcls[r]] == K_ZERO;
            nevg++;
        }
        copy_q0 |= reads_q0 && after_uq;
        copy_p0 |= reads_p0 && after_up;
    }
    put_str(sb, "explicit_mode", mode);
    put_int(sb, "nx", (long)(nx > 0 ? nx : 1));
    put_bool(sb, "copy_q0", copy_q0);
    put_bool(sb, "copy_p0", copy_p0);
    put_bool(sb, "fsal", fsal_f || fsal_g);
    put_int(sb, "nevals_f", nevf - fsal_f);
    put_int(sb, "nevals_g", nevg - fsal_g);
    vigen_strbuf_append(sb, "fsal_swaps = { ");
    if (fsal_f) vigen_strbuf_printf(sb, "{ %ld, %ld }, ", (long)buf[id_fn(P, fs)], (long)buf[id_fn(P, fe)]);
    if (fsal_g) vigen_strbuf_printf(sb, "{ %ld, %ld }, ", (long)buf[id_gn(P, gs)], (long)buf[id_gn(P, ge)]);
    vigen_strbuf_append(sb, "},\nxops = {\n");
    int rc = VIGEN_OK;
    char t1[32], t2[32];
    for (slong k = 0; k < P->norder && rc == VIGEN_OK; k++) {
        slong a = P->order[k];
        vigen_strbuf_append(sb, "  { ");
        if (a == id_uq(P)) {
            vigen_strbuf_append(sb, "op = \"update_q\", ");
            rc = put_terms(sb, E, P, NULL, E->b, 0, P->fcls, P->nf, id_fn, buf, "b (merged)");
        } else if (a == id_up(P)) {
            vigen_strbuf_append(sb, "op = \"update_p\", ");
            rc = put_terms(sb, E, P, NULL, E->bt, 0, P->gcls, P->ng, id_gn, buf, "bt (merged)");
        } else if (a < P->nq) {
            vigen_strbuf_printf(sb, "op = \"stage_q\", dst = \"X%ld\", ", (long)buf[a]);
            rc = put_terms(sb, E, P, E->A, NULL, P->qrep[a], P->fcls, P->nf, id_fn, buf, "A row (merged)");
        } else if (a < P->nq + P->np) {
            slong c = a - P->nq;
            vigen_strbuf_printf(sb, "op = \"stage_p\", dst = \"X%ld\", ", (long)buf[a]);
            rc = put_terms(sb, E, P, E->At, NULL, P->prep[c], P->gcls, P->ng, id_gn, buf, "At row (merged)");
        } else {
            int isf = a < P->nq + P->np + P->nf;
            slong e = isf ? a - P->nq - P->np : a - P->nq - P->np - P->nf;
            slong r = isf ? P->frep[e] : P->grep[e];
            int pt = isf ? f_point(P, e) : g_point(P, e);
            const char *qa, *pa;
            if (isf && !P->general) { qa = "q"; pa = pptr(P, P->pcls[r], buf, t2, sizeof t2); }
            else if (!isf && !P->general) { qa = qptr(P, P->qcls[r], buf, t1, sizeof t1); pa = "p"; }
            else { qa = qptr(P, P->qcls[r], buf, t1, sizeof t1); pa = pptr(P, P->pcls[r], buf, t2, sizeof t2); }
            int qk = P->qkind[P->qcls[r]];
            vigen_strbuf_printf(sb, "op = \"%s\", dst = \"X%ld\", q = \"%s\", p = \"%s\", ", isf ? "eval_f" : "eval_g",
                                (long)buf[a], qa, pa);
            if (qk == K_ZERO) vigen_strbuf_append(sb, "time = \"t0\", ");
            else if (qk == K_END) vigen_strbuf_append(sb, "time = \"t1\", ");
            else {
                char *lit = NULL;
                rc = literal(&lit, E, E->c + r, entry_ref(E, PART_C, r, 0), NULL);
                vigen_strbuf_append(sb, "time = \"c\", tc = ");
                vigen_template_quote(sb, lit ? lit : "0");
                vigen_strbuf_append(sb, ", ");
                free(lit);
            }
            int fsal = (isf && fsal_f && e == fs) || (!isf && fsal_g && e == gs);
            (void)pt;
            vigen_strbuf_printf(sb, "fsal = %s, ", fsal ? "true" : "false");
        }
        vigen_strbuf_append(sb, "},\n");
    }
    vigen_strbuf_append(sb, "},\n");
    free(buf);
    return rc;
}

/* ------------------------------------------------------- template lookup */

#if defined(__linux__)
/* Whether path names a file that can be read. */
static int readable_file(const char *path)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) return 0;
    fclose(f);
    return 1;
}

/* The directory of the running executable (heap string), or NULL. */
static char *exe_dir(void)
{
    size_t cap = 256;
    for (;;) {
        char *buf = malloc(cap);
        if (buf == NULL) return NULL;
        ssize_t n = readlink("/proc/self/exe", buf, cap);
        if (n < 0) { free(buf); return NULL; }
        if ((size_t)n < cap) {
            buf[n] = '\0';
            char *slash = strrchr(buf, '/');
            if (slash == NULL) { free(buf); return NULL; }
            if (slash == buf) slash[1] = '\0';
            else *slash = '\0';
            return buf;
        }
        free(buf);
        cap *= 2;
    }
}

static int same_dir(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/* Whether directory dir (an absolute path) is top or lies below it. */
static int within_dir(const char *dir, const char *top)
{
    char *d = vigen_strdup(dir);
    int found = 0;
    for (;;) {
        if (same_dir(d, top)) { found = 1; break; }
        char *slash = strrchr(d, '/');
        if (slash == NULL || slash == d) break;
        *slash = '\0';
    }
    free(d);
    return found;
}
#endif

/* The templates directory (heap string): $VIGEN_TEMPLATE_DIR when set; else,
 * for an installed vigen (an executable outside its build directory
 * VIGEN_BINARY_DIR, so that the tests built there never read an installed
 * copy), the templates installed with it: first relative to the
 * executable (VIGEN_TEMPLATE_INSTALL_RELDIR, e.g. ../share/vigen/templates,
 * so that a relocated install prefix works), then VIGEN_TEMPLATE_INSTALL_DIR
 * (absolute, from the configured prefix); else vigen_template_dir(), which
 * falls back to the source tree's templates/. */
static char *emit_template_dir(void)
{
    const char *env = getenv("VIGEN_TEMPLATE_DIR");
    if (env && *env) return vigen_strdup(env);
#if defined(__linux__) && defined(VIGEN_TEMPLATE_INSTALL_RELDIR)
    char *exe = exe_dir();
    int in_build_tree = 0;
#if defined(VIGEN_BINARY_DIR)
    in_build_tree = exe != NULL && within_dir(exe, VIGEN_BINARY_DIR);
#endif
    if (exe != NULL && !in_build_tree) {
        char *dir = vigen_strdup_printf("%s/%s", exe, VIGEN_TEMPLATE_INSTALL_RELDIR);
        char *probe = vigen_strdup_printf("%s/stepper.c.in", dir);
        int found = readable_file(probe);
        free(probe);
        if (found) { free(exe); return dir; }
        free(dir);
    }
#if defined(VIGEN_TEMPLATE_INSTALL_DIR)
    if (!in_build_tree && readable_file(VIGEN_TEMPLATE_INSTALL_DIR "/stepper.c.in")) {
        free(exe);
        return vigen_strdup(VIGEN_TEMPLATE_INSTALL_DIR);
    }
#endif
    free(exe);
#endif
    return vigen_strdup(vigen_template_dir());
}

/* ------------------------------------------------------------- rendering */

static int evaluate(emit_ctx *E, vigen_error *err)
{
    const vigen_tableau *t = E->t;
    slong s = E->s;
    for (slong i = 0; i < s; i++) {
        int rc = vigen_tableau_entry_eval(E->c + i, t->c_text[i], E->prec, err);
        if (rc == VIGEN_OK) rc = vigen_tableau_entry_eval(E->b + i, t->b_text[i], E->prec, err);
        if (rc == VIGEN_OK) rc = vigen_tableau_entry_eval(E->bt + i, E->bt_text[i], E->prec, err);
        for (slong j = 0; j < s && rc == VIGEN_OK; j++) {
            rc = vigen_tableau_entry_eval(arb_mat_entry(E->A, i, j), t->A_text[i * s + j], E->prec, err);
            if (rc == VIGEN_OK)
                rc = vigen_tableau_entry_eval(arb_mat_entry(E->At, i, j), E->At_text[i * s + j], E->prec, err);
        }
        if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s: ", t->name ? t->name : "tableau");
    }
    return VIGEN_OK;
}

static int build_data(vigen_strbuf *sb, emit_ctx *E, const vigen_emit_options *opt, const char *ident)
{
    static const char *const reals[] = { "double", "long double", "vigen_float128" };
    static const char *const sfx[] = { "", "_ld", "_q" };
    static const char *const real_opt[] = { "double", "long-double", "float128" };
    const vigen_tableau *t = E->t;
    slong s = E->s;
    int rc;
    char *uname = vigen_strdup(ident);
    for (char *c = uname; *c; c++)
        if (*c >= 'a' && *c <= 'z') *c = (char)(*c - 'a' + 'A');
    char *tname = safe_name(t->name ? t->name : "unnamed");

    vigen_strbuf_append(sb, "return {\n");
    put_str(sb, "NAME", ident);
    put_str(sb, "UNAME", uname);
    put_str(sb, "REAL", reals[opt->real]);
    put_str(sb, "SFX", sfx[opt->real]);
    vigen_strbuf_printf(sb, "HAM = \"vigen_hamiltonian%s\",\n", sfx[opt->real]);
    vigen_strbuf_printf(sb, "STEPPER_TYPE = \"vigen_stepper_type%s\",\n", sfx[opt->real]);
    if (opt->real == VIGEN_REAL_LONG_DOUBLE) put_str(sb, "real_check", "!defined(LDBL_MANT_DIG) || LDBL_MANT_DIG != 64");
    else put_bool(sb, "real_check", 0);
    put_str(sb, "tableau_name", tname);
    /* what the coefficient comments may promise */
    {
        char *head = E->inexact_done
                         ? vigen_strdup_printf("rounded to %s from the decimals as written (--allow-inexact: some "
                                               "entries have too few digits to round correctly, so the coefficients "
                                               "are only as good as those decimals)", reals[opt->real])
                         : vigen_strdup_printf("correctly rounded to %s", reals[opt->real]);
        put_str(sb, "coef_head", head);
        free(head);
    }
    put_int(sb, "s", (long)s);
    put_int(sb, "order", t->claim_order);

    /* header comment lines */
    vigen_strbuf_append(sb, "header = {\n");
    {
        char *line;
        char *inp = safe_text(opt->input_label ? opt->input_label : "-", 200);
        line = vigen_strdup_printf("Generated by vigen %s: vigen emit %s --name %s --real %s%s", VIGEN_VERSION, inp,
                                   ident, real_opt[opt->real], E->inexact_done ? " --allow-inexact" : "");
        vigen_template_quote(sb, line);
        vigen_strbuf_append(sb, ",\n");
        free(line);
        if (t->generated_now) {
            line = vigen_strdup_printf("Tableau generated from the spec %s with %ld certified digits "
                                       "(as by vigen generate %s --digits %ld)",
                                       inp, (long)t->digits, inp, (long)t->digits);
            vigen_template_quote(sb, line);
            vigen_strbuf_append(sb, ",\n");
            free(line);
        }
        free(inp);
        line = vigen_strdup_printf("Tableau digest (FNV-1a 64 of the canonical text): %016llx", tableau_digest(t));
        vigen_template_quote(sb, line);
        vigen_strbuf_append(sb, ",\n");
        free(line);
        line = vigen_strdup_printf("Stages: %ld; claimed order: %s%s", (long)s,
                                   t->claim_order >= 0 ? "" : "none",
                                   t->claim_symplectic == 1 ? "; claimed symplectic" : "");
        if (t->claim_order >= 0) {
            free(line);
            line = vigen_strdup_printf("Stages: %ld; claimed order: %d%s", (long)s, t->claim_order,
                                       t->claim_symplectic == 1 ? "; claimed symplectic" : "");
        }
        vigen_template_quote(sb, line);
        vigen_strbuf_append(sb, ",\n");
        free(line);
        if (t->description) {
            char *d = safe_text(t->description, 300);
            line = vigen_strdup_printf("Description: %s", d);
            vigen_template_quote(sb, line);
            vigen_strbuf_append(sb, ",\n");
            free(line);
            free(d);
        }
        if (t->source) {
            char *d = safe_text(t->source, 300);
            line = vigen_strdup_printf("Source: %s", d);
            vigen_template_quote(sb, line);
            vigen_strbuf_append(sb, ",\n");
            free(line);
            free(d);
        }
        vigen_template_quote(sb, "Do not edit: regenerate with vigen emit.");
        vigen_strbuf_append(sb, ",\n},\n");
    }
    /* coefficient texts as comments */
    vigen_strbuf_append(sb, "coef_lines = {\n");
    {
        struct { const char *label; char **texts; slong n; int matrix; } parts[] = {
            { "c", t->c_text, s, 0 }, { "A", t->A_text, s * s, 1 }, { "b", t->b_text, s, 0 },
            { "At", E->At_text, s * s, 1 }, { "bt", E->bt_text, s, 0 },
        };
        for (size_t k = 0; k < sizeof parts / sizeof parts[0]; k++) {
            if ((k == 3 && !t->has_At) || (k == 4 && !t->has_bt)) continue;
            for (slong e = 0; e < parts[k].n; e++) {
                if (strcmp(parts[k].texts[e], "0") == 0) continue;
                char *d = safe_text(parts[k].texts[e], 200);
                char *line = parts[k].matrix
                                 ? vigen_strdup_printf("%s[%ld][%ld] = %s", parts[k].label, (long)(e / s + 1), (long)(e % s + 1), d)
                                 : vigen_strdup_printf("%s[%ld] = %s", parts[k].label, (long)(e + 1), d);
                vigen_template_quote(sb, line);
                vigen_strbuf_append(sb, ",\n");
                free(line);
                free(d);
            }
        }
        if (!t->has_At) { vigen_template_quote(sb, "At = A, bt = b (a Runge-Kutta method)"); vigen_strbuf_append(sb, ",\n"); }
        else if (!t->has_bt) { vigen_template_quote(sb, "bt = b"); vigen_strbuf_append(sb, ",\n"); }
    }
    vigen_strbuf_append(sb, "},\n");

    rc = put_vec(sb, E, "c", E->c, PART_C, 1);
    if (rc == VIGEN_OK) rc = put_vec(sb, E, "b", E->b, PART_B, 0);
    if (rc == VIGEN_OK) rc = put_vec(sb, E, "bt", E->bt, PART_BT, 0);
    if (rc == VIGEN_OK) rc = put_mat(sb, E, "a", E->A, PART_A);
    if (rc == VIGEN_OK) rc = put_mat(sb, E, "at", E->At, PART_AT);

    /* extrapolation: Lagrange through distinct nodes c */
    int distinct = s >= 2;
    for (slong i = 0; i < s && distinct; i++)
        for (slong j = 0; j < i && distinct; j++)
            if (arb_overlaps(E->c + i, E->c + j)) distinct = 0;
    if (rc == VIGEN_OK) {
        put_str(sb, "extrap", distinct ? "lagrange" : "copy");
        vigen_strbuf_append(sb, "inv = {\n");
        if (distinct) {
            arb_t d;
            arb_init(d);
            for (slong j = 0; j < s && rc == VIGEN_OK; j++) {
                vigen_strbuf_append(sb, "  { ");
                for (slong m = 0; m < s && rc == VIGEN_OK; m++) {
                    if (m == j) { vigen_strbuf_append(sb, "false, "); continue; }
                    arb_sub(d, E->c + j, E->c + m, E->prec);
                    arb_inv(d, d, E->prec);
                    rc = put_coef(sb, E, d, -1, "1/(c_j - c_m)");
                    vigen_strbuf_append(sb, ", ");
                }
                vigen_strbuf_append(sb, "},\n");
            }
            arb_clear(d);
        }
        vigen_strbuf_append(sb, "},\n");
    }

    /* explicit structure */
    if (rc == VIGEN_OK) {
        plan P;
        int done = 0;
        if (plan_build(&P, E, 1)) {
            rc = put_explicit(sb, E, &P, "general");
            put_int(sb, "explicit_separable", 1);
            done = 1;
        }
        plan_free(&P);
        if (!done && rc == VIGEN_OK) {
            if (plan_build(&P, E, 0)) {
                rc = put_explicit(sb, E, &P, "separable");
                put_int(sb, "explicit_separable", 1);
                done = 1;
            }
            plan_free(&P);
        }
        if (!done && rc == VIGEN_OK) {
            put_str(sb, "explicit_mode", "none");
            put_int(sb, "explicit_separable", 0);
            put_int(sb, "nx", 0);
        }
    }
    {
        /* arrays of length dim in the workspace block */
        long narrays = 6 * (long)s + 4 + 6;
        vigen_strbuf_printf(sb, "narrays_base = %ld,\n", narrays);
    }
    vigen_strbuf_append(sb, "}\n");
    free(uname);
    free(tname);
    return rc;
}

slong vigen_emit_spec_digits(int real) { return real == VIGEN_REAL_FLOAT128 ? 60 : 40; }

static const char *const real_names[] = { "double", "long-double", "float128" };

/* How the messages name the input. */
static const char *input_name(const emit_ctx *E, const vigen_emit_options *opt)
{
    if (opt->input_label) return opt->input_label;
    return E->t->name ? E->t->name : "tableau";
}

/* Rewrites the error of an entry that more working precision could not
 * round into one that says what to do about it. */
static void precision_message(emit_ctx *E, const vigen_emit_options *opt, vigen_error *err)
{
    const vigen_tableau *t = E->t;
    char lab[64];
    const char *text = NULL;
    if (E->fail_ref >= 0) entry_describe(E, E->fail_ref, lab, sizeof lab, &text, NULL);
    else snprintf(lab, sizeof lab, "%s", E->fail_label);
    char *shown = text ? safe_text(text, 60) : NULL;
    char *what;
    if (shown) what = vigen_strdup_printf("%s = %s", lab, shown);
    else what = vigen_strdup_printf("%s (computed from entries given as rounded decimals)", lab);
    const char *why = E->fail_kind == 2 ? "is a ball around zero too wide to be rounded" : "is not known well enough to round it correctly";
    long bits = (long)E->bits, need = (long)vigen_emit_spec_digits(E->real);
    const char *rname = real_names[E->real];
    if (t->generated_now)
        vigen_error_set(err, VIGEN_E_PRECISION,
                        "%s %s to %ld bits (%s), even generated from the spec with %ld digits (the value lies "
                        "extremely close to a rounding boundary); pass --allow-inexact to round the decimals as "
                        "written", what, why, bits, rname, (long)t->digits);
    else if (t->digits > 0)
        vigen_error_set(err, VIGEN_E_PRECISION,
                        "%s %s to %ld bits (%s): the tableau was generated with %ld digits; regenerate it with "
                        "'vigen generate SPEC --digits %ld' (or more), or emit the spec itself (vigen emit then "
                        "generates enough digits); or give the entry exactly; or pass --allow-inexact to round the "
                        "decimals as written (the stepper's coefficients are then only as good as the decimals)",
                        what, why, bits, rname, (long)t->digits, need);
    else
        vigen_error_set(err, VIGEN_E_PRECISION,
                        "%s %s to %ld bits (%s): give the entry exactly (an expression such as 1/3 or sqrt(3)/6) "
                        "or with %ld or more significant digits (a tableau from vigen generate: regenerate it with "
                        "'vigen generate SPEC --digits %ld'); or pass --allow-inexact to round the decimals as "
                        "written (the stepper's coefficients are then only as good as the decimals)",
                        what, why, bits, rname, need, need);
    free(shown);
    free(what);
}

/* The warnings of the last pass, one per entry: exact zeros taken from tiny
 * balls, and one summary of the entries rounded as written. */
static void report_marks(emit_ctx *E, const vigen_emit_options *opt)
{
    const char *in = input_name(E, opt);
    slong n = n_entries(E->s), ninexact = 0;
    vigen_strbuf names;
    vigen_strbuf_init(&names);
    vigen_strbuf_append(&names, "");
    for (slong r = 0; r < n; r++) {
        if (!E->marks[r]) continue;
        char lab[64];
        arb_srcptr v;
        entry_describe(E, r, lab, sizeof lab, NULL, &v);
        if (E->marks[r] & MARK_ZERO)
            vigen_warn("%s: %s is only known to lie within %.3g of zero; emitted as an exact 0", in, lab,
                       mag_get_d(arb_radref(v)));
        if (E->marks[r] & MARK_INEXACT) {
            if (ninexact < 5) vigen_strbuf_printf(&names, "%s%s", ninexact ? ", " : "", lab);
            ninexact++;
        }
    }
    if (ninexact > 0 || E->inexact_derived > 0) {
        char more[64] = "", derived[96] = "";
        if (ninexact > 5) snprintf(more, sizeof more, " and %ld more", (long)(ninexact - 5));
        if (E->inexact_derived > 0)
            snprintf(derived, sizeof derived, "; and %ld coefficient%s computed from them", (long)E->inexact_derived,
                     E->inexact_derived == 1 ? "" : "s");
        vigen_warn("%s: --allow-inexact: rounded %ld entr%s to %s (%ld bits) from %s decimals as written (%s%s%s): "
                   "too few digits to round %s correctly, so the stepper's coefficients are only as good as these "
                   "decimals",
                   in, (long)ninexact, ninexact == 1 ? "y" : "ies", real_names[E->real], (long)E->bits,
                   ninexact == 1 ? "its" : "their", ninexact ? names.data : "none", more, derived,
                   ninexact == 1 ? "it" : "them");
    }
    vigen_strbuf_clear(&names);
}

int vigen_emit_render(const vigen_tableau *t, const vigen_emit_options *opt, char **h_text, char **c_text,
                      char **ident, vigen_error *err)
{
    *h_text = *c_text = NULL;
    *ident = NULL;
    static const slong bits[] = { 53, 64, 113 };
    if (opt->real < 0 || opt->real > 2) return vigen_error_set(err, VIGEN_E_USAGE, "unknown real type");
    char *id = vigen_emit_identifier(opt->name ? opt->name : "stepper");
    emit_ctx E;
    memset(&E, 0, sizeof E);
    E.t = t;
    E.s = t->s;
    E.real = opt->real;
    E.allow_inexact = opt->allow_inexact;
    E.bits = bits[opt->real];
    E.err = err;
    E.At_text = t->has_At ? t->At_text : t->A_text;
    E.bt_text = t->has_bt ? t->bt_text : t->b_text;
    E.c = _arb_vec_init(t->s);
    E.b = _arb_vec_init(t->s);
    E.bt = _arb_vec_init(t->s);
    arb_mat_init(E.A, t->s, t->s);
    arb_mat_init(E.At, t->s, t->s);
    E.marks = calloc((size_t)n_entries(t->s), 1);
    if (E.marks == NULL) abort();
    vigen_strbuf data;
    vigen_strbuf_init(&data);
    int rc = VIGEN_OK;
    for (E.prec = E.bits + 64;; E.prec *= 2) {
        rc = evaluate(&E, err);
        if (rc != VIGEN_OK) break;
        vigen_strbuf_clear(&data);
        vigen_strbuf_init(&data);
        memset(E.marks, 0, (size_t)n_entries(t->s));
        E.inexact_derived = 0;
        E.fail_kind = 0;
        rc = build_data(&data, &E, opt, id);
        if (rc != VIGEN_E_PRECISION) break;
        if (E.prec >= 8192) {
            /* more precision does not help: entries given as rounded decimals */
            if (!opt->allow_inexact || E.inexact_done) break;
            E.inexact_done = 1;
            E.prec /= 2;
        }
        vigen_error_clear(err);
    }
    if (rc == VIGEN_E_PRECISION && E.fail_kind) precision_message(&E, opt, err);
    if (rc == VIGEN_OK) {
        /* the workspace block size depends on nx, known only from the data: let
         * the template compute it from narrays_base + nx */
        char *dir = emit_template_dir();
        char *hp = vigen_strdup_printf("%s/stepper.h.in", dir);
        char *cp = vigen_strdup_printf("%s/stepper.c.in", dir);
        rc = vigen_template_render_file(h_text, hp, data.data, err);
        if (rc == VIGEN_OK) rc = vigen_template_render_file(c_text, cp, data.data, err);
        free(dir);
        free(hp);
        free(cp);
    }
    if (rc == VIGEN_OK) report_marks(&E, opt);
    vigen_strbuf_clear(&data);
    free(E.marks);
    _arb_vec_clear(E.c, t->s);
    _arb_vec_clear(E.b, t->s);
    _arb_vec_clear(E.bt, t->s);
    arb_mat_clear(E.A);
    arb_mat_clear(E.At);
    if (rc != VIGEN_OK) {
        free(*h_text);
        free(*c_text);
        *h_text = *c_text = NULL;
        free(id);
        return rc;
    }
    *ident = id;
    return VIGEN_OK;
}

/* ------------------------------------------------------------------ audit */

/* The first problem of the report of a kind that certainly fails (diagnosed
 * = 1: the one naming a single entry; 0: a plain failing condition). */
static const vigen_check_problem *first_failing(const vigen_check_report *rep, int kind, int diagnosed)
{
    for (slong k = 0; k < rep->nproblems; k++) {
        const vigen_check_problem *p = rep->problems + k;
        if (p->kind == kind && !p->undecided && p->diagnosed == diagnosed && p->message) return p;
    }
    return NULL;
}

int vigen_emit_audit(vigen_tableau *t, const char *path, int *warnings, vigen_error *err)
{
    *warnings = 0;
    const char *label = path ? path : (t->name ? t->name : "tableau");
    /* The claimed order becomes NAME_ORDER and the type's order field, which
     * programs print; one claim is certainly false without any evaluation:
     * an s-stage (P)RK method has order at most 2s (its q part alone is an
     * s-stage Runge-Kutta method). */
    if (t->claim_order > 2 * t->s) {
        vigen_warn("%s: the file claims order %d, but a %ld-stage method has order at most %ld; the stepper's order "
                   "field repeats the claim: run 'vigen check %s'", label, t->claim_order, (long)t->s,
                   (long)(2 * t->s), label);
        (*warnings)++;
    }
    vigen_check_options copt;
    vigen_check_options_init(&copt);
    /* Row sums and symplecticity do not depend on the order conditions; order
     * 1 is the cheapest level the checker evaluates.  A claim order = p would
     * make it evaluate order p + 1 (up to 12, slow for many stages), and a
     * claim symplectic = true only changes how bt != b is listed: both are
     * set aside for the audit and restored. */
    copt.max_order = 1;
    copt.path = label;
    int claim_order = t->claim_order, claim_symplectic = t->claim_symplectic;
    t->claim_order = -1;
    t->claim_symplectic = -1;
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    int rc = vigen_check_tableau(&rep, t, NULL, &copt, err);
    t->claim_order = claim_order;
    t->claim_symplectic = claim_symplectic;
    if (rc != VIGEN_OK) {
        vigen_check_report_clear(&rep);
        return rc;
    }
    /* Only certain failures are reported: a condition on rounded decimals that
     * holds within the precision of the data, or an undecided one, is no
     * evidence against the tableau. */
    if (rep.consistent == VIGEN_CHECK_NO) {
        const vigen_check_problem *p = first_failing(&rep, VIGEN_PROBLEM_ROWSUM, 0);
        vigen_warn("%s: the tableau is not consistent (%ld of %ld conditions c_i = sum_j a_ij%s, sum b = 1%s fail%s%s)",
                   label, (long)rep.row_fail, (long)rep.row_total, rep.has_ct ? ", ct_i = sum_j at_ij" : "",
                   rep.has_bt ? ", sum bt = 1" : "", p ? "; first: " : "", p ? p->message : "");
        (*warnings)++;
    }
    if (rep.symplectic == VIGEN_CHECK_NO && rep.symplectic_separable == VIGEN_CHECK_YES) {
        vigen_warn("%s: the tableau is symplectic only for separable H = T(p) + V(t, q) (bt != b); "
                   "for other H the stepper is not symplectic", label);
        (*warnings)++;
    } else if (rep.symplectic == VIGEN_CHECK_NO && claim_symplectic != 0) {
        /* (a file that says symplectic = false knows: no warning) */
        const vigen_check_problem *p = first_failing(&rep, VIGEN_PROBLEM_SYMPLECTIC, 0);
        vigen_warn("%s: the tableau is not symplectic (%ld of %ld conditions b_i at_ij + b_j a_ji - b_i b_j = 0%s "
                   "fail%s%s)",
                   label, (long)rep.sym_fail, (long)rep.sym_total, rep.has_bt ? ", bt = b" : "",
                   p ? "; first: " : "", p ? p->message : "");
        (*warnings)++;
    }
    /* A claimed order up to 7 is cheap to test (orders <= claim + 1 <= 8:
     * milliseconds even for 10 stages); a certainly false one is warned
     * about, since it becomes NAME_ORDER and the type's order field. */
    if (claim_order >= 0 && claim_order <= 2 * t->s && claim_order + 1 <= 8) {
        vigen_check_options oopt;
        vigen_check_options_init(&oopt);
        oopt.max_order = claim_order + 1;
        oopt.path = label;
        vigen_check_report orep;
        vigen_check_report_init(&orep);
        vigen_error oerr;
        vigen_error_init(&oerr);
        if (vigen_check_tableau(&orep, t, NULL, &oopt, &oerr) == VIGEN_OK &&
            orep.claim_order_status == VIGEN_CHECK_NO) {
            const vigen_check_level *L = &orep.orders[VIGEN_CHECK_GENERAL].level;
            vigen_warn("%s: the file claims order %d, which is false (%s %d); the stepper's order field repeats "
                       "the claim: run 'vigen check %s'", label, claim_order,
                       L->capped ? "the order conditions hold up to order" : "the order is", L->value, label);
            (*warnings)++;
        }
        vigen_error_clear(&oerr);
        vigen_check_report_clear(&orep);
    }
    if (*warnings > 0) {
        const vigen_check_problem *d = first_failing(&rep, VIGEN_PROBLEM_ROWSUM, 1);
        if (d == NULL) d = first_failing(&rep, VIGEN_PROBLEM_SYMPLECTIC, 1);
        if (d) vigen_warn("%s: a misprint? %s", label, d->message);
        vigen_warn("%s: the stepper is emitted as the tableau says; run 'vigen check %s' for details", label, label);
    }
    vigen_check_report_clear(&rep);
    return VIGEN_OK;
}

/* ---------------------------------------------------------------- command */


/* Loads FILE for emission: a tableau file as it is; a spec generated with
 * vigen_emit_spec_digits(real) digits, doubled (up to 960) while the emitter
 * still finds a value it cannot round, with allow_inexact honoured only at
 * the last attempt.  Renders into *h, *c, *ident; t is left initialised
 * (on success and on failures after loading); *loaded says whether it is. */
int vigen_emit_load_render(vigen_tableau *t, int *loaded, const char *file, vigen_emit_options *opt, char **h,
                            char **c, char **ident, vigen_error *err)
{
    *loaded = 0;
    int kind = vigen_source_is_tableau(file, err);
    if (kind < 0) return err->code;
    if (kind == 1) {
        int rc = vigen_tableau_load(t, file, NULL, err);
        if (rc != VIGEN_OK) return rc;
        *loaded = 1;
        return vigen_emit_render(t, opt, h, c, ident, err);
    }
    vigen_spec *spec = NULL;
    int rc = vigen_spec_load(&spec, file, NULL, err);
    if (rc != VIGEN_OK) return rc;
    int inexact = opt->allow_inexact;
    const slong max_digits = 960;
    for (slong digits = vigen_emit_spec_digits(opt->real);; digits *= 2) {
        if (*loaded) vigen_tableau_clear(t);
        *loaded = 0;
        rc = vigen_galerkin_generate(t, spec, digits, err); /* its messages name the file */
        if (rc != VIGEN_OK) break;
        *loaded = 1;
        opt->allow_inexact = digits * 2 > max_digits ? inexact : 0;
        rc = vigen_emit_render(t, opt, h, c, ident, err);
        if (rc != VIGEN_E_PRECISION || digits * 2 > max_digits) break;
        vigen_error_clear(err);
    }
    opt->allow_inexact = inexact;
    vigen_spec_free(spec);
    return rc;
}
