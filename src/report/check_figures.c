/* check_figures.c — the figures of `vigen check` in the text and JSON
 * reports: principal error constants, the linear stability interval and the
 * cost of a step (docs/analysis.md defines each). */
#include <stdlib.h>
#include "report/check_figures.h"
#include "check/balls.h"
#include "report/json.h"

static const char *const ec_title[VIGEN_CHECK_EC_FAMILIES] = {"general H", "separable H", "Nystrom H"};
static const char *const ec_key[VIGEN_CHECK_EC_FAMILIES] = {"general", "separable", "nystrom"};

/* the certain digits of x (at most 6) */
static void put_figure(FILE *out, const arb_t x)
{
    char *s = vigen_ball_str(x, 6);
    fputs(s, out);
    free(s);
}

/* The family with the highest decided order when it is above the general
 * order (-1 otherwise): a method designed for separable or Nystrom H. */
static int higher_family(const vigen_check_report *rep)
{
    static const int fam[3] = {VIGEN_CHECK_GENERAL, VIGEN_CHECK_SEPARABLE, VIGEN_CHECK_NYSTROM};
    const vigen_check_level *g = &rep->orders[VIGEN_CHECK_GENERAL].level;
    if (g->capped) return -1;
    int best = -1, value = g->value;
    for (int f = 1; f < 3; f++) {
        const vigen_check_level *L = &rep->orders[fam[f]].level;
        if (L->value > value) {
            best = f;
            value = L->value;
        }
    }
    return best;
}

int vigen_report_design_family(const vigen_check_report *rep)
{
    int hf = higher_family(rep);
    if (hf >= 0) return hf;   /* VIGEN_CHECK_EC_SEPARABLE or VIGEN_CHECK_EC_NYSTROM */
    /* a splitting method (explicit for separable H only) is made for separable H */
    if (rep->cost.explicit_separable && !rep->cost.explicit_general) return VIGEN_CHECK_EC_SEPARABLE;
    return VIGEN_CHECK_EC_GENERAL;
}

void vigen_report_figures_text(FILE *out, const vigen_check_report *rep)
{
    int hf = higher_family(rep);
    if (hf >= 0)
        fprintf(out, "design order  %d%s for %s (general H: %d, separable H: %d, Nystrom H: %d): the method is made "
                     "for %s\n",
                rep->orders[hf == 1 ? VIGEN_CHECK_SEPARABLE : VIGEN_CHECK_NYSTROM].level.value,
                rep->orders[hf == 1 ? VIGEN_CHECK_SEPARABLE : VIGEN_CHECK_NYSTROM].level.capped ? " or more" : "",
                ec_title[hf], rep->orders[VIGEN_CHECK_GENERAL].level.value,
                rep->orders[VIGEN_CHECK_SEPARABLE].level.value, rep->orders[VIGEN_CHECK_NYSTROM].level.value,
                hf == 1 ? "H = T(p) + V(q)" : "H = p^T M^-1 p / 2 + V(q)");
    fputs("error constants (2-norm of (Phi(t) - 1/gamma(t))/sigma(t) over the trees of order p + 1)\n", out);
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
        const vigen_check_error_constant *e = &rep->error_constant[f];
        fprintf(out, "  %-12s ", ec_title[f]);
        if (e->available) {
            fprintf(out, "order %d: ", e->order);
            put_figure(out, e->value);
            fprintf(out, " (%ld trees of order %d)\n", (long)e->ntrees, e->order + 1);
        } else
            fprintf(out, "not computed: the order is not decided below the orders evaluated (%d; --max-order)\n",
                    rep->max_order);
    }
    const vigen_check_lie_error *le = &rep->lie_error;
    if (le->computed) {
        fprintf(out, "Lie basis     principal error h^%d x (Lyndon basis; A drifts, B kicks, in order), 2-norm ",
                le->degree);
        put_figure(out, le->norm);
        fputc('\n', out);
        for (slong k = 0; k < le->nterms; k++) {
            fprintf(out, "  %-28s ", le->brackets[k]);
            put_figure(out, le->coef + k);
            fputc('\n', out);
        }
    }
    const vigen_check_stability *st = &rep->stability;
    fputs("stability     on q'' = -omega^2 q: ", out);
    if (st->status == VIGEN_CHECK_STAB_UNBOUNDED) fputs("stable for every h omega", out);
    else if (st->status == VIGEN_CHECK_STAB_BOUNDED) {
        fputs("stable for h omega < ", out);
        put_figure(out, st->x);
    } else fputs("undecided", out);
    if (st->reason) fprintf(out, " (%s)", st->reason);
    fputc('\n', out);
    const vigen_check_cost *c = &rep->cost;
    fprintf(out, "cost          %ld stage%s; for H = T(p) + V(q): %ld force and %ld velocity evaluations per step%s, %s; "
                 "for general H: %s\n",
            (long)c->stages, c->stages == 1 ? "" : "s", (long)c->force, (long)c->velocity,
            c->fsal ? " (first force = last of the previous step)" : "",
            c->explicit_separable ? "explicit" : "implicit", c->explicit_general ? "explicit" : "implicit");
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

void vigen_report_figures_json(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_error_constant *d = &rep->error_constant[vigen_report_design_family(rep)];
    int hf = higher_family(rep);
    if (hf >= 0)
        fprintf(out, ",\n \"design_order\": {\"order\": %d, \"family\": \"%s\"}",
                rep->orders[hf == 1 ? VIGEN_CHECK_SEPARABLE : VIGEN_CHECK_NYSTROM].level.value, ec_key[hf]);
    else fprintf(out, ",\n \"design_order\": {\"order\": %d, \"family\": \"general\"}",
                 rep->orders[VIGEN_CHECK_GENERAL].level.value);
    fputs(",\n \"error_constant\": ", out);
    if (d->available) json_number(out, d->value);
    else fputs("null", out);
    fputs(",\n \"error_constants\": {", out);
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
        const vigen_check_error_constant *e = &rep->error_constant[f];
        fprintf(out, "%s\"%s\": ", f ? ", " : "", ec_key[f]);
        if (!e->available) {
            fputs("null", out);
            continue;
        }
        fprintf(out, "{\"order\": %d, \"trees\": %ld, \"value\": ", e->order, (long)e->ntrees);
        json_number(out, e->value);
        char *b = vigen_ball_json_str(e->value, 20);
        fprintf(out, ", \"ball\": \"%s\"}", b);
        free(b);
    }
    const vigen_check_lie_error *le = &rep->lie_error;
    fputs("},\n \"lie_error\": ", out);
    if (!le->computed) fputs("null", out);
    else {
        fprintf(out, "{\"degree\": %d, \"norm\": ", le->degree);
        json_number(out, le->norm);
        fputs(", \"terms\": [", out);
        for (slong k = 0; k < le->nterms; k++) {
            fprintf(out, "%s{\"word\": \"%s\", \"bracket\": \"%s\", \"coefficient\": ", k ? ", " : "", le->words[k],
                    le->brackets[k]);
            json_number(out, le->coef + k);
            char *b = vigen_ball_json_str(le->coef + k, 20);
            fprintf(out, ", \"ball\": \"%s\"}", b);
            free(b);
        }
        fputs("]}", out);
    }
    const vigen_check_stability *st = &rep->stability;
    static const char *const words[] = {"none", "bounded", "unbounded", "undecided"};
    fputs(",\n \"stability_interval\": ", out);
    if (st->status == VIGEN_CHECK_STAB_BOUNDED) json_number(out, st->x);
    else fputs("null", out);
    fprintf(out, ", \"stability\": {\"status\": \"%s\"", words[st->status]);
    if (st->status == VIGEN_CHECK_STAB_BOUNDED) {
        char *b = vigen_ball_json_str(st->x, 20);
        fprintf(out, ", \"ball\": \"%s\"", b);
        free(b);
    }
    fputs(", \"reason\": ", out);
    if (st->reason) vigen_json_write_string(out, st->reason);
    else fputs("null", out);
    const vigen_check_cost *c = &rep->cost;
    fprintf(out, "},\n \"evaluations_per_step\": %ld, \"cost\": {\"stages\": %ld, \"force\": %ld, \"velocity\": %ld, "
                 "\"fsal\": %s, \"explicit_separable\": %s, \"explicit_general\": %s}",
            (long)c->force, (long)c->stages, (long)c->force, (long)c->velocity, c->fsal ? "true" : "false",
            c->explicit_separable ? "true" : "false", c->explicit_general ? "true" : "false");
}
