/* design_method.c — the method file of a proved solution: a composition file
 * in the library's format with its claims, checked by the checker before
 * anything is written (the file goes to a private temporary file, is loaded
 * as any composition file is, checked, and removed), and the files of a
 * design written as a unit. */
#define _DEFAULT_SOURCE /* mkstemp */
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "design/design_method.h"
#include "design/design_internal.h"
#include "vigen/check.h"
#include "vigen/method.h"
#include "support/file.h"
#include "support/guard.h"
#include "support/strbuf.h"

char *vigen_design_method_text(const vigen_design_spec *d, const char *base, const char *name, slong index,
                               slong count, char *const *values, const char *how, const int claims[3],
                               const int *gen, int ngen)
{
    int splitting = d->base == NULL;
    vigen_strbuf gw;
    vigen_strbuf_init(&gw);
    for (int j = 0; j < ngen; j++) vigen_strbuf_printf(&gw, "%s%d", j ? ", " : "", gen[j]);
    char *what = d->flow_b ? vigen_strdup_printf("a %ssplitting of the flows %s and %s with %d steps of %s "
                                                 "(H = %s + eps %s), generalized order {%s}",
                                                 d->symmetric ? "symmetric " : "", d->flow_a, d->flow_b, d->stages,
                                                 d->flow_b, d->flow_a, d->flow_b, gw.data ? gw.data : "")
               : d->processed ? vigen_strdup_printf("a symmetric splitting with %d kicks of effective order %d%s "
                                                    "processed by the corrector C (drift, kick, drift, kick, drift, kick): "
                                                    "one step is C, the kernel, C^-1", d->stages, d->order,
                                                    d->nystrom ? " for Nystrom H" : "")
               : splitting ? vigen_strdup_printf("a %ssplitting with %d kicks", d->symmetric ? "symmetric " : "",
                                                 d->stages)
                           : vigen_strdup_printf("a %d-stage %scomposition of %s", d->stages,
                                                 d->symmetric ? "symmetric " : "", base);
    const char *family = !splitting || d->flow_b ? "" : d->nystrom ? " for Nystrom H (T = p^2/2)" : " for separable H";
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    if (d->flow_b) vigen_strbuf_printf(&sb, "-- %s: %s.\n", name, what);
    else vigen_strbuf_printf(&sb, "-- %s: %s, order %d%s.\n", name, what, d->order, family);
    vigen_strbuf_printf(&sb, "-- Found by vigen design from %s (solution %ld of %ld): %s\n", d->path, (long)index,
                        (long)count, how);
    vigen_strbuf_append(&sb, "-- Every digit is certified: the exact step lies within half a unit of the last digit.\n");
    vigen_strbuf_printf(&sb, "return {\n  name = \"%s\",\n", name);
    static const char *const claim_names[3] = {"order", "order_separable", "order_nystrom"};
    for (int c = 0; c < 3; c++)
        if (claims[c] >= 0) vigen_strbuf_printf(&sb, "  %s = %d,\n", claim_names[c], claims[c]);
    /* a processed step C K C^-1 is symplectic by construction (exact flows),
     * but the checker leaves its symplecticity undecided on these decimals:
     * no claim is made that it does not certify */
    if (!d->processed) vigen_strbuf_append(&sb, "  symplectic = true,\n");
    if (d->flow_b) {
        const char *first = d->flows_first_b ? d->flow_b : d->flow_a;
        const char *second = d->flows_first_b ? d->flow_a : d->flow_b;
        if (ngen > 0) vigen_strbuf_printf(&sb, "  generalized_order = {%s},\n", gw.data);
        vigen_strbuf_printf(&sb, "  flows = { \"%s\", \"%s\" },\n  perturbation = \"%s\",\n", first, second,
                            d->flow_b);
    }
    vigen_strbuf_clear(&gw);
    vigen_strbuf_printf(&sb, "  source = \"vigen design %s, solution %ld of %ld\",\n", d->path, (long)index,
                        (long)count);
    if (d->flow_b)
        vigen_strbuf_printf(&sb, "  description = \"%c%s; a root of the order conditions proved to exist by the "
                            "Krawczyk operator.\",\n", 'A', what + 1);
    else
        vigen_strbuf_printf(&sb, "  description = \"%c%s of order %d%s; a root of the order conditions proved to exist "
                            "by the Krawczyk operator.\",\n", 'A', what + 1, d->order, family);
    if (splitting) {
        vigen_strbuf_append(&sb, "  splitting = {\n");
        /* a symmetric splitting that starts with a kick ends with one: its
         * end drifts are 0, and a stage of weight 0 at the end leaves the
         * checker's symplecticity undecided on decimals, so they are left
         * out (the method is the same) */
        int ends = d->first_kick && d->symmetric;
        for (int i = 0; i < 2 * d->stages + 1; i++)
            if (!(ends && (i == 0 || i == 2 * d->stages) && strcmp(values[i], "0") == 0))
                vigen_strbuf_printf(&sb, "    { \"%s\", \"%s\" },\n", i % 2 ? (d->flow_b ? d->flow_b : "kick")
                                    : (d->flow_a ? d->flow_a : "drift"), values[i]);
        vigen_strbuf_append(&sb, "  },\n");
        if (d->processed) {
            vigen_strbuf_append(&sb, "  corrector = {\n");
            for (int i = 0; i < DESIGN_CORRECTOR_UNKNOWNS; i++)
                vigen_strbuf_printf(&sb, "    { \"%s\", \"%s\" },\n", i % 2 ? "kick" : "drift",
                                    values[2 * d->stages + 1 + i]);
            vigen_strbuf_append(&sb, "  },\n");
        }
        vigen_strbuf_append(&sb, "}\n");
    } else {
        vigen_strbuf_printf(&sb, "  composition = {\n    base = \"%s\",\n    gamma = {\n", base);
        for (int i = 0; i < d->stages; i++) vigen_strbuf_printf(&sb, "      \"%s\",\n", values[i]);
        vigen_strbuf_append(&sb, "    },\n  },\n}\n");
    }
    free(what);
    return sb.data;
}

/* text to a fresh temporary file; its path, or NULL. */
static char *temp_file(const char *text, int *slot)
{
    const char *dir = getenv("TMPDIR");
    char *path = vigen_strdup_printf("%s/vigen-design-XXXXXX", dir && *dir ? dir : "/tmp");
    sigset_t old;
    vigen_guard_block(&old);
    int fd = mkstemp(path);
    *slot = fd >= 0 ? vigen_guard_temp_add(path) : -1;
    vigen_guard_unblock(&old);
    if (fd < 0) {
        free(path);
        return NULL;
    }
    size_t len = strlen(text), done = 0;
    int ok = 1;
    while (ok && done < len) {
        ssize_t w = write(fd, text + done, len - done);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) ok = 0;
        else done += (size_t)w;
    }
    if (close(fd) != 0) ok = 0;
    if (!ok) {
        unlink(path);
        free(path);
        return NULL;
    }
    return path;
}

static char *ball_text(const arb_t x)
{
    char *s = arb_get_str(x, 6, ARB_STR_NO_RADIUS);
    char *out = vigen_strdup(s);
    flint_free(s);
    return out;
}

/* text loaded as the composition file it is (through a temporary file) and
 * checked to order max_order (classical: the classical figures only, not
 * the generalized orders of named flows); rep initialised on success. */
static int load_check(vigen_check_report *rep, const char *text, const char *shown_path, int max_order,
                      int classical, vigen_error *err)
{
    int slot = -1;
    char *tmp = temp_file(text, &slot);
    if (tmp == NULL) return vigen_error_set(err, VIGEN_E_WRITE, "cannot write a temporary file to check %s: %s",
                                            shown_path, strerror(errno));
    vigen_tableau t;
    int rc = vigen_source_load(&t, tmp, 34, err);
    sigset_t old;
    vigen_guard_block(&old);
    unlink(tmp);
    vigen_guard_temp_drop(slot);
    vigen_guard_unblock(&old);
    free(tmp);
    if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s: ", shown_path);
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.path = shown_path;
    opt.max_order = max_order <= VIGEN_TREE_MAX_ORDER ? max_order : VIGEN_TREE_MAX_ORDER;
    opt.generalized = !classical;
    vigen_check_report_init(rep);
    rc = vigen_check_tableau(rep, &t, NULL, &opt, err);
    if (rc != VIGEN_OK) vigen_check_report_clear(rep);
    vigen_tableau_clear(&t);
    return rc;
}

int vigen_design_method_check(vigen_design_solution *sol, const char *text, const char *shown_path, int order,
                              vigen_error *err)
{
    vigen_check_report rep;
    int rc = load_check(&rep, text, shown_path, order + 1 > 8 ? order + 1 : 8, 0, err);
    if (rc != VIGEN_OK) return rc;
    int at_least = 0, undecided = 0;
    sol->order = vigen_check_certified_order(&rep, VIGEN_CHECK_GENERAL, &at_least, &undecided);
    if (at_least || undecided) sol->order = -1;
    int sl = 0, su = 0;
    sol->order_separable = vigen_check_certified_order(&rep, VIGEN_CHECK_SEPARABLE, &sl, &su);
    if (sl || su) sol->order_separable = -1;
    sol->order_nystrom = vigen_check_certified_order(&rep, VIGEN_CHECK_NYSTROM, &sl, &su);
    if (sl || su) sol->order_nystrom = -1;
    char **text_of[VIGEN_CHECK_EC_FAMILIES] = {&sol->error_constant, &sol->error_constant_sep,
                                               &sol->error_constant_nystrom};
    double *value_of[VIGEN_CHECK_EC_FAMILIES] = {&sol->error_constant_d, &sol->error_constant_sep_d,
                                                 &sol->error_constant_nystrom_d};
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
        const vigen_check_error_constant *ec = &rep.error_constant[f];
        *value_of[f] = -1;
        if (!ec->available) continue;
        *text_of[f] = ball_text(ec->value);
        *value_of[f] = arf_get_d(arb_midref(ec->value), ARF_RND_NEAR);
    }
    sol->force = (long)rep.cost.force;
    const vigen_check_generalized *g = rep.generalized;
    sol->ngeneralized = 0;
    if (g && g->computed && g->why == NULL && g->k <= VIGEN_DESIGN_MAX_GENERALIZED) {
        int decided = g->k > 0;
        for (int j = 1; j <= g->k; j++) decided &= g->state[j] == VIGEN_GEN_DECIDED;
        for (int j = 1; decided && j <= g->k; j++) sol->generalized[sol->ngeneralized++] = g->r[j];
    }
    /* the claims the text states hold, every one (the family orders only
     * when the text states them) */
    sol->certified = rep.exit_code == 0 &&
                     (rep.claim_symplectic < 0 || rep.claim_symplectic_status == VIGEN_CHECK_YES) &&
                     (rep.claim_order < 0 || rep.claim_order_status == VIGEN_CHECK_YES);
    if (g && g->claim_status >= 0 && g->claim_status != VIGEN_CHECK_YES) sol->certified = 0;
    for (int f = 0; f < 2; f++)
        if (rep.claim_order_family[f] >= 0 && rep.claim_order_family_status[f] != VIGEN_CHECK_YES) sol->certified = 0;
    if (!sol->certified)
        sol->why = vigen_strdup_printf("the checker does not certify the claims (order %d%s, symplectic %s)",
                                       sol->order, sol->order < 0 ? ": undecided" : "",
                                       rep.claim_symplectic_status == VIGEN_CHECK_YES ? "yes" : "not certified");
    vigen_check_report_clear(&rep);
    return VIGEN_OK;
}

int vigen_design_method_error_constant(double *ec, long *force, const char *text, int order, int family,
                                       vigen_error *err)
{
    vigen_check_report rep;
    *ec = -1;
    *force = 0;
    int rc = load_check(&rep, text, "(candidate)", order + 1, 1, err);
    if (rc != VIGEN_OK) return rc;
    const vigen_check_error_constant *e = &rep.error_constant[family];
    if (e->available && e->order == order) *ec = arf_get_d(arb_midref(e->value), ARF_RND_NEAR);
    *force = (long)rep.cost.force;
    vigen_check_report_clear(&rep);
    return VIGEN_OK;
}

int vigen_design_write(const vigen_design_result *res, vigen_error *err)
{
    size_t n = 0;
    const char **paths = malloc((size_t)(res->nsol + 1) * sizeof(char *));
    const char **texts = malloc((size_t)(res->nsol + 1) * sizeof(char *));
    for (slong i = 0; i < res->nsol; i++)
        if (res->sol[i].certified && res->sol[i].file && res->sol[i].text) {
            paths[n] = res->sol[i].file;
            texts[n] = res->sol[i].text;
            n++;
        }
    int rc = n ? vigen_write_files_atomic(n, paths, texts, err) : VIGEN_OK;
    free(paths);
    free(texts);
    return rc;
}
