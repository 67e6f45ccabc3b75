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
 * together: merged again).  Merging across steps (the last substep of a
 * step with the first of the next, first same as last) is not done: it
 * would change the state every step returns, which output at any time,
 * events and restart read.  Time is carried by flow 0: substep k starts at
 * t0 + tau_k h with tau_k the sum of the coefficients of flow 0 before it,
 * rounded from its ball like the coefficients.
 *
 * A bracket flow (degree k: the Poisson bracket of k letters) advances by
 * coef h^k: its table row carries k, and the stepper passes coef times the
 * product h h ... h (k factors, computed once per step). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/check.h"
#include "emit/names.h"
#include "emit/variant.h"
#include "support/strbuf.h"

/* The substeps as the builder reads them. */
typedef struct {
    slong nflows;
    const char *const *names;
    slong n;
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

/* The merged substeps: flow, coefficient and start time as literals. */
typedef struct {
    slong m;
    int *flow;
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

static int split_round(split_subs *U, emit_ctx *E, const split_input *in)
{
    memset(U, 0, sizeof *U);
    const slong N = in->n;
    arb_ptr v = _arb_vec_init(N);
    int *flow = calloc((size_t)N, sizeof *flow);
    char **text = calloc((size_t)N, sizeof *text);
    if (flow == NULL || text == NULL) abort();
    int rc = VIGEN_OK;
    slong m = 0;
    for (slong k = 0; k < N && rc == VIGEN_OK; k++) {
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
    if (rc == VIGEN_OK && m == 0)
        rc = vigen_error_set(E->err, VIGEN_E_SPEC, "the splitting has no substep with a nonzero coefficient");
    if (rc == VIGEN_OK) {
        U->m = m;
        U->flow = flow;
        U->text = text;
        flow = NULL;
        text = NULL;
        U->coef = calloc((size_t)m, sizeof *U->coef);
        U->time = calloc((size_t)m, sizeof *U->time);
        if (U->coef == NULL || U->time == NULL) abort();
        arb_t tau;
        arb_init(tau);
        for (slong k = 0; k < m && rc == VIGEN_OK; k++) {
            char label[64];
            snprintf(label, sizeof label, "coefficient of substep %ld", (long)k + 1);
            rc = vigen_emit_literal(U->coef + k, E, v + k, -1, label);
            if (rc == VIGEN_OK) {
                snprintf(label, sizeof label, "time of substep %ld", (long)k + 1);
                rc = vigen_emit_literal(U->time + k, E, tau, -1, label);
            }
            if (U->flow[k] == 0) arb_add(tau, tau, v + k, E->prec);
        }
        arb_clear(tau);
    } else {
        for (slong k = 0; k < m; k++) free(text[k]);
    }
    free(flow);
    free(text);
    _arb_vec_clear(v, N);
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

static void split_texts(vigen_slots *S, emit_ctx *E, const vigen_emit_options *opt, const char *ident,
                        const split_input *in, const split_subs *U)
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
    int maxdeg = 1;
    for (slong k = 0; k < in->nflows && in->degree; k++)
        if (in->degree[k] > maxdeg) maxdeg = in->degree[k];
    vigen_slots_flag(S, "BRACKETS", in->degree != NULL);
    vigen_slots_textf(S, "MAX_DEGREE", "%d", maxdeg);
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
        if (in->degree != NULL)
            vigen_slot_line(T, "{ %s, %d, %s, %s }%s", constant[U->flow[k]], in->degree[U->flow[k]], U->coef[k],
                            U->time[k] ? U->time[k] : "0", k + 1 < U->m ? "," : "");
        else
            vigen_slot_line(T, "{ %s, %s, %s }%s", constant[U->flow[k]], U->coef[k], U->time[k] ? U->time[k] : "0",
                            k + 1 < U->m ? "," : "");
    }
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
    rc = split_round(&U, E, &in);
    if (rc == VIGEN_OK) split_texts(S, E, opt, ident, &in, &U);
    split_subs_clear(&U);
    split_input_clear(&in);
    return rc;
}
