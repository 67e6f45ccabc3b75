/* report_init.c — the report of `vigen check` as data: options and report
 * set up and torn down, and the list of problems the checks file into it
 * (src/report/check_text.c and check_json.c print it).
 */
#include <stdlib.h>
#include <string.h>
#include "check/check_internal.h"

void vigen_check_options_init(vigen_check_options *opt)
{
    memset(opt, 0, sizeof(*opt));
    opt->max_order = CHK_DEFAULT_MAX_ORDER;
    opt->max_prec = CHK_DEFAULT_MAX_PREC;
    opt->spec_digits = 34;
    opt->generalized = 1;
}

vigen_check_failure *chk_failure_new(vigen_check_report *rep, int kind)
{
    if (rep->nfailures == rep->alloc_failures) {
        rep->alloc_failures = rep->alloc_failures ? 2 * rep->alloc_failures : 16;
        rep->failures = flint_realloc(rep->failures, sizeof(vigen_check_failure) * (size_t)rep->alloc_failures);
    }
    vigen_check_failure *p = rep->failures + rep->nfailures++;
    memset(p, 0, sizeof(*p));
    p->kind = kind;
    arb_init(p->value);
    arb_init(p->expected);
    return p;
}

void chk_failures_clear(vigen_check_report *rep)
{
    for (slong k = 0; k < rep->nfailures; k++) {
        vigen_check_failure *p = rep->failures + k;
        arb_clear(p->value);
        arb_clear(p->expected);
        free(p->value_json);
        free(p->expected_json);
        free(p->message);
    }
    flint_free(rep->failures);
    rep->failures = NULL;
    rep->nfailures = rep->alloc_failures = 0;
}

/* The members of the X_RESULT rows: set, value and text, by the value's type
 * (BALL values hold an arb_t, STR values and texts are from malloc). */
#define RESULT_INIT_BOOL(v) (void)0
#define RESULT_INIT_INT(v) (void)0
#define RESULT_INIT_LONG(v) (void)0
#define RESULT_INIT_TRI(v) (void)0
#define RESULT_INIT_STR(v) (void)0
#define RESULT_INIT_BALL(v) arb_init(v)
#define RESULT_CLEAR_BOOL(v) (void)0
#define RESULT_CLEAR_INT(v) (void)0
#define RESULT_CLEAR_LONG(v) (void)0
#define RESULT_CLEAR_TRI(v) (void)0
#define RESULT_CLEAR_STR(v) free(v)
#define RESULT_CLEAR_BALL(v) arb_clear(v)
#define X_CHECK(name, fn, description)
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn)

/* every member zero (memset by the caller), BALL values initialised */
static void results_init(vigen_check_report *rep)
{
#define X_RESULT(name, fn, description, type, sep, text_at, label) RESULT_INIT_##type(rep->name.value);
#include "vigen/check_fields.def"
#undef X_RESULT
}

static void results_clear(vigen_check_report *rep)
{
#define X_RESULT(name, fn, description, type, sep, text_at, label)                                                   \
    RESULT_CLEAR_##type(rep->name.value);                                                                              \
    free(rep->name.text);
#include "vigen/check_fields.def"
#undef X_RESULT
}

void chk_results_reset(vigen_check_report *rep)
{
    results_clear(rep);
#define X_RESULT(name, fn, description, type, sep, text_at, label) memset(&rep->name, 0, sizeof(rep->name));
#include "vigen/check_fields.def"
#undef X_RESULT
    results_init(rep);
}
#undef X_CHECK
#undef X_FIGURE

void vigen_check_report_init(vigen_check_report *rep)
{
    memset(rep, 0, sizeof(*rep));
    results_init(rep);
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
        arb_init(rep->orders[f].fail_value);
        arb_init(rep->orders[f].fail_expected);
        arb_init(rep->orders[f].undecided_value);
        arb_init(rep->orders[f].undecided_expected);
    }
    for (int k = 0; k < VIGEN_CHECK_SECTIONS; k++) mag_init(rep->holds[k].radius);
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
        arb_init(rep->error_constant[f].value);
        for (int n = 0; n <= VIGEN_TREE_MAX_ORDER; n++) arb_init(rep->error_constant[f].sumsq[n]);
    }
    arb_init(rep->stability.x);
    arb_init(rep->lie_error.norm);
    rep->claim_order = -1;
    rep->claim_symplectic = -1;
    rep->claim_order_family[0] = rep->claim_order_family[1] = -1;
}

void chk_notes_clear(vigen_check_report *rep)
{
    for (slong k = 0; k < rep->nnotes; k++) {
        vigen_check_note *n = rep->notes + k;
        free(n->entry);
        free(n->text);
        free(n->expression);
        free(n->radius);
        free(n->fraction);
        free(n->message);
    }
    free(rep->notes);
    rep->notes = NULL;
    rep->nnotes = 0;
    free(rep->reducible);
    rep->reducible = NULL;
}

/* rep->generalized (generalized.c allocates it on the first round) */
static void generalized_free(vigen_check_generalized *g)
{
    if (g == NULL) return;
    for (int j = 0; j <= VIGEN_GEN_MAX_DEGREE; j++) {
        chk_lie_error_clear(&g->terms[j]);
        arb_clear(g->terms[j].norm);
    }
    free(g->letter_a);
    free(g->letter_b);
    free(g);
}

void vigen_check_report_clear(vigen_check_report *rep)
{
    chk_failures_clear(rep);
    chk_notes_clear(rep);
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
        free(rep->orders[f].fail_tree);
        free(rep->orders[f].undecided_tree);
        arb_clear(rep->orders[f].fail_value);
        arb_clear(rep->orders[f].fail_expected);
        arb_clear(rep->orders[f].undecided_value);
        arb_clear(rep->orders[f].undecided_expected);
    }
    for (int k = 0; k < VIGEN_CHECK_SECTIONS; k++) mag_clear(rep->holds[k].radius);
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
        arb_clear(rep->error_constant[f].value);
        for (int n = 0; n <= VIGEN_TREE_MAX_ORDER; n++) arb_clear(rep->error_constant[f].sumsq[n]);
    }
    arb_clear(rep->stability.x);
    chk_lie_error_clear(&rep->lie_error);
    arb_clear(rep->lie_error.norm);
    generalized_free(rep->generalized);
    free(rep->path);
    free(rep->name);
    flint_free(rep->rational_denominator);
    flint_free(rep->quadratic_d);
    flint_free(rep->quadratic_denominator);
    results_clear(rep);
    memset(rep, 0, sizeof(*rep));
}

