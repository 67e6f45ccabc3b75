/* check_json.c — the JSON report of `vigen check` (vigen_check_print_json):
 * one object, a member per X_FIGURE and X_RESULT row of
 * vigen/check_fields.def; strings through the one
 * JSON writer (json.h).  The writers of the CUSTOM rows are here.
 */
#include <stdlib.h>
#include <string.h>
#include "vigen/check.h"
#include "check/balls.h"
#include "report/json.h"
#include "report/check_fields.h"
#include "report/check_figures.h"

static void json_ball(FILE *out, const arb_t x, slong prec)
{
    slong digits = (slong)(prec * 0.30103);
    if (digits > 60) digits = 60;
    if (digits < 10) digits = 10;
    char *s = vigen_ball_json_str(x, digits);
    vigen_json_write_string(out, s);
    free(s);
}

static void json_tri(FILE *out, int v)
{
    fputs(v == VIGEN_CHECK_YES ? "true" : v == VIGEN_CHECK_NO ? "false" : "null", out);
}

/* "exact": the level is certainly value; "within_data": it is value, resting
 * on conditions that hold within the precision of the data; "at_least" and
 * "at_least_within_data": everything up to the cap holds; "undecided":
 * value + 1 is undecided. */
static const char *level_status(const vigen_check_level *L)
{
    if (L->capped) return L->within_data ? "at_least_within_data" : "at_least";
    if (L->undecided) return "undecided";
    return L->within_data ? "within_data" : "exact";
}

static void json_level(FILE *out, const vigen_check_level *L)
{
    fprintf(out, "{\"value\": %d, \"status\": \"%s\", \"within_data\": %s, \"data_too_short\": %s}", L->value,
            level_status(L), L->within_data ? "true" : "false", L->undecided && L->too_short ? "true" : "false");
}

static void json_bad_tree(FILE *out, const vigen_check_orders *o, slong prec)
{
    const vigen_check_level *L = &o->level;
    const char *tree = L->capped ? NULL : L->undecided ? o->undecided_tree : o->fail_tree;
    if (tree == NULL) { fputs("null", out); return; }
    fputs("{\"tree\": ", out);
    vigen_json_write_string(out, tree);
    fprintf(out, ", \"order\": %d, \"undecided\": %s, \"value\": ", L->value + 1, L->undecided ? "true" : "false");
    json_ball(out, L->undecided ? o->undecided_value : o->fail_value, prec);
    fputs(", \"expected\": ", out);
    json_ball(out, L->undecided ? o->undecided_expected : o->fail_expected, prec);
    fputc('}', out);
}


static void json_string_or_null(FILE *out, const char *s)
{
    if (s) vigen_json_write_string(out, s);
    else fputs("null", out);
}

static void json_quadratic_field(FILE *out, const vigen_check_report *rep)
{
    fprintf(out, "\"sqrt(%s)\"", rep->quadratic_d);
}

static void json_notes(FILE *out, const vigen_check_report *rep)
{
    fputc('[', out);
    for (slong k = 0; k < rep->nnotes; k++) {
        const vigen_check_note *n = rep->notes + k;
        fputs(k ? ",\n  {\"entry\": " : "\n  {\"entry\": ", out);
        vigen_json_write_string(out, n->entry);
        fputs(", \"text\": ", out);
        vigen_json_write_string(out, n->text);
        if (n->expression) {
            fputs(", \"expression\": ", out);
            vigen_json_write_string(out, n->expression);
        }
        fprintf(out, ", \"significant_digits\": %ld, \"radius\": ", (long)n->digits);
        vigen_json_write_string(out, n->radius);
        fputs(", \"exact_value\": ", out);
        vigen_json_write_string(out, n->fraction);
        fputs(", \"message\": ", out);
        vigen_json_write_string(out, n->message);
        fputc('}', out);
    }
    fputs(rep->nnotes ? "\n ]" : "]", out);
}

/* how the holding conditions of each section were decided */
static void json_holding(FILE *out, const vigen_check_report *rep)
{
    static const char *const sect_keys[] = {"rowsum", "symplectic", "order", "simplifying", "against"};
    fputc('{', out);
    for (int k = 0; k < VIGEN_CHECK_SECTIONS; k++) {
        const vigen_check_holds *h = rep->holds + k;
        if (k == VIGEN_CHECK_SECT_AGAINST && !rep->against_checked) continue;
        fprintf(out, "%s\"%s\": {\"exact\": %ld, \"within_data_precision\": %ld, \"undecided_too_short\": %ld, "
                     "\"radius\": ", k ? ", " : "", sect_keys[k], (long)h->exact, (long)h->data, (long)h->too_short);
        if (h->data) {
            char *r = vigen_mag_str(h->radius);
            vigen_json_write_string(out, r);
            free(r);
        } else fputs("null", out);
        fputc('}', out);
    }
    fputc('}', out);
}

static void json_orders(FILE *out, const vigen_check_report *rep)
{
    static const char *const family_keys[] = {"general", "separable", "A", "At", "nystrom"};
    fputc('{', out);
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
        const vigen_check_orders *o = &rep->orders[f];
        fprintf(out, "%s\n  \"%s\": {\"level\": ", f ? "," : "", family_keys[f]);
        json_level(out, &o->level);
        fputs(", \"first_bad_tree\": ", out);
        json_bad_tree(out, o, rep->prec);
        fputs(", \"per_order\": [", out);
        for (int n = 1; n <= o->evaluated_to; n++)
            fprintf(out, "%s{\"order\": %d, \"conditions\": %ld, \"hold\": %ld, \"fail\": %ld, \"undecided\": %ld, "
                         "\"evaluated\": %ld, \"from_symplecticity\": %ld}",
                    n > 1 ? ", " : "", n, (long)o->count[n], (long)o->hold[n], (long)o->fail[n],
                    (long)o->undecided[n], (long)(o->count[n] - o->inferred[n]), (long)o->inferred[n]);
        fputs("]}", out);
    }
    fputc('}', out);
}

static void json_simplifying(FILE *out, const vigen_check_report *rep)
{
    fputc('{', out);
    for (int part = 0; part < 2; part++) {
        fprintf(out, "%s\"%s\": {\"B\": ", part ? ", " : "", part ? "At" : "A");
        json_level(out, &rep->B[part]);
        fputs(", \"C\": ", out);
        json_level(out, &rep->C[part]);
        fputs(", \"D\": ", out);
        json_level(out, &rep->D[part]);
        fputs(", \"stage_order\": ", out);
        json_level(out, &rep->stage_order[part]);
        fputc('}', out);
    }
    fputc('}', out);
}

static void json_theorem(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_theorem *th = &rep->theorem;
    fprintf(out, "{\"applies\": %s, \"order\": %d, \"B\": %d, \"C\": %d, \"D\": %d, \"within_data\": %s, \"why_not\": ",
            th->applies ? "true" : "false", th->order, th->B, th->eta, th->zeta, th->within_data ? "true" : "false");
    json_string_or_null(out, th->why_not);
    fprintf(out, ", \"bushy_tree_fails\": {\"general\": %d, \"separable\": %d, \"checked_to\": %d}}",
            th->bushy_fail[0], th->bushy_fail[1], th->bushy_to);
}

static void json_claims(FILE *out, const vigen_check_report *rep)
{
    fputc('{', out);
    int first = 1;
    if (rep->claim_order >= 0) {
        fprintf(out, "\"order\": {\"claimed\": %d, \"holds\": ", rep->claim_order);
        json_tri(out, rep->claim_order_status);
        fprintf(out, ", \"separable_only\": %s, \"beyond_max_order\": %s, \"within_data\": %s, \"data_too_short\": %s, "
                     "\"by_simplifying_assumptions\": %s}",
                rep->claim_order_separable ? "true" : "false", rep->claim_order_beyond ? "true" : "false",
                rep->claim_order_within_data ? "true" : "false", rep->claim_order_too_short ? "true" : "false",
                rep->claim_order_theorem ? "true" : "false");
        first = 0;
    }
    if (rep->claim_symplectic >= 0) {
        fprintf(out, "%s\"symplectic\": {\"claimed\": %s, \"holds\": ", first ? "" : ", ",
                rep->claim_symplectic ? "true" : "false");
        json_tri(out, rep->claim_symplectic_status);
        fprintf(out, ", \"separable_only\": %s, \"within_data\": %s}", rep->claim_symplectic_separable ? "true" : "false",
                rep->claim_symplectic_within_data ? "true" : "false");
        first = 0;
    }
    for (int f = 0; f < 2; f++)
        if (rep->claim_order_family[f] >= 0) {
            fprintf(out, "%s\"%s\": {\"claimed\": %d, \"holds\": ", first ? "" : ", ",
                    f ? "order_nystrom" : "order_separable", rep->claim_order_family[f]);
            json_tri(out, rep->claim_order_family_status[f]);
            fputc('}', out);
            first = 0;
        }
    fputc('}', out);
}

static void json_problems(FILE *out, const vigen_check_report *rep)
{
    static const char *const kinds[] = {"rowsum", "symplectic", "claim", "against"};
    fputc('[', out);
    for (slong k = 0; k < rep->nfailures; k++) {
        const vigen_check_failure *p = rep->failures + k;
        fprintf(out, "%s\n  {\"kind\": \"%s\"", k ? "," : "", kinds[p->kind]);
        if (p->claim) fprintf(out, ", \"claim\": \"%s\"", p->claim);
        if (p->matrix) fprintf(out, ", \"matrix\": \"%s\"", p->matrix);
        if (p->row) fprintf(out, ", \"row\": %ld", (long)p->row);
        if (p->col) fprintf(out, ", \"col\": %ld", (long)p->col);
        if (p->has_value) { fputs(", \"value\": ", out); json_ball(out, p->value, rep->prec); }
        else if (p->value_json) fprintf(out, ", \"value\": %s", p->value_json);
        if (p->has_expected) { fputs(", \"expected\": ", out); json_ball(out, p->expected, rep->prec); }
        else if (p->expected_json) fprintf(out, ", \"expected\": %s", p->expected_json);
        if (p->undecided) fputs(", \"undecided\": true", out);
        if (p->diagnosed) fputs(", \"diagnosed\": true", out);
        fputs(", \"message\": ", out);
        vigen_json_write_string(out, p->message ? p->message : "");
        fputc('}', out);
    }
    fputs(rep->nfailures ? "\n ]" : "]", out);
}

static void json_against(FILE *out, const vigen_check_report *rep)
{
    fprintf(out, "{\"differences\": %ld, \"undecided\": %ld}", (long)rep->against_differences,
            (long)rep->against_undecided);
}

/* a JSON number: the midpoint to 17 digits, or null when not finite */
static void json_number(FILE *out, const arb_t x)
{
    if (!arb_is_finite(x)) {
        fputs("null", out);
        return;
    }
    double d = arf_get_d(arb_midref(x), ARF_RND_NEAR);
    fprintf(out, "%.17g", d);
}

/* ", \"ball\": \"...\"": x to 20 digits as a ball */
static void json_ball20(FILE *out, const arb_t x)
{
    char *b = vigen_ball_json_str(x, 20);
    fprintf(out, ", \"ball\": \"%s\"", b);
    free(b);
}

static void json_design_order(FILE *out, const vigen_check_report *rep)
{
    int hf = vigen_report_higher_family(rep);
    if (hf >= 0)
        fprintf(out, "{\"order\": %d, \"family\": \"%s\"}",
                rep->orders[hf == 1 ? VIGEN_CHECK_SEPARABLE : VIGEN_CHECK_NYSTROM].level.value,
                vigen_report_ec_key[hf]);
    else fprintf(out, "{\"order\": %d, \"family\": \"general\"}", rep->orders[VIGEN_CHECK_GENERAL].level.value);
}

/* the error constant of the design family */
static void json_error_constant(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_error_constant *d = &rep->error_constant[vigen_report_design_family(rep)];
    if (d->available) json_number(out, d->value);
    else fputs("null", out);
}

static void json_error_constants(FILE *out, const vigen_check_report *rep)
{
    fputc('{', out);
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
        const vigen_check_error_constant *e = &rep->error_constant[f];
        fprintf(out, "%s\"%s\": ", f ? ", " : "", vigen_report_ec_key[f]);
        if (!e->available) {
            fputs("null", out);
            continue;
        }
        fprintf(out, "{\"order\": %d, \"trees\": %ld, \"value\": ", e->order, (long)e->ntrees);
        json_number(out, e->value);
        json_ball20(out, e->value);
        fputc('}', out);
    }
    fputc('}', out);
}

static void json_lie_error(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_lie_error *le = &rep->lie_error;
    if (!le->computed) {
        fputs("null", out);
        return;
    }
    fprintf(out, "{\"degree\": %d, \"norm\": ", le->degree);
    json_number(out, le->norm);
    fputs(", \"terms\": [", out);
    for (slong k = 0; k < le->nterms; k++) {
        fprintf(out, "%s{\"word\": \"%s\", \"bracket\": \"%s\", \"coefficient\": ", k ? ", " : "", le->words[k],
                le->brackets[k]);
        json_number(out, le->coef + k);
        json_ball20(out, le->coef + k);
        fputc('}', out);
    }
    fputs("]}", out);
}

static const char *gen_state_word(int state)
{
    return state == VIGEN_GEN_DECIDED ? "decided" : state == VIGEN_GEN_AT_LEAST ? "at_least" : "undecided";
}

static void json_generalized(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_generalized *g = rep->generalized;
    if (g == NULL || !g->computed) {
        fputs("null", out);
        return;
    }
    fprintf(out, "{\"A\": \"%s\", \"B\": \"%s\", \"processed\": %s, \"degree\": %d, \"rounded\": %s, "
                 "\"within_data\": %s, \"why\": ", g->letter_a, g->letter_b, g->processed ? "true" : "false",
            g->degree, g->rounded ? "true" : "false", g->within_data ? "true" : "false");
    if (g->why) fprintf(out, "\"%s\"", g->why);
    else fputs("null", out);
    if (g->brackets > 0) fprintf(out, ", \"bracket_flows\": %d", g->brackets);
    if (!g->why) {
        fprintf(out, ", \"classical_order\": %d, \"classical_status\": \"%s\", \"orders\": [", g->classical,
                gen_state_word(g->classical_state));
        for (int j = 1; j <= g->k; j++) fprintf(out, "%s%d", j > 1 ? ", " : "", g->r[j]);
        fputs("], \"orders_status\": [", out);
        for (int j = 1; j <= g->k; j++) fprintf(out, "%s\"%s\"", j > 1 ? ", " : "", gen_state_word(g->state[j]));
        fputs("], \"terms\": [", out);
        int first = 1;
        for (int j = 1; j <= g->k; j++) {
            const vigen_check_lie_error *le = &g->terms[j];
            if (!le->computed) continue;
            fprintf(out, "%s{\"eps\": %d, \"h\": %d, \"degree\": %d, \"norm\": ", first ? "" : ", ", j, g->r[j],
                    le->degree);
            first = 0;
            json_number(out, le->norm);
            fputs(", \"terms\": [", out);
            for (slong k = 0; k < le->nterms; k++) {
                fprintf(out, "%s{\"word\": \"%s\", \"bracket\": \"%s\", \"coefficient\": ", k ? ", " : "",
                        le->words[k], le->brackets[k]);
                json_number(out, le->coef + k);
                json_ball20(out, le->coef + k);
                fputc('}', out);
            }
            fputs("]}", out);
        }
        fputc(']', out);
    }
    fputs(", \"claim\": ", out);
    if (g->claim_status < 0) fputs("null", out);
    else {
        fputc('[', out);
        for (int j = 0; j < g->claim_k; j++) fprintf(out, "%s%d", j ? ", " : "", g->claim[j]);
        fprintf(out, "], \"claim_status\": \"%s\"", g->claim_status == VIGEN_CHECK_YES ? "holds" :
                g->claim_status == VIGEN_CHECK_NO ? "fails" : "undecided");
    }
    fputc('}', out);
}

static void json_stability_interval(FILE *out, const vigen_check_report *rep)
{
    if (rep->stability.status == VIGEN_CHECK_STAB_BOUNDED) json_number(out, rep->stability.x);
    else fputs("null", out);
}

static void json_stability(FILE *out, const vigen_check_report *rep)
{
    static const char *const words[] = {"none", "bounded", "unbounded", "undecided"};
    const vigen_check_stability *st = &rep->stability;
    fprintf(out, "{\"status\": \"%s\"", words[st->status]);
    if (st->status == VIGEN_CHECK_STAB_BOUNDED) json_ball20(out, st->x);
    fputs(", \"reason\": ", out);
    json_string_or_null(out, st->reason);
    fputc('}', out);
}

static void json_cost(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_cost *c = &rep->cost;
    fprintf(out, "{\"stages\": %ld, \"force\": %ld, \"velocity\": %ld, \"fsal\": %s, \"explicit_separable\": %s, "
                 "\"explicit_general\": %s}",
            (long)c->stages, (long)c->force, (long)c->velocity, c->fsal ? "true" : "false",
            c->explicit_separable ? "true" : "false", c->explicit_general ? "true" : "false");
}

/* the JSON columns of check_fields.def: the separators and the value types */
#define SEP_COMMA ", "
#define SEP_LINE ",\n "
#define JSON_BOOL(v) fputs((v) ? "true" : "false", out)
#define JSON_INT(v) fprintf(out, "%d", (int)(v))
#define JSON_LONG(v) fprintf(out, "%ld", (long)(v))
#define JSON_TRI(v) json_tri(out, (v))
#define JSON_STR(v) json_string_or_null(out, (v))
#define JSON_BALL(v) json_number(out, (v))
#define JSON_CUSTOM(writer) writer(out, rep)

void vigen_check_print_json(FILE *out, const vigen_check_report *rep)
{
    int first = 1;
#define X_CHECK(name, fn, description)
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn)                                                      \
    if (when) {                                                                                                        \
        fprintf(out, "%s\"" #key "\": ", first ? "{" : SEP_##sep);                                                    \
        JSON_##type(value);                                                                                            \
        first = 0;                                                                                                     \
    }
/* the member of a check's own row: null until the check sets it */
#define X_RESULT(name, fn, description, type, sep, text_at, label)                                                   \
    fprintf(out, "%s\"" #name "\": ", first ? "{" : SEP_##sep);                                                       \
    if (rep->name.set) JSON_##type(rep->name.value);                                                                   \
    else fputs("null", out);                                                                                           \
    first = 0;
#include "vigen/check_fields.def"
#undef X_CHECK
#undef X_FIGURE
#undef X_RESULT
    fputs("}\n", out);
}
