/* checks.c — one round of `vigen check`: every check of
 * vigen/check_fields.def (its X_CHECK and X_RESULT rows), in the table's
 * order, at the precision of the context.  The refinement loop
 * (refine.c) runs rounds until the verdicts settle.
 */
#include <string.h>
#include "check/check_internal.h"
#include "vigen/check.h"
#include "support/strbuf.h"

typedef struct {
    const char *name;
    chk_check_fn run;
    const char *description;
} chk_check_row;

static const chk_check_row checks[] = {
#define X_CHECK(name, fn, description) {#name, fn, description},
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn)
#define X_RESULT(name, fn, description, type, sep, text_at, label) {#name, fn, description},
#include "vigen/check_fields.def"
#undef X_CHECK
#undef X_FIGURE
#undef X_RESULT
};

static void report_reset_round(vigen_check_report *rep)
{
    chk_failures_clear(rep);
    chk_results_reset(rep);
    rep->against_checked = 0;
    rep->against_differences = 0;
    rep->against_undecided = 0;
    for (int k = 0; k < VIGEN_CHECK_SECTIONS; k++) {
        rep->holds[k].exact = rep->holds[k].data = rep->holds[k].too_short = 0;
        mag_zero(rep->holds[k].radius);
    }
}

static void round_clear(chk_round *r)
{
    for (slong k = 0; k < r->nconds; k++) arb_clear(r->conds[k].r);
    flint_free(r->conds);
    if (r->have_mid) chk_midpoints_clear(&r->mid);
}

/* One round of every check at the precision of t (and against). */
int chk_round_run(vigen_check_report *rep, ctx_t *cx, vigen_tableau *t, vigen_tableau *against,
                  const exactness *ex_against, int P, vigen_error *err)
{
    report_reset_round(rep);
    if (cx->conj) chk_conj_log_start(cx->conj, cx->conj_recording);
    chk_round r;
    memset(&r, 0, sizeof(r));
    r.rep = rep;
    r.cx = cx;
    r.t = t;
    r.against = against;
    r.ex_against = ex_against;
    r.P = P;
    int rc = VIGEN_OK;
    for (size_t k = 0; k < sizeof(checks) / sizeof(checks[0]) && rc == VIGEN_OK; k++) rc = checks[k].run(&r, err);
    round_clear(&r);
    return rc;
}

char *vigen_check_list_text(void)
{
    size_t width = 0;
    for (size_t k = 0; k < sizeof(checks) / sizeof(checks[0]); k++)
        if (strlen(checks[k].name) > width) width = strlen(checks[k].name);
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "The checks of 'vigen check', in the order they run on every round:\n");
    for (size_t k = 0; k < sizeof(checks) / sizeof(checks[0]); k++)
        vigen_strbuf_printf(&sb, "  %-*s  %s\n", (int)width, checks[k].name, checks[k].description);
    return sb.data ? sb.data : vigen_strdup("");
}
