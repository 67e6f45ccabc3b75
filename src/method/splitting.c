/* splitting.c — splitting and composition files as PRK tableaux (the
 * "splitting" and "composition" rows of methods.def).
 *
 * A splitting (kicks p <- p - b h dV/dq, drifts q <- q + a h dT/dp, in order
 * of application, consecutive substeps of one kind merged) becomes the PRK
 * tableau with bt = b that is symplectic for every H and, for separable H,
 * explicit and equal to the splitting step by step: each substep gets a time
 * stamp, a kick the drift time before it (tau = sum of the drifts before)
 * and a drift the kick time before it (sigma = sum of the kicks before);
 * stage i lies between substeps i and i + 1, one kick and one drift, with
 * weight w_i = stamp_{i+1} - stamp_i; then c_i = tau of its kick, ct_i =
 * sigma of its drift, a_ij = w_j when the drift of stage j comes before the
 * kick of stage i, at_ij = w_j when the kick of stage j comes before the
 * drift of stage i, b = bt = w.  The weights of the stages beside a drift
 * add up to its coefficient, those beside a kick to its coefficient, which
 * is why both kinds must add up to the same total (1 for a consistent
 * method).  s = substeps - 1.
 *
 * A composition of a base method (c, A, b; ct, At, bt) with steps gamma_k h
 * is the method of m s stages with blocks gamma_l b_j (l < k), gamma_k a_ij
 * (l = k), 0 (l > k), likewise for At, and weights gamma_l b_j (Hairer,
 * Lubich & Wanner, GNI sec. III.1.3 and II.4). */
#include <stdlib.h>
#include <string.h>
#include "core/expr.h"
#include "method/splitting_file.h"
#include "method/methods.h"
#include "method/method_tableau.h"
#include "vigen/method.h"
#include "support/strbuf.h"

static vigen_name_resolver_fn name_resolver;

void vigen_method_set_name_resolver(vigen_name_resolver_fn fn) { name_resolver = fn; }

static char *sum_text(char **terms, slong n)
{
    if (n == 0) return vigen_strdup("0");
    if (n == 1) return vigen_strdup(terms[0]);
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    for (slong k = 0; k < n; k++) vigen_strbuf_printf(&sb, "%s(%s)", k ? " + " : "", terms[k]);
    return sb.data;
}

static char *difference_text(const char *x, const char *y)
{
    if (strcmp(y, "0") == 0) return vigen_strdup(x);
    return vigen_strdup_printf("(%s) - (%s)", x, y);
}

static char *product_text(const char *x, const char *y)
{
    if (strcmp(x, "0") == 0 || strcmp(y, "0") == 0) return vigen_strdup("0");
    if (strcmp(x, "1") == 0) return vigen_strdup(y);
    if (strcmp(y, "1") == 0) return vigen_strdup(x);
    return vigen_strdup_printf("(%s)*(%s)", x, y);
}

/* the value of an entry text at prec, read as every tableau entry is */
static int eval_text(arb_t res, const char *text, slong prec, vigen_error *err)
{
    return vigen_tableau_entry_eval(res, text, prec, err);
}

static char **texts_alloc(slong n)
{
    char **t = calloc((size_t)n, sizeof *t);
    if (t == NULL) abort();
    return t;
}

static int splitting_tableau(vigen_tableau *t, const vigen_splitting *sp, const char *path, vigen_error *err)
{
    /* merge consecutive substeps of one kind */
    slong n = 0;
    int *drift = calloc((size_t)sp->n, sizeof *drift);
    char **coef = texts_alloc(sp->n);
    for (slong k = 0; k < sp->n;) {
        slong j = k;
        while (j < sp->n && sp->drift[j] == sp->drift[k]) j++;
        drift[n] = sp->drift[k];
        coef[n++] = sum_text(sp->coef + k, j - k);
        k = j;
    }
    int rc = VIGEN_OK;
    if (n < 2)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'splitting' needs both kicks and drifts (it has only %ss)", path,
                             drift[0] ? "drift" : "kick");
    /* stamps: a kick the drift time before it, a drift the kick time before it */
    char **stamp = texts_alloc(n);
    slong nd = 0, nk = 0;
    char **drifts = texts_alloc(n), **kicks = texts_alloc(n);
    for (slong k = 0; k < n; k++) {
        stamp[k] = drift[k] ? sum_text(kicks, nk) : sum_text(drifts, nd);
        if (drift[k]) drifts[nd++] = coef[k];
        else kicks[nk++] = coef[k];
    }
    char *total_kicks = sum_text(kicks, nk), *total_drifts = sum_text(drifts, nd);
    if (rc == VIGEN_OK) {
        /* b = bt holds only if both kinds add up to the same total */
        arb_t x, y;
        arb_init(x);
        arb_init(y);
        rc = eval_text(x, total_kicks, 256, err);
        if (rc == VIGEN_OK) rc = eval_text(y, total_drifts, 256, err);
        if (rc == VIGEN_OK && !arb_overlaps(x, y)) {
            char *xs = arb_get_str(x, 10, 0), *ys = arb_get_str(y, 10, 0);
            rc = vigen_error_set(err, VIGEN_E_MATH, "%s: the kicks of 'splitting' add up to %s and the drifts to %s; "
                                 "they must add up to the same total (1 for a consistent method)", path, xs, ys);
            flint_free(xs);
            flint_free(ys);
        }
        if (rc != VIGEN_OK) vigen_error_prefix(err, "%s: ", path);
        arb_clear(x);
        arb_clear(y);
    }
    if (rc == VIGEN_OK) {
        slong s = n - 1;
        vigen_tableau_init(t, s);
        /* stage i: its kick and its drift are substeps i and i + 1 */
        slong *kick_of = calloc((size_t)s, sizeof *kick_of), *drift_of = calloc((size_t)s, sizeof *drift_of);
        t->c_text = texts_alloc(s);
        t->ct_text = texts_alloc(s);
        t->b_text = texts_alloc(s);
        t->A_text = texts_alloc(s * s);
        t->At_text = texts_alloc(s * s);
        for (slong i = 0; i < s; i++) {
            kick_of[i] = drift[i] ? i + 1 : i;
            drift_of[i] = drift[i] ? i : i + 1;
            t->b_text[i] = difference_text(stamp[i + 1], stamp[i]);
            t->c_text[i] = vigen_strdup(stamp[kick_of[i]]);
            t->ct_text[i] = vigen_strdup(stamp[drift_of[i]]);
        }
        for (slong i = 0; i < s; i++)
            for (slong j = 0; j < s; j++) {
                t->A_text[i * s + j] = vigen_strdup(drift_of[j] < kick_of[i] ? t->b_text[j] : "0");
                t->At_text[i * s + j] = vigen_strdup(kick_of[j] < drift_of[i] ? t->b_text[j] : "0");
            }
        t->has_At = t->has_ct = 1;
        free(kick_of);
        free(drift_of);
    }
    for (slong k = 0; k < n; k++) {
        free(coef[k]);
        free(stamp[k]);
    }
    free(coef);
    free(stamp);
    free(drift);
    free(drifts);
    free(kicks);
    free(total_kicks);
    free(total_drifts);
    return rc;
}

/* name, source, description and claims of the file onto the tableau */
static void take_info(vigen_tableau *t, vigen_tableau *info)
{
    t->name = info->name;
    t->source = info->source;
    t->description = info->description;
    info->name = info->source = info->description = NULL;
    t->claim_order = info->claim_order;
    t->claim_symplectic = info->claim_symplectic;
    t->claim_order_sep = info->claim_order_sep;
    t->claim_order_nys = info->claim_order_nys;
    t->digits = info->digits;
}

static int has_brackets(const vigen_splitting *sp)
{
    for (slong f = 0; f < sp->nflows && sp->flow_degree; f++)
        if (sp->flow_degree[f] > 1) return 1;
    return 0;
}

/* One step of the method as substeps: the kernel, or for a processed method
 * the corrector C, the kernel and C^-1 (C's substeps reversed and negated).
 * drift[k] is the letter: 1 for the first flow (A, the drift), 0 for the
 * second (B, the kick). */
static int step_substeps(vigen_splitting *step, const vigen_splitting *sp, const char *path, vigen_error *err)
{
    memset(step, 0, sizeof *step);
    if (!has_brackets(sp) && sp->nflows > 2)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: a splitting of %ld flows: its order is not decided for more "
                               "than two flows (vigen checks splittings of two flows, A + B)", path, (long)sp->nflows);
    slong m = sp->ncorrector, n = sp->n + 2 * m;
    step->n = n;
    step->drift = calloc((size_t)n, sizeof *step->drift);
    step->flow = calloc((size_t)n, sizeof *step->flow);
    step->coef = texts_alloc(n);
    if (step->drift == NULL || step->flow == NULL) abort();
    for (slong k = 0; k < m; k++) {
        step->flow[k] = step->flow[n - 1 - k] = sp->corrector_flow[k];
        step->coef[k] = vigen_strdup(sp->corrector_coef[k]);
        step->coef[n - 1 - k] = vigen_strdup_printf("-(%s)", sp->corrector_coef[k]);
    }
    for (slong k = 0; k < sp->n; k++) {
        step->flow[m + k] = sp->flow[k];
        step->coef[m + k] = vigen_strdup(sp->coef[k]);
    }
    for (slong k = 0; k < n; k++) step->drift[k] = step->flow[k] == 0;
    return VIGEN_OK;
}

/* The substeps of the plain flows alone (the bracket flows have no PRK
 * form): a view into step's arrays, which it borrows. */
static void plain_substeps(vigen_splitting *plain, const vigen_splitting *step, const vigen_splitting *sp)
{
    memset(plain, 0, sizeof *plain);
    plain->drift = calloc((size_t)step->n, sizeof *plain->drift);
    plain->coef = texts_alloc(step->n);
    if (plain->drift == NULL) abort();
    for (slong k = 0; k < step->n; k++)
        if (sp->flow_degree == NULL || sp->flow_degree[step->flow[k]] == 1) {
            plain->drift[plain->n] = step->drift[k];
            plain->coef[plain->n++] = step->coef[k];
        }
}

/* the named flows, the corrector's length and the generalized-order claim
 * onto the tableau (files with `flows` or `corrector` only), and the bracket
 * flows with the whole step's substeps when there are any */
static void take_flows(vigen_tableau *t, const vigen_splitting *sp, const vigen_splitting *step)
{
    if (!sp->named && sp->ncorrector == 0) return;
    vigen_flows fl;
    memset(&fl, 0, sizeof fl);
    fl.nflows = sp->nflows;
    fl.names = sp->flow_names;
    fl.perturbation = sp->perturbation;
    fl.ncorrector = sp->ncorrector;
    fl.ngeneralized = sp->ngeneralized;
    memcpy(fl.generalized, sp->generalized, sizeof fl.generalized);
    if (has_brackets(sp)) {
        fl.degree = sp->flow_degree;
        fl.bracket = sp->flow_bracket;
        fl.nstep = step->n;
        fl.step_flow = step->flow;
        fl.step_coef = step->coef;
    }
    vigen_tableau_set_flows(t, &fl);
}

int vigen_method_splitting_read(void **state, vigen_sandbox *sb, const char *path, vigen_method_loader load,
                                vigen_error *err)
{
    *state = NULL;
    vigen_splitting sp, step;
    vigen_tableau info, t;
    vigen_tableau_init(&info, 1);
    int rc = vigen_splitting_from_table(&sp, &info, sb, path, err);
    vigen_sandbox_free(sb);
    if (rc == VIGEN_OK) {
        vigen_splitting plain;
        memset(&plain, 0, sizeof plain);
        rc = step_substeps(&step, &sp, path, err);
        if (rc == VIGEN_OK) {
            plain_substeps(&plain, &step, &sp);
            rc = splitting_tableau(&t, &plain, path, err);
        }
        if (rc == VIGEN_OK) {
            vigen_tableau_set_substeps(&t, plain.n, plain.drift, plain.coef);
            take_flows(&t, &sp, &step);
        }
        free(plain.drift);
        free(plain.coef);
        vigen_splitting_clear(&step);
        vigen_splitting_clear(&sp);
    }
    if (rc == VIGEN_OK) {
        take_info(&t, &info);
        rc = vigen_method_tableau_adopt(state, &t, path, err);
    }
    vigen_tableau_clear(&info);
    return rc;
}

/* ---------------------------------------------------------------- composition */

typedef struct {
    char *path;
    vigen_composition co;
    vigen_tableau info;
    vigen_method *base;
} composition_state;

/* compositions nest (a base may be a composition): a file naming itself, or
 * a cycle, would recurse for ever */
static int nesting;
enum { MAX_NESTING = 8 };

/* The base's file: relative to the composition file's folder (a path, or a
 * name in that folder), else a name the resolver knows (the method library). */
static int base_path(char **out, const char *base, const char *path, vigen_error *err)
{
    *out = NULL;
    const char *slash = strrchr(path, '/');
    char *dir = slash ? vigen_strdup(path) : vigen_strdup(".");
    if (slash) dir[slash - path] = '\0';
    size_t n = strlen(base);
    int has_ext = n > 4 && strcmp(base + n - 4, ".lua") == 0;
    char *cand = base[0] == '/' ? vigen_strdup(base) : vigen_strdup_printf("%s/%s%s", dir, base, has_ext ? "" : ".lua");
    free(dir);
    FILE *f = fopen(cand, "r");
    if (f == NULL && !has_ext && strchr(base, '/') != NULL) {
        /* a path written with its own extension or none */
        char *plain = vigen_strdup_printf("%.*s", (int)(strlen(cand) - 4), cand);
        free(cand);
        cand = plain;
        f = fopen(cand, "r");
    }
    if (f != NULL) {
        fclose(f);
        *out = cand;
        return VIGEN_OK;
    }
    free(cand);
    if (strchr(base, '/') == NULL && name_resolver != NULL) {
        vigen_error e;
        vigen_error_init(&e);
        if (name_resolver(out, base, &e) == VIGEN_OK) return VIGEN_OK;
        vigen_error_clear(&e);
    }
    return vigen_error_set(err, VIGEN_E_SPEC, "%s: composition.base '%s' is neither a file beside it nor a method "
                           "name ('vigen list' lists the names)", path, base);
}

int vigen_method_composition_read(void **state, vigen_sandbox *sb, const char *path, vigen_method_loader load,
                                vigen_error *err)
{
    *state = NULL;
    composition_state *st = calloc(1, sizeof *st);
    if (st == NULL) {
        vigen_sandbox_free(sb);
        return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    }
    vigen_tableau_init(&st->info, 1);
    int rc = vigen_composition_from_table(&st->co, &st->info, sb, path, err);
    vigen_sandbox_free(sb);
    char *base = NULL;
    if (rc == VIGEN_OK) rc = base_path(&base, st->co.base, path, err);
    if (rc == VIGEN_OK && nesting >= MAX_NESTING)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: compositions nested more than %d deep (does composition.base "
                             "lead back to this file?)", path, MAX_NESTING);
    if (rc == VIGEN_OK) {
        nesting++;
        rc = load(&st->base, base, err);
        nesting--;
        if (rc != VIGEN_OK) vigen_error_prefix(err, "%s: composition.base: ", path);
    }
    free(base);
    if (rc != VIGEN_OK) {
        vigen_composition_clear(&st->co);
        vigen_tableau_clear(&st->info);
        free(st);
        return rc;
    }
    st->path = vigen_strdup(path);
    *state = st;
    return VIGEN_OK;
}

static void compose(vigen_tableau *t, const vigen_tableau *u, const vigen_composition *co)
{
    slong s = u->s, m = co->m, S = m * s;
    vigen_tableau_init(t, S);
    t->c_text = texts_alloc(S);
    t->ct_text = texts_alloc(S);
    t->b_text = texts_alloc(S);
    t->bt_text = texts_alloc(S);
    t->A_text = texts_alloc(S * S);
    t->At_text = texts_alloc(S * S);
    char **bt = u->has_bt ? u->bt_text : u->b_text;
    char **At = u->has_At ? u->At_text : u->A_text;
    for (slong k = 0; k < m; k++)
        for (slong i = 0; i < s; i++) {
            slong r = k * s + i;
            for (slong l = 0; l < m; l++)
                for (slong j = 0; j < s; j++) {
                    slong col = l * s + j;
                    const char *g = co->gamma[l];
                    t->A_text[r * S + col] = l < k ? product_text(g, u->b_text[j])
                                             : l == k ? product_text(g, u->A_text[i * s + j]) : vigen_strdup("0");
                    t->At_text[r * S + col] = l < k ? product_text(g, bt[j])
                                              : l == k ? product_text(g, At[i * s + j]) : vigen_strdup("0");
                }
            /* nodes: the row sums, written out (exact whatever the base) */
            t->c_text[r] = sum_text(t->A_text + r * S, S);
            t->ct_text[r] = sum_text(t->At_text + r * S, S);
        }
    for (slong l = 0; l < m; l++)
        for (slong j = 0; j < s; j++) {
            t->b_text[l * s + j] = product_text(co->gamma[l], u->b_text[j]);
            t->bt_text[l * s + j] = product_text(co->gamma[l], bt[j]);
        }
    t->has_At = t->has_ct = t->has_bt = 1;
    /* a composition of a splitting is a splitting: the base's substeps with
     * each step's fraction */
    if (u->nsubsteps > 0) {
        slong n = u->nsubsteps, N = m * n;
        int *drift = malloc(sizeof(int) * (size_t)N);
        char **coef = texts_alloc(N);
        if (drift == NULL) abort();
        for (slong l = 0; l < m; l++)
            for (slong k = 0; k < n; k++) {
                drift[l * n + k] = u->substep_drift[k];
                coef[l * n + k] = product_text(co->gamma[l], u->substep_coef[k]);
            }
        vigen_tableau_set_substeps(t, N, drift, coef);
        /* a composition's step is no longer C K C^-1: the generalized-order
         * claim and the corrector belong to the base */
        if (u->flows) {
            vigen_flows fl = *u->flows;
            fl.ncorrector = 0;
            fl.ngeneralized = 0;
            vigen_tableau_set_flows(t, &fl);
        }
        for (slong k = 0; k < N; k++) free(coef[k]);
        free(coef);
        free(drift);
    }
}

int vigen_method_composition_tableau(vigen_tableau *t, void *state, slong digits, vigen_error *err)
{
    composition_state *st = state;
    vigen_tableau u;
    int rc = vigen_method_tableau(&u, st->base, digits, err);
    if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s: composition.base: ", st->path);
    if (u.c_text == NULL || u.A_text == NULL || u.b_text == NULL) {
        vigen_tableau_clear(&u);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: composition.base has no entry texts", st->path);
    }
    if (u.s * st->co.m > VIGEN_MAX_STAGES) {
        slong S = u.s * st->co.m;
        vigen_tableau_clear(&u);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: the composition has %ld stages, above the maximum %d",
                               st->path, (long)S, VIGEN_MAX_STAGES);
    }
    if (u.flows != NULL && u.flows->nstep > 0) {
        vigen_tableau_clear(&u);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: composition.base has bracket flows; a composition of such a "
                               "method is not supported (write the composed substeps in a splitting file)", st->path);
    }
    compose(t, &u, &st->co);
    vigen_tableau_clear(&u);
    t->name = vigen_strdup(st->info.name);
    t->source = st->info.source ? vigen_strdup(st->info.source) : NULL;
    t->description = st->info.description ? vigen_strdup(st->info.description) : NULL;
    t->claim_order = st->info.claim_order;
    t->claim_symplectic = st->info.claim_symplectic;
    t->claim_order_sep = st->info.claim_order_sep;
    t->claim_order_nys = st->info.claim_order_nys;
    if (digits <= 0) return VIGEN_OK;
    rc = vigen_tableau_evaluate(t, vigen_method_tableau_prec(digits, t->s), err);
    if (rc != VIGEN_OK) {
        vigen_error_prefix(err, "%s: ", st->path);
        vigen_tableau_clear(t);
    }
    return rc;
}

void vigen_method_composition_release(void *state)
{
    composition_state *st = state;
    if (st == NULL) return;
    vigen_method_free(st->base);
    vigen_composition_clear(&st->co);
    vigen_tableau_clear(&st->info);
    free(st->path);
    free(st);
}
