/* check_text.c — the text report of `vigen check` (vigen_check_print_text):
 * the lines of each row of vigen/check_fields.def that has a place in it
 * (text_at), in the order of the places.  Texts that may come from the
 * file (the path, the name, notes and problems quoting entries) are printed
 * escaped (support/printable.h). */
#include <stdlib.h>
#include <string.h>
#include "vigen/check.h"
#include "support/printable.h"
#include "check/balls.h"
#include "report/check_fields.h"
#include "report/check_figures.h"
#include "support/strbuf.h"

static const char *family_title[VIGEN_CHECK_FAMILIES] = {
    "order", "order for separable H = T(p) + V(q)", "(c, A, b) alone as an RK method",
    "(ct, At, bt) alone as an RK method", "order for Nystrom H = p^2/2 + V(q)"};

static const char *const within_words = "within the precision of the data";

/* the certain digits of x (at most 6) */
static void put_figure(FILE *out, const arb_t x)
{
    char *s = vigen_ball_str(x, 6);
    fputs(s, out);
    free(s);
}

/* fputs of a text that may come from the file, escaped */
static void put_shown(const char *text, FILE *out)
{
    char *s = vigen_printable(text);
    fputs(s, out);
    free(s);
}

static void print_level_words(FILE *out, const vigen_check_level *L)
{
    if (L->capped) fprintf(out, "%d or more", L->value);
    else if (L->undecided) fprintf(out, "at least %d", L->value);
    else fprintf(out, "%d", L->value);
    if (L->within_data) fprintf(out, " %s", within_words);
    if (!L->capped && L->undecided)
        fprintf(out, " (order %d undecided%s)", L->value + 1,
                L->too_short ? ": the data are too short to decide" : " at this precision");
}


static void print_bad_tree(FILE *out, const vigen_check_orders *o, const char *indent)
{
    const vigen_check_level *L = &o->level;
    if (L->capped) return;
    int undecided = L->undecided;
    const char *tree = undecided ? o->undecided_tree : o->fail_tree;
    if (tree == NULL) return;
    fprintf(out, "%s%s tree: %s (order %d): sum bhat_i Phi_i = ", indent, undecided ? "first undecided" : "first failing",
            tree, L->value + 1);
    arb_srcptr dv = undecided ? o->undecided_value : o->fail_value, de = undecided ? o->undecided_expected : o->fail_expected;
    /* as many digits as tell the two sides apart in the text */
    char *vs = vigen_ball_str_apart(dv, de, 128), *es = vigen_ball_str_apart(de, dv, 128);
    fprintf(out, "%s, 1/gamma = %s", vs, es);
    free(vs);
    free(es);
    arb_t d;
    arb_init(d);
    arb_sub(d, dv, de, FLINT_MAX(arb_bits(dv), arb_bits(de)) + 64);
    char *ds = vigen_ball_str(d, 6);
    fprintf(out, " (defect %s%s)\n", ds[0] == '[' ? "in " : "", ds);
    free(ds);
    arb_clear(d);
}

static const char *tri_word(int v, const char *yes, const char *no)
{
    return v == VIGEN_CHECK_YES ? yes : v == VIGEN_CHECK_NO ? no : "undecided at this precision";
}

/* tri_word, saying why when undecided for short data */
static const char *tri_word_data(int v, const char *yes, const char *no, int too_short)
{
    if (v == VIGEN_CHECK_UNDECIDED && too_short) return "undecided (the data are too short to decide)";
    return tri_word(v, yes, no);
}

/* " within the precision of the data (radius <= X)" when some holding
 * condition of the section was decided on rounded entries. */
static void print_within(FILE *out, const vigen_check_holds *h)
{
    if (h->data == 0) return;
    char *r = vigen_mag_str(h->radius);
    fprintf(out, " %s (radius <= %s)", within_words, r);
    free(r);
}

/* B(4), B(4)* when it holds within the precision of the data (returns 1 then) */
static int print_assumption(FILE *out, const char *name, const vigen_check_level *L)
{
    if (L->capped) fprintf(out, "%s(>=%d)", name, L->value);
    else if (L->undecided) fprintf(out, "%s(%d, %d undecided%s)", name, L->value, L->value + 1,
                                   L->too_short ? ": data too short" : "");
    else fprintf(out, "%s(%d)", name, L->value);
    if (L->within_data) fputc('*', out);
    return L->within_data;
}

/* A long integer for the text report: its first and last digits and its
 * length ("30000...0000 (870 digits)"); short ones whole.  JSON has them whole. */
static char *short_integer(const char *digits)
{
    size_t n = strlen(digits);
    if (n <= 40) return vigen_strdup(digits);
    return vigen_strdup_printf("%.12s...%s (%lu digits)", digits, digits + n - 8, (unsigned long)n);
}

static void problem_line(FILE *out, const char *message)
{
    fputs("  ", out);
    put_shown(message, out);
    fputc('\n', out);
}

/* the file, its name, its stages */
static void text_header(FILE *out, const vigen_check_report *rep)
{
    put_shown(rep->path ? rep->path : "tableau", out);
    if (rep->name && !(rep->path && strcmp(rep->path, rep->name) == 0)) {
        fputs(" (", out);
        put_shown(rep->name, out);
        fputs(")", out);
    }
    fprintf(out, ": %ld stage%s, %s\n", (long)rep->s, rep->s == 1 ? "" : "s",
            rep->has_At ? "partitioned (A and At given)" : "one RK method for both parts (At = A)");
}

/* what the entries are and the precision they were checked at */
static void text_entries(FILE *out, const vigen_check_report *rep)
{
    if (rep->rational_denominator) {
        char *D = short_integer(rep->rational_denominator);
        fprintf(out, "  entries: exact rationals, common denominator D = %s; ", D);
        free(D);
    } else if (rep->quadratic_d) {
        char *D = short_integer(rep->quadratic_denominator);
        fprintf(out, "  entries: exact, in Q(sqrt(%s)): a + b sqrt(%s), common denominator D = %s; ", rep->quadratic_d,
                rep->quadratic_d, D);
        free(D);
    } else
        fprintf(out, "  entries: %s; ",
                rep->rounded_entries && rep->exact_entries ? "rounded decimals (half-ulp balls) and exact expressions"
                : rep->rounded_entries ? "rounded decimals (half-ulp balls) or balls"
                                       : "exact expressions");
    if (rep->rounds > 1)
        fprintf(out, "checked at %ld bits (%ld evaluations, from %ld bits)\n", (long)rep->prec, (long)rep->rounds,
                (long)rep->prec_first);
    else fprintf(out, "checked at %ld bits (1 evaluation)\n", (long)rep->prec);
}

/* when a condition fails, holds or is undecided, for these entries */
static void text_rule(FILE *out, const vigen_check_report *rep)
{
    if (rep->rational_denominator)
        fputs("  a condition fails when its ball excludes 0; it holds, proved, when its ball lies inside\n"
              "  (-1/(D^k g), 1/(D^k g)), k entries per term and g the denominator of its constant: the value is a\n"
              "  multiple of 1/(D^k g), so 0; otherwise it is undecided\n", out);
    else if (rep->quadratic_d)
        fprintf(out, "  a condition fails when its ball excludes 0; it holds, proved, when |v| |v'| (D^k g)^2 < 1, v' the same\n"
                     "  condition on the conjugate tableau (sqrt(%s) -> -sqrt(%s)), k entries per term and g the denominator\n"
                     "  of its constant: v v' (D^k g)^2 is an integer m^2 - %s n^2, so m = n = 0 and v = 0; otherwise it\n"
                     "  holds only with a radius below 2^-(prec/2) of its terms and the same verdicts at two precisions,\n"
                     "  else it is undecided\n",
                rep->quadratic_d, rep->quadratic_d, rep->quadratic_d);
    else if (!rep->exact_entries)
        fputs("  a condition fails when its ball excludes 0 and holds, within the precision of the data, when it\n"
              "  contains 0 with a radius at most 2^-10 of its terms; a wider ball is undecided (the data are too\n"
              "  short to decide)\n", out);
    else if (!rep->rounded_entries)
        fputs("  a condition fails when its ball excludes 0; it holds when its ball contains 0 with a radius below\n"
              "  2^-(prec/2) of its terms, with the same verdicts at two precisions; otherwise it is undecided.\n"
              "  These holds are numerical confirmations, not proofs (entries outside Q and one Q(sqrt d): only\n"
              "  rational and real quadratic tableaux are proved); the precision starts above the span of the\n"
              "  entries' parts, so that a part like exp(-2000) is seen\n", out);
    else
        fputs("  a condition fails when its ball excludes 0 and holds when it contains 0: within the precision of\n"
              "  the data when it involves a rounded entry and its radius is at most 2^-10 of its terms; on exact\n"
              "  entries only with a radius below 2^-(prec/2) of its terms and the same verdicts at two precisions;\n"
              "  otherwise it is undecided\n", out);
}

/* short decimals that look exact (the first 10) and stages that reduce */
static void text_notes(FILE *out, const vigen_check_report *rep)
{
    for (slong k = 0; k < rep->nnotes && k < 10; k++) {
        fputs("  note: ", out);
        put_shown(rep->notes[k].message, out);
        fputc('\n', out);
    }
    if (rep->reducible) {
        fputs("  note: ", out);
        put_shown(rep->reducible, out);
        fputc('\n', out);
    }
    if (rep->nnotes > 10)
        fprintf(out, "  note: ... and %ld more short decimals (all of them with --json)\n", (long)(rep->nnotes - 10));
}

static void text_rowsums(FILE *out, const vigen_check_report *rep)
{
    fprintf(out, "row sums      %s", tri_word_data(rep->consistent, "hold", "FAIL",
                                                  rep->holds[VIGEN_CHECK_SECT_ROWSUM].too_short > 0));
    if (rep->consistent == VIGEN_CHECK_YES) print_within(out, &rep->holds[VIGEN_CHECK_SECT_ROWSUM]);
    fprintf(out, " (%ld conditions: c_i = sum_j a_ij%s, sum b = 1", (long)rep->row_total,
            rep->has_ct ? ", ct_i = sum_j at_ij" : "");
    if (rep->row_fail) fprintf(out, "; %ld fail", (long)rep->row_fail);
    if (rep->row_undecided) fprintf(out, "; %ld undecided", (long)rep->row_undecided);
    fputs(")\n", out);
}

static void text_symplectic(FILE *out, const vigen_check_report *rep)
{
    fprintf(out, "symplectic    %s", tri_word_data(rep->symplectic, "yes", "no",
                                                  rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].too_short > 0));
    if (rep->symplectic == VIGEN_CHECK_YES) print_within(out, &rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC]);
    fprintf(out, " (%ld condition%s: %sb_i %s_ij + b_j a_ji - b_i b_j = 0", (long)rep->sym_total,
            rep->sym_total == 1 ? "" : "s", rep->has_bt ? "bt = b, " : "", rep->has_At ? "at" : "a");
    if (rep->sym_fail) fprintf(out, "; %ld fail", (long)rep->sym_fail);
    if (rep->sym_undecided) fprintf(out, "; %ld undecided", (long)rep->sym_undecided);
    fputs(")\n", out);
    if (rep->has_bt && rep->symplectic != VIGEN_CHECK_YES)
        fprintf(out, "              for separable H (b_i at_ij + bt_j a_ji - b_i bt_j = 0 suffices): %s\n",
                tri_word_data(rep->symplectic_separable, "yes", "no",
                              rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].too_short > 0));
}

/* the order for general H, its first bad tree, and the conditions of every
 * family per order */
static void text_order(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_orders *g = &rep->orders[VIGEN_CHECK_GENERAL];
    fputs("order         ", out);
    print_level_words(out, &g->level);
    fprintf(out, "   (orders 1..%d checked)\n", rep->max_order);
    print_bad_tree(out, g, "              ");
    if (rep->holds[VIGEN_CHECK_SECT_ORDER].data > 0) {
        char *r = vigen_mag_str(rep->holds[VIGEN_CHECK_SECT_ORDER].radius);
        fprintf(out, "              (%ld conditions hold within the precision of the data: radius <= %s)\n",
                (long)rep->holds[VIGEN_CHECK_SECT_ORDER].data, r);
        free(r);
    }
    if (rep->holds[VIGEN_CHECK_SECT_ORDER].too_short > 0)
        fprintf(out, "              (%ld conditions undecided: the data are too short to decide, their balls contain 0 "
                     "but are wider than 2^-%d of their terms)\n",
                (long)rep->holds[VIGEN_CHECK_SECT_ORDER].too_short, VIGEN_CHECK_DATA_BITS);

    fputs("  order  conditions   hold   fail  undecided |  separable     A alone    At alone     Nystrom\n", out);
    for (int n = 1; n <= g->evaluated_to; n++) {
        fprintf(out, "  %5d  %10ld %6ld %6ld %10ld |", n, (long)g->count[n], (long)g->hold[n], (long)g->fail[n],
                (long)g->undecided[n]);
        for (int f = 1; f < VIGEN_CHECK_FAMILIES; f++) {
            char buf[64];
            snprintf(buf, sizeof(buf), "%ld/%ld", (long)rep->orders[f].hold[n], (long)rep->orders[f].count[n]);
            fprintf(out, " %11s", buf);
        }
        fputc('\n', out);
    }
    if (g->evaluated_to + 1 == rep->max_order)
        fprintf(out, "  (order %d not evaluated: every family already fails)\n", rep->max_order);
    else if (g->evaluated_to < rep->max_order)
        fprintf(out, "  (orders %d..%d not evaluated: every family already fails)\n", g->evaluated_to + 1,
                rep->max_order);
    fputs("  (x/y: conditions holding / conditions of that family)\n", out);
    long total = 0, inferred = 0;
    for (int n = 1; n <= g->evaluated_to; n++) {
        total += (long)g->count[n];
        inferred += (long)g->inferred[n];
    }
    if (inferred > 0)
        fprintf(out, "  (%ld of the %ld conditions follow from the %ld evaluated by symplecticity: a tree and its "
                     "rerooting have opposite residuals; counted as holding%s)\n",
                inferred, total, total - inferred, rep->symplectic_within_data ? " within the precision of the data" : "");
}

/* the order of each family of trees, and its first bad tree when it is not
 * the general one */
static void text_families(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_orders *g = &rep->orders[VIGEN_CHECK_GENERAL];
    for (int f = 1; f < VIGEN_CHECK_FAMILIES; f++) {
        const vigen_check_orders *o = &rep->orders[f];
        if (f == VIGEN_CHECK_AT_ALONE && !rep->has_At) {
            fprintf(out, "%s: same as (c, A, b) (At = A)\n", family_title[f]);
            continue;
        }
        fprintf(out, "%s: ", family_title[f]);
        print_level_words(out, &o->level);
        if (f == VIGEN_CHECK_SEPARABLE && o->level.value == g->level.value && o->level.capped == g->level.capped &&
            o->level.undecided == g->level.undecided && o->level.within_data == g->level.within_data &&
            o->level.too_short == g->level.too_short) {
            fputs(" (same)\n", out);
            continue;
        }
        fputc('\n', out);
        const char *mine = o->level.undecided ? o->undecided_tree : o->fail_tree;
        const char *general = g->level.undecided ? g->undecided_tree : g->fail_tree;
        if (!(mine && general && strcmp(mine, general) == 0 && o->level.value == g->level.value))
            print_bad_tree(out, o, "  ");
    }
}

/* B, C, D and the stage order of each part */
static void text_simplifying(FILE *out, const vigen_check_report *rep)
{
    fputs("simplifying assumptions\n", out);
    for (int part = 0; part < (rep->has_At ? 2 : 1); part++) {
        fprintf(out, "  %-13s ", part ? "(ct, At, bt):" : "(c, A, b):");
        print_assumption(out, "B", &rep->B[part]);
        fputc(' ', out);
        print_assumption(out, "C", &rep->C[part]);
        fputc(' ', out);
        print_assumption(out, "D", &rep->D[part]);
        fputs(", stage order ", out);
        const vigen_check_level *S = &rep->stage_order[part];
        if (S->capped) fprintf(out, ">= %d", S->value);
        else fprintf(out, "%d", S->value);
        if (S->within_data) fputc('*', out);
        if (!S->capped && S->undecided) fputs(S->too_short ? " (undecided above: data too short)" : " (undecided above)", out);
        fputc('\n', out);
    }
    if (!rep->has_At) fputs("  (ct, At, bt):  same (At = A)\n", out);
}

/* Butcher's theorem and the bushy trees; the footnote to the starred
 * assumptions (those that hold within the precision of the data) */
static void text_theorem(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_theorem *th = &rep->theorem;
    int starred = th->applies && th->within_data;
    for (int part = 0; part < (rep->has_At ? 2 : 1); part++)
        starred |= rep->B[part].within_data || rep->C[part].within_data || rep->D[part].within_data ||
                   rep->stage_order[part].within_data;
    if (th->applies)
        fprintf(out, "  order >= %d%s by Butcher's theorem (B(%d), C(%d), D(%d) of both parts, b = bt, c = ct)",
                th->order, th->within_data ? "*" : "", th->B, th->eta, th->zeta);
    else fprintf(out, "  Butcher's theorem does not apply (%s; it needs the row sums, b = bt and c = ct)",
                 th->why_not ? th->why_not : "?");
    if (th->bushy_fail[0])
        fprintf(out, "; the bushy tree of order %d fails: order <= %d", th->bushy_fail[0], th->bushy_fail[0] - 1);
    if (th->bushy_fail[1] && th->bushy_fail[1] != th->bushy_fail[0])
        fprintf(out, " (<= %d for separable H)", th->bushy_fail[1] - 1);
    fputc('\n', out);
    if (starred) {
        char *r = vigen_mag_str(rep->holds[VIGEN_CHECK_SECT_SIMPLIFYING].radius);
        fprintf(out, "  (*: holds %s, radius <= %s)\n", within_words, r);
        free(r);
    }
}

/* the family a method is designed for, when its order is above the general one */
static void text_design_order(FILE *out, const vigen_check_report *rep)
{
    int hf = vigen_report_higher_family(rep);
    if (hf >= 0)
        fprintf(out, "design order  %d%s for %s (general H: %d, separable H: %d, Nystrom H: %d): the method is made "
                     "for %s\n",
                rep->orders[hf == 1 ? VIGEN_CHECK_SEPARABLE : VIGEN_CHECK_NYSTROM].level.value,
                rep->orders[hf == 1 ? VIGEN_CHECK_SEPARABLE : VIGEN_CHECK_NYSTROM].level.capped ? " or more" : "",
                vigen_report_ec_title[hf], rep->orders[VIGEN_CHECK_GENERAL].level.value,
                rep->orders[VIGEN_CHECK_SEPARABLE].level.value, rep->orders[VIGEN_CHECK_NYSTROM].level.value,
                hf == 1 ? "H = T(p) + V(q)" : "H = p^T M^-1 p / 2 + V(q)");
}

static void text_error_constants(FILE *out, const vigen_check_report *rep)
{
    fputs("error constants (2-norm of (Phi(t) - 1/gamma(t))/sigma(t) over the trees of order p + 1)\n", out);
    for (int f = 0; f < VIGEN_CHECK_EC_FAMILIES; f++) {
        const vigen_check_error_constant *e = &rep->error_constant[f];
        fprintf(out, "  %-12s ", vigen_report_ec_title[f]);
        if (e->available) {
            fprintf(out, "order %d: ", e->order);
            put_figure(out, e->value);
            fprintf(out, " (%ld trees of order %d)\n", (long)e->ntrees, e->order + 1);
        } else
            fprintf(out, "not computed: the order is not decided below the orders evaluated (%d; --max-order)\n",
                    rep->max_order);
    }
}

/* the principal error of a splitting in the Lyndon basis */
static void text_lie_error(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_lie_error *le = &rep->lie_error;
    if (le->computed) {
        const vigen_check_generalized *g = rep->generalized;
        if (g && g->computed)
            fprintf(out, "Lie basis     principal error h^%d x (Lyndon basis; A %s, B %s, in order), 2-norm ",
                    le->degree, g->flipped ? g->letter_b : g->letter_a, g->flipped ? g->letter_a : g->letter_b);
        else
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
}

static void text_orders_list(FILE *out, const vigen_check_generalized *g, int k)
{
    fputc('(', out);
    for (int j = 1; j <= k; j++)
        fprintf(out, "%s%s%d", j > 1 ? "," : "", g->state[j] == VIGEN_GEN_DECIDED ? "" : ">=", g->r[j]);
    fputc(')', out);
}

static void text_generalized(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_generalized *g = rep->generalized;
    if (g == NULL || !g->computed) return;
    fprintf(out, "generalized   H = %s + eps %s (A = %s, B = %s)%s\n", g->letter_a, g->letter_b, g->letter_a,
            g->letter_b, g->processed ? "; the step C K C^-1 of the processed method" : "");
    if (g->brackets > 0)
        fprintf(out, "  with %d bracket flow%s (their terms below); the tableau above, its trees, stability and cost "
                "are those of the plain flows' substeps alone\n", g->brackets, g->brackets > 1 ? "s" : "");
    if (g->why) fprintf(out, "  not decided: %s\n", g->why);
    else {
        fputs("  generalized order ", out);
        text_orders_list(out, g, g->k);
        fputs(": error O(", out);
        for (int j = 1; j <= g->k; j++)
            fprintf(out, "%seps%s%.0d h^%s%d", j > 1 ? " + " : "", j > 1 ? "^" : "", j > 1 ? j : 0,
                    g->state[j] == VIGEN_GEN_DECIDED ? "" : ">=", g->r[j]);
        fprintf(out, "); classical order %s%d for general A + B (terms to degree %d%s)\n",
                g->classical_state == VIGEN_GEN_DECIDED ? "" : ">=", g->classical, g->degree,
                g->rounded ? (g->within_data ? "; terms of rounded coefficients vanish to the data's precision" : "; "
                              "rounded coefficients") : "");
        for (int j = 1; j <= g->k; j++) {
            const vigen_check_lie_error *le = &g->terms[j];
            if (!le->computed) continue;
            fprintf(out, "  eps^%d h^%-3d 2-norm ", j, g->r[j]);
            put_figure(out, le->norm);
            fprintf(out, " (%ld Lyndon term%s of degree %d)\n", (long)le->nterms, le->nterms == 1 ? "" : "s",
                    le->degree);
            for (slong k = 0; k < le->nterms && k < 8; k++) {
                fprintf(out, "    %-30s ", le->brackets[k]);
                put_figure(out, le->coef + k);
                fputc('\n', out);
            }
            if (le->nterms > 8) fprintf(out, "    ... %ld more (all of them with --json)\n", (long)(le->nterms - 8));
        }
    }
    if (g->claim_status >= 0) {
        fputs("  claim generalized_order = {", out);
        for (int j = 0; j < g->claim_k; j++) fprintf(out, "%s%d", j ? ", " : "", g->claim[j]);
        fprintf(out, "}: %s\n", g->claim_status == VIGEN_CHECK_YES ? (g->within_data ? "holds (within the data's "
                "precision)" : "holds") : g->claim_status == VIGEN_CHECK_NO ? "fails" : "undecided");
    }
}

static void text_stability(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_stability *st = &rep->stability;
    fputs("stability     on q'' = -omega^2 q: ", out);
    if (st->status == VIGEN_CHECK_STAB_UNBOUNDED) fputs("stable for every h omega", out);
    else if (st->status == VIGEN_CHECK_STAB_BOUNDED) {
        fputs("stable for h omega < ", out);
        put_figure(out, st->x);
    } else fputs("undecided", out);
    if (st->reason) fprintf(out, " (%s)", st->reason);
    fputc('\n', out);
}

static void text_cost(FILE *out, const vigen_check_report *rep)
{
    const vigen_check_cost *c = &rep->cost;
    fprintf(out, "cost          %ld stage%s; for H = T(p) + V(q): %ld force and %ld velocity evaluations per step%s, %s; "
                 "for general H: %s\n",
            (long)c->stages, c->stages == 1 ? "" : "s", (long)c->force, (long)c->velocity,
            c->fsal ? " (first force = last of the previous step)" : "",
            c->explicit_separable ? "explicit" : "implicit", c->explicit_general ? "explicit" : "implicit");
}

static void text_claims(FILE *out, const vigen_check_report *rep)
{
    if (rep->claim_order >= 0 || rep->claim_symplectic >= 0 || rep->claim_order_family[0] >= 0 ||
        rep->claim_order_family[1] >= 0) {
        fputs("claims       ", out);
        if (rep->claim_order >= 0)
            fprintf(out, " order = %d: %s%s%s%s;", rep->claim_order,
                    rep->claim_order_beyond ? "undecided (beyond the orders that can be evaluated)"
                                            : tri_word_data(rep->claim_order_status, "holds", "FALSE",
                                                            rep->claim_order_too_short),
                    rep->claim_order_within_data ? " " : "", rep->claim_order_within_data ? within_words : "",
                    rep->claim_order_separable ? " (for separable H)" : "");
        if (rep->claim_symplectic >= 0)
            fprintf(out, " symplectic = %s: %s%s%s%s;", rep->claim_symplectic ? "true" : "false",
                    tri_word_data(rep->claim_symplectic_status, "holds", "FALSE",
                                  rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].too_short > 0),
                    rep->claim_symplectic_within_data ? " " : "",
                    rep->claim_symplectic_within_data ? within_words : "",
                    rep->claim_symplectic_separable ? " (for separable H)" : "");
        for (int f = 0; f < 2; f++)
            if (rep->claim_order_family[f] >= 0)
                fprintf(out, " %s = %d: %s;", f ? "order_nystrom" : "order_separable", rep->claim_order_family[f],
                        tri_word_data(rep->claim_order_family_status[f], "holds", "FALSE", 0));
        fputc('\n', out);
    }
}

/* with --against (the row's condition) */
static void text_against(FILE *out, const vigen_check_report *rep)
{
    if (rep->against_stages > 0) {
        fprintf(out, "against       the tableaux cannot be compared: %ld stage%s here, %ld there\n", (long)rep->s,
                rep->s == 1 ? "" : "s", (long)rep->against_stages);
    } else {
        fprintf(out, "against       %ld entr%s differ%s beyond the certified precision",
                (long)rep->against_differences, rep->against_differences == 1 ? "y" : "ies",
                rep->against_differences == 1 ? "s" : "");
        if (rep->against_undecided) fprintf(out, ", %ld undecided", (long)rep->against_undecided);
        if (rep->holds[VIGEN_CHECK_SECT_AGAINST].data > 0) {
            char *r = vigen_mag_str(rep->holds[VIGEN_CHECK_SECT_AGAINST].radius);
            fprintf(out, " (%ld agree within the precision of the data, radius <= %s)",
                    (long)rep->holds[VIGEN_CHECK_SECT_AGAINST].data, r);
            free(r);
        }
        fputc('\n', out);
    }
}

static void text_undecided(FILE *out, const vigen_check_report *rep)
{
    if (rep->undecided_left)
        fprintf(out, "undecided     %ld conditions at %ld bits: %s\n", (long)rep->undecided_left, (long)rep->prec,
                rep->undecided_reason ? rep->undecided_reason : "");
}

/* symplecticity pairs: the first 20; everything else: up to 40 lines */
static void text_problems(FILE *out, const vigen_check_report *rep)
{
    if (rep->nfailures) {
        fputs("problems\n", out);
        /* symplecticity pairs: the first 20; everything else: up to 40 lines */
        slong pairs = 0, pairs_shown = 0, other_shown = 0, other_hidden = 0;
        for (slong k = 0; k < rep->nfailures; k++) {
            const vigen_check_failure *p = rep->failures + k;
            if (p->kind == VIGEN_CHECK_FAIL_SYMPLECTIC && !p->diagnosed && p->col > 0) pairs++;
        }
        for (slong k = 0; k < rep->nfailures; k++) {
            const vigen_check_failure *p = rep->failures + k;
            /* a diagnosis is filed once per kind of condition, with one message */
            if (k > 0 && p->diagnosed && rep->failures[k - 1].diagnosed &&
                strcmp(p->message, rep->failures[k - 1].message) == 0)
                continue;
            if (p->kind == VIGEN_CHECK_FAIL_SYMPLECTIC && !p->diagnosed && p->col > 0) {
                if (pairs_shown < 20) {
                    problem_line(out, p->message);
                    if (++pairs_shown == 20 && pairs > 20)
                        fprintf(out, "  ... and %ld more pairs (all of them with --json)\n", (long)(pairs - 20));
                }
                continue;
            }
            if (other_shown < 40) {
                problem_line(out, p->message);
                other_shown++;
            } else other_hidden++;
        }
        if (other_hidden) fprintf(out, "  ... and %ld more problems (all of them with --json)\n", (long)other_hidden);
    } else fputs("problems      none\n", out);
}

static void text_notation(FILE *out, const vigen_check_report *rep)
{
    fprintf(out, "trees: %s\n", vigen_tree_notation_help());
}

/* the verdict and the exit status */
static void text_result(FILE *out, const vigen_check_report *rep)
{
    int within = rep->consistent_within_data || rep->claim_order_within_data || rep->claim_symplectic_within_data;
    /* exit 1 with nothing certainly false: undecided, not failed */
    int failed = rep->consistent == VIGEN_CHECK_NO || (rep->claim_order >= 0 && rep->claim_order_status == VIGEN_CHECK_NO) ||
                 (rep->claim_symplectic >= 0 && rep->claim_symplectic_status == VIGEN_CHECK_NO) ||
                 rep->against_differences > 0;
    fprintf(out, "result        %s (exit %d)\n",
            rep->exit_code != 0 && !failed ? "NOT DECIDED: nothing is certainly false, but not everything could be "
                                             "decided (see the undecided conditions above)"
            : rep->exit_code != 0 ? "FAILED: see the problems above"
            : within ? "consistent; every stated claim holds (some only within the precision of the data)"
                     : "consistent; every stated claim holds",
            rep->exit_code);
}

/* the value of a check's own row in words */
#define TEXT_BOOL(v) fputs((v) ? "yes" : "no", out)
#define TEXT_INT(v) fprintf(out, "%d", (int)(v))
#define TEXT_LONG(v) fprintf(out, "%ld", (long)(v))
#define TEXT_TRI(v) fputs(tri_word((v), "yes", "no"), out)
#define TEXT_STR(v) put_shown((v) ? (v) : "", out)
#define TEXT_BALL(v) put_figure(out, (v))

/* The line of each X_RESULT row: "label" in the column of the other figures'
 * names, then the check's own words or its value in words; nothing while
 * the check has not set it. */
#define X_CHECK(name, fn, description)
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn)
#define X_RESULT(name, fn, description, type, sep, text_at, label)                                                   \
    static void text_result_##name(FILE *out, const vigen_check_report *rep)                                           \
    {                                                                                                                  \
        if (!rep->name.set) return;                                                                                    \
        fprintf(out, "%-13s ", label);                                                                                 \
        if (rep->name.text) put_shown(rep->name.text, out);                                                            \
        else TEXT_##type(rep->name.value);                                                                             \
        fputc('\n', out);                                                                                              \
    }
#include "vigen/check_fields.def"
#undef X_RESULT

void vigen_check_print_text(FILE *out, const vigen_check_report *rep)
{
    const struct {
        int at;
        void (*print)(FILE *, const vigen_check_report *);
        int when;
    } rows[] = {
#undef X_FIGURE
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn) {text_at, text_fn, (when) != 0},
#define X_RESULT(name, fn, description, type, sep, text_at, label) {text_at, text_result_##name, 1},
#include "vigen/check_fields.def"
#undef X_CHECK
#undef X_FIGURE
#undef X_RESULT
    };
    enum { NROWS = sizeof(rows) / sizeof(rows[0]) };
    /* the rows in increasing text_at (distinct places, a few dozen rows;
     * text_at 0: JSON only) */
    for (int last = 0;;) {
        int next = -1;
        for (int k = 0; k < NROWS; k++)
            if (rows[k].print && rows[k].at > last && (next < 0 || rows[k].at < rows[next].at)) next = k;
        if (next < 0) break;
        if (rows[next].when) rows[next].print(out, rep);
        last = rows[next].at;
    }
}
