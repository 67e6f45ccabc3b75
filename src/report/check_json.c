/* check_json.c — the JSON report of `vigen check` (vigen_check_print_json):
 * one object; strings through the one JSON writer (json.h).
 */
#include <stdlib.h>
#include <string.h>
#include "vigen/check.h"
#include "check/balls.h"
#include "report/json.h"
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

void vigen_check_print_json(FILE *out, const vigen_check_report *rep)
{
    static const char *const kinds[] = {"rowsum", "symplectic", "claim", "against"};
    static const char *const family_keys[] = {"general", "separable", "A", "At", "nystrom"};
    const vigen_check_orders *g = &rep->orders[VIGEN_CHECK_GENERAL];
    fputs("{\"file\": ", out);
    if (rep->path) vigen_json_write_string(out, rep->path); else fputs("null", out);
    fputs(", \"name\": ", out);
    if (rep->name) vigen_json_write_string(out, rep->name); else fputs("null", out);
    fprintf(out, ", \"stages\": %ld, \"partitioned\": %s, \"precision_bits\": %ld, \"first_precision_bits\": %ld, "
                 "\"evaluations\": %ld, \"max_order\": %d,\n",
            (long)rep->s, rep->has_At ? "true" : "false", (long)rep->prec, (long)rep->prec_first, (long)rep->rounds,
            rep->max_order);
    fprintf(out, " \"rounded_entries\": %s, \"exact_entries\": %s,\n", rep->rounded_entries ? "true" : "false",
            rep->exact_entries ? "true" : "false");
    if (rep->rational_denominator)
        fprintf(out, " \"rational_denominator\": \"%s\", \"proved\": %ld,\n", rep->rational_denominator,
                (long)rep->proved);
    else if (rep->quadratic_d)
        fprintf(out, " \"quadratic_field\": \"sqrt(%s)\", \"denominator\": \"%s\", \"proved\": %ld,\n",
                rep->quadratic_d, rep->quadratic_denominator, (long)rep->proved);
    /* holds on exact entries are proofs only in the two cases above */
    fprintf(out, " \"exact_holds_are_proofs\": %s,\n",
            rep->rational_denominator || rep->quadratic_d ? "true" : "false");
    fputs(" \"rule\": \"a condition fails when its ball excludes 0 and holds when it contains 0: on rounded entries "
          "within the precision of the data, with a radius at most 2^-10 of its terms; on exact entries with a radius "
          "below 2^-(prec/2) of its terms and the same verdicts at two precisions; otherwise it is undecided\",\n",
          out);
    fprintf(out, " \"data_threshold_bits\": %d,\n", VIGEN_CHECK_DATA_BITS);
    fputs(" \"notes\": [", out);
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
    fputs(rep->nnotes ? "\n ],\n" : "],\n", out);
    fputs(" \"reducible\": ", out);
    if (rep->reducible) vigen_json_write_string(out, rep->reducible);
    else fputs("null", out);
    fputs(",\n", out);
    static const char *const sect_keys[] = {"rowsum", "symplectic", "order", "simplifying", "against"};
    fputs(" \"holding\": {", out);
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
    fputs("},\n", out);
    fputs(" \"consistent\": ", out);
    json_tri(out, rep->consistent);
    fputs(", \"symplectic\": ", out);
    json_tri(out, rep->symplectic);
    fputs(", \"symplectic_separable\": ", out);
    json_tri(out, rep->symplectic_separable);
    fprintf(out, ",\n \"consistent_within_data\": %s, \"symplectic_within_data\": %s",
            rep->consistent_within_data ? "true" : "false", rep->symplectic_within_data ? "true" : "false");
    fprintf(out, ",\n \"order\": %d, \"order_status\": \"%s\", \"order_within_data\": %s, \"order_separable\": %d, "
                 "\"order_separable_status\": \"%s\",\n",
            g->level.value, level_status(&g->level), g->level.within_data ? "true" : "false",
            rep->orders[VIGEN_CHECK_SEPARABLE].level.value, level_status(&rep->orders[VIGEN_CHECK_SEPARABLE].level));
    fprintf(out, " \"order_A\": %d, \"order_At\": %d,\n", rep->orders[VIGEN_CHECK_A_ALONE].level.value,
            rep->orders[VIGEN_CHECK_AT_ALONE].level.value);
    fputs(" \"orders\": {", out);
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
    fputs("},\n \"simplifying\": {", out);
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
    const vigen_check_theorem *th = &rep->theorem;
    fprintf(out, "},\n \"butcher_theorem\": {\"applies\": %s, \"order\": %d, \"B\": %d, \"C\": %d, \"D\": %d, "
                 "\"within_data\": %s, \"why_not\": ",
            th->applies ? "true" : "false", th->order, th->B, th->eta, th->zeta, th->within_data ? "true" : "false");
    if (th->why_not) vigen_json_write_string(out, th->why_not);
    else fputs("null", out);
    fprintf(out, ", \"bushy_tree_fails\": {\"general\": %d, \"separable\": %d, \"checked_to\": %d}",
            th->bushy_fail[0], th->bushy_fail[1], th->bushy_to);
    fputs("},\n \"claims\": {", out);
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
    fputs("},\n \"problems\": [", out);
    for (slong k = 0; k < rep->nproblems; k++) {
        const vigen_check_problem *p = rep->problems + k;
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
    fputs(rep->nproblems ? "\n ]" : "]", out);
    vigen_report_figures_json(out, rep);
    fputs(",\n \"notation\": ", out);
    vigen_json_write_string(out, vigen_tree_notation_help());
    if (rep->against_checked)
        fprintf(out, ",\n \"against\": {\"differences\": %ld, \"undecided\": %ld}", (long)rep->against_differences,
                (long)rep->against_undecided);
    fprintf(out, ",\n \"undecided_conditions\": %ld, \"undecided_too_short\": %ld, \"undecided_reason\": ",
            (long)rep->undecided_left, (long)rep->undecided_short);
    if (rep->undecided_reason) vigen_json_write_string(out, rep->undecided_reason); else fputs("null", out);
    fprintf(out, ",\n \"exit\": %d}\n", rep->exit_code);
}

