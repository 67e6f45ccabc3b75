/* split.c — the "split" variant's slot builder (variants.def): a splitting
 * stepper that calls the flows of the parts of H back (templates/split/).
 *
 * Its input is the method's substeps in order of application, each a flow
 * (by index into the file's flows) and a coefficient text.  A file with
 * named flows gives them as written (a processed method: one step is the
 * corrector, the kernel and the corrector's inverse, the state at every
 * step's end the true one); a file of kicks and drifts has the two flows
 * "drift" (flow 0, H_0 = T) and "kick" (flow 1, H_1 = V), so that a user who
 * solves T and V exactly (or any two parts) runs any kick-drift method of
 * the library with those flows.
 *
 * Consecutive substeps of one flow are merged, their coefficients added in
 * ball arithmetic (exactly: the sum is rounded once), and a substep whose
 * coefficient is an exact zero is dropped (which may bring two of one flow
 * together: merged again).  NAME_step does not merge across steps (the
 * last substep of a step with the first of the next, first same as last):
 * the state every step returns is the method's, which output at any time,
 * events and restart read.  NAME_advance, which takes many steps and
 * returns the state at their end only, has tables of its own: the
 * corrector C, one step of the kernel, the join (the kernel's last substep
 * and its first added, when they are of one flow) and C^-1, each merged
 * within itself.  Time is carried by flow 0: substep k starts at
 * t0 + tau_k h with tau_k the sum of the coefficients of flow 0 before it
 * in the step C K C^-1, rounded from its ball like the coefficients.
 *
 * A bracket flow (degree k: the Poisson bracket of k letters) advances by
 * coef h^k: its table row carries k, and the stepper passes coef times the
 * product h h ... h (k factors, formed at the call). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/check.h"
#include "emit/names.h"
#include "emit/variant.h"
#include "support/strbuf.h"

/* The substeps as the builder reads them: one step, C K C^-1 for a
 * processed method (ncorrector substeps of C first and of C^-1 last). */
typedef struct {
    slong nflows;
    const char *const *names;
    slong n;
    slong ncorrector;
    int *flow;
    char *const *coef;
    const int *degree;     /* [nflows] bracket flows: a substep advances flow j by coef h^degree[j]; else NULL */
    int *const *bracket;   /* [nflows] the letters of a bracket flow, NULL for a plain one */
} split_input;

static const char *const kick_drift_names[] = { "drift", "kick" };

/* The substeps of E's method; VIGEN_E_USAGE when it has none (a tableau
 * that is not a splitting).  The tableau of a splitting of two flows keeps
 * its substeps as drifts (the first flow) and kicks (the second), and the
 * file's names of the flows when it has them. */
static int split_input_get(split_input *in, emit_ctx *E)
{
    const vigen_tableau *t = E->t;
    memset(in, 0, sizeof *in);
    if (t->nsubsteps < 1)
        return vigen_error_set(E->err, VIGEN_E_USAGE, "the split variant needs a splitting (a file with "
                               "'splitting', or a composition of one); '%s' is a tableau: emit it with the "
                               "default variant", t->name ? t->name : "unnamed");
    in->nflows = 2;
    in->names = kick_drift_names;
    if (t->flows != NULL && t->flows->nflows == 2) in->names = (const char *const *)t->flows->names;
    in->n = t->nsubsteps;
    if (t->flows != NULL && 2 * t->flows->ncorrector < t->nsubsteps) in->ncorrector = t->flows->ncorrector;
    in->flow = malloc(sizeof(int) * (size_t)t->nsubsteps);
    if (in->flow == NULL) abort();
    for (slong k = 0; k < in->n; k++) in->flow[k] = t->substep_drift[k] ? 0 : 1;
    in->coef = t->substep_coef;
    if (t->flows != NULL && t->flows->nstep > 0) {
        /* bracket flows: the step's substeps, which the tableau leaves out */
        const vigen_flows *fl = t->flows;
        in->nflows = fl->nflows;
        in->names = (const char *const *)fl->names;
        in->n = fl->nstep;
        free(in->flow);
        in->flow = malloc(sizeof(int) * (size_t)fl->nstep);
        if (in->flow == NULL) abort();
        memcpy(in->flow, fl->step_flow, sizeof(int) * (size_t)fl->nstep);
        in->coef = fl->step_coef;
        in->degree = fl->degree;
        in->bracket = fl->bracket;
    }
    return VIGEN_OK;
}

static void split_input_clear(split_input *in) { free(in->flow); }

/* Merged substeps: flow, coefficient (its ball in val) and start time as
 * literals. */
typedef struct {
    slong m;
    int *flow;
    arb_ptr val;
    char **coef, **time;
    char **text;     /* the coefficients as written, joined by " + " where merged */
} split_subs;

static void split_subs_clear(split_subs *U)
{
    for (slong k = 0; k < U->m; k++) {
        free(U->coef[k]);
        free(U->time[k]);
        free(U->text[k]);
    }
    if (U->val != NULL) _arb_vec_clear(U->val, U->m);
    free(U->flow);
    free(U->coef);
    free(U->time);
    free(U->text);
    memset(U, 0, sizeof *U);
}

static char *join_text(char *a, const char *b)
{
    if (a == NULL) return vigen_strdup(b);
    char *j = vigen_strdup_printf("%s + %s", a, b);
    free(a);
    return j;
}

/* The n substeps of in from k0 on, merged: consecutive substeps of one flow
 * added, exact zeros dropped.  tau is the time (in units of h) at the first
 * of them on entry and after the last on return: the one place where the
 * start time of a substep is computed.  Substep labels in messages count
 * from first (1-based). */
static int split_round(split_subs *U, emit_ctx *E, const split_input *in, slong k0, slong n, arb_t tau, slong first)
{
    memset(U, 0, sizeof *U);
    const slong N = n > 0 ? n : 1;
    arb_ptr v = _arb_vec_init(N);
    int *flow = calloc((size_t)N, sizeof *flow);
    char **text = calloc((size_t)N, sizeof *text);
    if (flow == NULL || text == NULL) abort();
    int rc = VIGEN_OK;
    slong m = 0;
    for (slong k = k0; k < k0 + n && rc == VIGEN_OK; k++) {
        arb_t x;
        arb_init(x);
        rc = vigen_tableau_entry_eval(x, in->coef[k], E->prec, E->err);
        if (rc == VIGEN_OK && !vigen_emit_tiny_zero(E, x)) {
            if (m > 0 && flow[m - 1] == in->flow[k]) {
                arb_add(v + m - 1, v + m - 1, x, E->prec);
                text[m - 1] = join_text(text[m - 1], in->coef[k]);
            } else {
                flow[m] = in->flow[k];
                arb_set(v + m, x);
                text[m++] = vigen_strdup(in->coef[k]);
            }
            /* a merged sum that is zero goes, and may leave two of one flow side by side */
            while (m >= 1 && vigen_emit_tiny_zero(E, v + m - 1)) {
                free(text[--m]);
                while (m >= 2 && flow[m - 2] == flow[m - 1]) {
                    arb_add(v + m - 2, v + m - 2, v + m - 1, E->prec);
                    text[m - 2] = join_text(text[m - 2], text[m - 1]);
                    free(text[--m]);
                }
            }
        }
        arb_clear(x);
    }
    if (rc == VIGEN_OK) {
        U->m = m;
        U->flow = flow;
        U->text = text;
        flow = NULL;
        text = NULL;
        U->val = _arb_vec_init(m);
        _arb_vec_set(U->val, v, m);
        U->coef = calloc((size_t)N, sizeof *U->coef);
        U->time = calloc((size_t)N, sizeof *U->time);
        if (U->coef == NULL || U->time == NULL) abort();
        for (slong k = 0; k < m && rc == VIGEN_OK; k++) {
            char label[64];
            snprintf(label, sizeof label, "coefficient of substep %ld", (long)(first + k));
            rc = vigen_emit_literal(U->coef + k, E, v + k, -1, label);
            if (rc == VIGEN_OK) {
                snprintf(label, sizeof label, "time of substep %ld", (long)(first + k));
                rc = vigen_emit_literal(U->time + k, E, tau, -1, label);
            }
            if (U->flow[k] == 0) arb_add(tau, tau, v + k, E->prec);
        }
    } else {
        for (slong k = 0; k < m; k++) free(text[k]);
    }
    free(flow);
    free(text);
    _arb_vec_clear(v, N);
    return rc;
}

/* The tables of NAME_advance: the corrector C (none for a method that is not
 * processed), one step of the kernel, the join and C^-1.  The join is the
 * kernel's last substep followed by the next step's first, one substep when
 * they are of one flow (coefficients added before rounding; absent when
 * they are not, or when their sum is zero); it starts when the kernel's
 * last substep does.  Times are those of the step C K C^-1: C's from the
 * step's start, the kernel's after C's, C^-1's after the kernel's. */
typedef struct {
    split_subs pre, kern, post;
    int join;            /* 1: the join is a substep */
    int join_flow;
    char *join_coef, *join_time, *join_text;
} split_advance;

static void split_advance_clear(split_advance *A)
{
    split_subs_clear(&A->pre);
    split_subs_clear(&A->kern);
    split_subs_clear(&A->post);
    free(A->join_coef);
    free(A->join_time);
    free(A->join_text);
    memset(A, 0, sizeof *A);
}

static int split_advance_round(split_advance *A, emit_ctx *E, const split_input *in)
{
    memset(A, 0, sizeof *A);
    const slong c = in->ncorrector, nk = in->n - 2 * c;
    arb_t tau;
    arb_init(tau);
    int rc = split_round(&A->pre, E, in, 0, c, tau, 1);
    /* a corrector's coefficients of flow 0 cancel as a rule (it is made of
     * pairs K(-a h) ... K(a h)): a sum zero to the working precision starts
     * the kernel at 0, as vigen_emit_tiny_zero takes every coefficient */
    if (vigen_emit_tiny_zero(E, tau)) arb_zero(tau);
    if (rc == VIGEN_OK) rc = split_round(&A->kern, E, in, c, nk, tau, c + 1);
    if (rc == VIGEN_OK && A->kern.m == 0)
        rc = vigen_error_set(E->err, VIGEN_E_SPEC, "the kernel of the splitting has no substep with a nonzero "
                             "coefficient");
    if (rc == VIGEN_OK) rc = split_round(&A->post, E, in, c + nk, c, tau, c + nk + 1);
    const split_subs *K = &A->kern;
    if (rc == VIGEN_OK && K->m >= 2 && K->flow[0] == K->flow[K->m - 1]) {
        arb_t x;
        arb_init(x);
        arb_add(x, K->val + K->m - 1, K->val, E->prec);
        if (!vigen_emit_tiny_zero(E, x)) {
            A->join = 1;
            A->join_flow = K->flow[0];
            A->join_text = vigen_strdup_printf("%s + %s", K->text[K->m - 1], K->text[0]);
            rc = vigen_emit_literal(&A->join_coef, E, x, -1, "coefficient of the join of two steps");
            if (rc == VIGEN_OK) A->join_time = K->time[K->m - 1] ? vigen_strdup(K->time[K->m - 1]) : NULL;
        }
        arb_clear(x);
    }
    arb_clear(tau);
    return rc;
}

/* FLOW_<NAME>: the flow's name upper-cased, other characters '_'. */
static char *flow_constant(const char *uname, const char *name)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_printf(&sb, "%s_FLOW_", uname);
    for (const char *c = name; *c; c++) {
        char ch = *c;
        if (ch >= 'a' && ch <= 'z') ch = (char)(ch - 'a' + 'A');
        int ok = (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9');
        vigen_strbuf_appendn(&sb, ok ? &ch : "_", 1);
    }
    return sb.data;
}

/* One row of a substep table: the flow's constant, its degree when the
 * method has bracket flows (degree != NULL), the coefficient and the start
 * time (an exact zero: 0). */
static void sub_row(vigen_slot *T, char *const *constant, const int *degree, int flow, const char *coef,
                    const char *time, int more)
{
    if (degree != NULL)
        vigen_slot_line(T, "{ %s, %d, %s, %s }%s", constant[flow], degree[flow], coef, time ? time : "0",
                        more ? "," : "");
    else
        vigen_slot_line(T, "{ %s, %s, %s }%s", constant[flow], coef, time ? time : "0", more ? "," : "");
}

/* The rows of NAME_advance's table (ADV_TABLE), each group under a comment,
 * and their counts. */
static void advance_texts(vigen_slots *S, char *const *constant, const int *degree, const split_advance *A)
{
    const split_subs *group[3] = { &A->pre, &A->kern, &A->post };
    static const char *const what[3] = { "the corrector C, once at the start", "one step of the kernel",
                                         "C^-1, once at the end" };
    const slong count = A->pre.m + A->kern.m + A->join + A->post.m;
    vigen_slots_textf(S, "ADV_PRE", "%ld", (long)A->pre.m);
    vigen_slots_textf(S, "ADV_KERN", "%ld", (long)A->kern.m);
    vigen_slots_textf(S, "ADV_JOIN", "%d", A->join);
    vigen_slots_textf(S, "ADV_POST", "%ld", (long)A->post.m);
    vigen_slots_textf(S, "ADV_COUNT", "%ld", (long)count);
    vigen_slot *T = vigen_slots_lines(S, "ADV_TABLE");
    slong row = 0;
    for (int g = 0; g < 3; g++) {
        const split_subs *U = group[g];
        if (U->m > 0) vigen_slot_line(T, "/* %s */", what[g]);
        for (slong k = 0; k < U->m; k++, row++)
            sub_row(T, constant, degree, U->flow[k], U->coef[k], U->time[k], row + 1 < count);
        if (g == 1 && A->join) {
            char *d = vigen_emit_safe_text(A->join_text, 200);
            vigen_slot_line(T, "/* the join: the last substep of a step and the first of the next, %s */", d);
            free(d);
            sub_row(T, constant, degree, A->join_flow, A->join_coef, A->join_time, ++row < count);
        }
    }
}

static void split_texts(vigen_slots *S, emit_ctx *E, const vigen_emit_options *opt, const char *ident,
                        const split_input *in, const split_subs *U, const split_advance *A)
{
    const vigen_emit_real_type *R = &vigen_emit_reals[opt->real];
    const vigen_tableau *t = E->t;
    char *uname = vigen_strdup(ident);
    for (char *c = uname; *c; c++)
        if (*c >= 'a' && *c <= 'z') *c = (char)(*c - 'a' + 'A');
    char *tname = vigen_emit_safe_name(t->name ? t->name : "unnamed");
    vigen_slots_text(S, "NAME", ident);
    vigen_slots_text(S, "UNAME", uname);
    vigen_slots_text(S, "REAL", R->ctype);
    vigen_slots_text(S, "SFX", R->suffix);
    vigen_slots_textf(S, "STEPPER_TYPE", "vigen_stepper_type%s", R->suffix);
    vigen_slots_flag(S, "DOUBLE", opt->real == VIGEN_REAL_DOUBLE);
    vigen_slots_flag(S, "LONG_DOUBLE", opt->real == VIGEN_REAL_LONG_DOUBLE);
    vigen_slots_flag(S, "FLOAT128", opt->real == VIGEN_REAL_FLOAT128);
    vigen_slots_text(S, "TABLEAU_NAME", tname);
    /* the order for H = A + B with the parts' flows exact: that of the
     * splitting applied to H = T(p) + V(q), the separable family */
    const int order = vigen_emit_certified_order_family(t, VIGEN_CHECK_SEPARABLE);
    vigen_slots_textf(S, "ORDER", "%d", order);
    vigen_slots_textf(S, "NFLOWS", "%ld", (long)in->nflows);
    vigen_slots_textf(S, "SUB_COUNT", "%ld", (long)U->m);
    vigen_slots_flag(S, "BRACKETS", in->degree != NULL);
    if (E->inexact_done)
        vigen_slots_textf(S, "COEF_HEAD", "rounded to %s from the decimals as written (--allow-inexact: some "
                          "coefficients have too few digits to round correctly)", R->ctype);
    else
        vigen_slots_textf(S, "COEF_HEAD", "correctly rounded to %s", R->ctype);

    vigen_slot *H = vigen_slots_lines(S, "HEADER");
    char *inp = vigen_emit_safe_text(opt->input_label ? opt->input_label : "-", 200);
    vigen_slot_line(H, "Generated by vigen %s: vigen emit %s --name %s --real %s --variant split%s", VIGEN_VERSION,
                    inp, ident, R->name, E->inexact_done ? " --allow-inexact" : "");
    free(inp);
    vigen_slot_line(H, "Method digest (FNV-1a 64 of the canonical tableau text): %016llx", vigen_emit_digest(t));
    if (order >= 0) vigen_slot_line(H, "Substeps: %ld; certified order with exact flows: %d", (long)U->m, order);
    else vigen_slot_line(H, "Substeps: %ld; certified order with exact flows: not decided", (long)U->m);
    vigen_emit_header_about(H, t);

    vigen_slot *D = vigen_slots_lines(S, "FLOW_DOC");
    vigen_slot *F = vigen_slots_lines(S, "FLOW_ENUM");
    char **constant = calloc((size_t)in->nflows, sizeof *constant);
    char **nm = calloc((size_t)in->nflows, sizeof *nm);
    if (constant == NULL || nm == NULL) abort();
    for (slong k = 0; k < in->nflows; k++) {
        nm[k] = vigen_emit_safe_text(in->names[k], 80);
        constant[k] = flow_constant(uname, nm[k]);
        vigen_slot_line(D, "flow %ld: \"%s\" (%s)%s", (long)k, nm[k], constant[k], k == 0 ? ", carries the time" : "");
        if (in->degree != NULL && in->degree[k] > 1) {
            vigen_strbuf br;
            vigen_strbuf_init(&br);
            for (int j = 1; j < in->degree[k]; j++) vigen_strbuf_append(&br, "{");
            for (int j = 0; j < in->degree[k]; j++)
                vigen_strbuf_printf(&br, "%s%s%s", j ? ", " : "", nm[in->bracket[k][j]], j ? "}" : "");
            vigen_slot_line(D, "  the Hamiltonian %s (Poisson brackets), advanced by coef h^%d", br.data,
                            in->degree[k]);
            vigen_strbuf_clear(&br);
        }
        vigen_slot_line(F, "%s = %ld%s", constant[k], (long)k, k + 1 < in->nflows ? "," : "");
    }
    vigen_slot *C = vigen_slots_lines(S, "COEF_LINES");
    vigen_slot *T = vigen_slots_lines(S, "SUB_TABLE");
    for (slong k = 0; k < U->m; k++) {
        char *d = vigen_emit_safe_text(U->text[k], 200);
        vigen_slot_line(C, "%2ld. %s, %s", (long)k + 1, nm[U->flow[k]], d);
        free(d);
        sub_row(T, constant, in->degree, U->flow[k], U->coef[k], U->time[k], k + 1 < U->m);
    }
    advance_texts(S, constant, in->degree, A);
    for (slong k = 0; k < in->nflows; k++) {
        free(constant[k]);
        free(nm[k]);
    }
    free(constant);
    free(nm);
    free(uname);
    free(tname);
}

int vigen_emit_split_slots(vigen_slots *S, emit_ctx *E, const vigen_emit_options *opt, const char *ident)
{
    if (opt->dim > 0 || opt->batch)
        return vigen_error_set(E->err, VIGEN_E_USAGE, "the split variant takes no --dim and no --batch (its flows "
                               "are the user's functions: an ensemble runs through vigen_integrate_ensemble)");
    split_input in;
    int rc = split_input_get(&in, E);
    if (rc != VIGEN_OK) return rc;
    split_subs U;
    split_advance A;
    memset(&A, 0, sizeof A);
    arb_t tau;
    arb_init(tau);
    rc = split_round(&U, E, &in, 0, in.n, tau, 1);
    arb_clear(tau);
    if (rc == VIGEN_OK && U.m == 0)
        rc = vigen_error_set(E->err, VIGEN_E_SPEC, "the splitting has no substep with a nonzero coefficient");
    if (rc == VIGEN_OK) rc = split_advance_round(&A, E, &in);
    if (rc == VIGEN_OK) split_texts(S, E, opt, ident, &in, &U, &A);
    split_advance_clear(&A);
    split_subs_clear(&U);
    split_input_clear(&in);
    return rc;
}
