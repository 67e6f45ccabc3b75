/* cmd_design.c — `vigen design DESIGN`: the solutions of a design file
 * (vigen/design.h), a table of them on standard output, one method file per
 * certified solution.  Exit status 0 with a certified solution, 1 without. */
#include <stdlib.h>
#include "cli.h"
#include "vigen/design.h"
#include "support/printable.h"
#include "support/progress.h"

static void print_header(const vigen_design_spec *d, const vigen_design_result *res)
{
    if (d->base) {
        char *base = vigen_printable(d->base);
        printf("design %s: %d-stage %scomposition of %s (order %d), order %d\n", d->name, d->stages,
               d->symmetric ? "symmetric " : "", base, res->base_order, d->order);
        free(base);
    } else if (d->processed) {
        printf("design %s: processed: symmetric kernel with %d kicks (A drifts, B kicks) of effective order %d for "
               "%s H, and its corrector\n", d->name, d->stages, d->order, d->nystrom ? "Nystrom" : "separable");
    } else if (d->flow_b) {
        printf("design %s: %ssplitting of named flows with %d steps of %s (A %s, B %s: H = A + eps B), generalized "
               "order {", d->name, d->symmetric ? "symmetric " : "", d->stages, d->flow_b, d->flow_a, d->flow_b);
        for (int j = 0; j < d->ngeneralized; j++) printf("%s%d", j ? ", " : "", d->generalized[j]);
        printf("}\n");
    } else {
        printf("design %s: %ssplitting with %d kicks (A drifts, B kicks), order %d for %s H\n", d->name,
               d->symmetric ? "symmetric " : "", d->stages, d->order, d->nystrom ? "Nystrom" : "separable");
    }
    printf("conditions  %ld in %ld unknowns (coefficients of the %sBCH series%s%s%s):", (long)res->nconditions,
           (long)res->nunknowns, d->processed || d->nystrom ? "" : "Lyndon words of the ",
           d->processed || d->nystrom ? " modulo " : "", d->processed ? "[A+B, .]" : "",
           d->nystrom ? (d->processed ? " and the relations of Nystrom H" : "the relations of Nystrom H") : "");
    for (slong i = 0; i < res->nconditions; i++) printf("%s [%s]", i ? "," : "", res->conditions[i]);
    printf("\n");
    if (res->minimized) {
        if (d->screen > 0)
            printf("screen      %ld random points, each descended on the Lyndon norm of the principal error\n",
                   d->screen);
        printf("search      %ld free unknowns; Nelder-Mead on the checker's %s from %ld starts (%ld checker runs): "
               "%ld local minima\n", (long)res->nfree, d->minimize, (long)res->starts, res->evaluations,
               (long)res->nfound);
        printf("complete    the best found, not proved the global minimum\n");
        return;
    }
    printf("search      a square subsystem of %ld, Newton from %ld starts: %ld distinct real roots\n",
           (long)res->nsquare, (long)res->starts, (long)(res->nfound - res->homotopy_new));
    if (res->homotopy_paths > 0) {
        printf("homotopy    all %ld paths of a total-degree homotopy: %ld distinct roots (%ld real), %ld at infinity",
               (long)res->homotopy_paths, (long)res->homotopy_finite, (long)res->homotopy_real,
               (long)res->homotopy_infinite);
        if (res->homotopy_lost) printf(", %ld lost or singular", (long)res->homotopy_lost);
        if (res->homotopy_new) printf("; %ld real roots Newton had missed", (long)res->homotopy_new);
        printf("\n");
    }
    if (res->homotopy_complete)
        printf("complete    yes, by the homotopy: every path ended at a distinct nonsingular root or at infinity, "
               "so the %ld real roots found are all (paths tracked in floating point, not certified)\n",
               (long)res->nfound);
    else if (res->complete)
        printf("complete    yes: %ld roots found = the Bezout bound %ld of the subsystem (every root is real and "
               "found)\n", (long)res->nfound, (long)res->bezout);
    else if (res->bezout > 0)
        printf("complete    not established: the subsystem has at most %ld complex roots (Bezout bound); %ld real "
               "ones found\n", (long)res->bezout, (long)res->nfound);
    else
        printf("complete    not established (Bezout bound too large to state)\n");
}

static void print_table(const vigen_design_result *res, const vigen_design_spec *d)
{
    printf("%-4s %-13s %-6s %-12s %-12s %-12s %-6s %s\n", "k", "status", "order", "error const", "separable",
           "nystrom", "force", "file");
    for (slong i = 0; i < res->nsol; i++) {
        const vigen_design_solution *s = &res->sol[i];
        const char *status = s->certified ? "certified" : s->excluded ? "excluded" : s->proved ? "not certified"
                                                                                             : "not proved";
        char order[16] = "-";
        if (s->order >= 0) snprintf(order, sizeof order, "%d", s->order);
        char force[24] = "-";
        if (s->certified) snprintf(force, sizeof force, "%ld", s->force);
        printf("%-4ld %-13s %-6s %-12s %-12s %-12s %-6s %s\n", (long)(i + 1), status, order,
               s->error_constant ? s->error_constant : "-", s->error_constant_sep ? s->error_constant_sep : "-",
               s->error_constant_nystrom ? s->error_constant_nystrom : "-", force,
               s->certified && s->file ? s->file : "-");
        double effective = vigen_design_solution_criterion(s, d);
        if (d->minimize_effective && s->certified && effective >= 0)
            printf("     %s = %.6g (the constant times %ld forces to the power %d)\n", d->minimize, effective,
                   s->force, d->order);
        printf("     x =");
        for (slong j = 0; j < s->nunknowns; j++)
            printf(" %s", s->proved && s->digits && s->digits[j] ? s->digits[j] : "");
        if (!s->proved)
            for (slong j = 0; j < s->nunknowns; j++) printf(" %.16g", s->x[j]);
        printf("\n");
        if (s->proved && s->radius) printf("     proved in a box of radius %s\n", s->radius);
        if (s->why) printf("     %s\n", s->why);
    }
}

int vigen_cmd_design(const vigen_cli_args *args)
{
    vigen_design_options opt;
    vigen_design_options_init(&opt);
    long long digits = opt.digits;
    int rc;
    if (args->value[VIGEN_OPT_design_digits] &&
        (rc = vigen_cli_whole(&digits, args, VIGEN_OPT_design_digits, 10, 1000)) >= 0)
        return rc;
    opt.digits = (long)digits;
    if (args->value[VIGEN_OPT_design_output]) opt.outdir = args->value[VIGEN_OPT_design_output];
    vigen_error err;
    vigen_error_init(&err);
    vigen_design_spec d;
    if (vigen_design_read(&d, args->operand, &err) != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    vigen_design_result res;
    /* a line on a terminal while the search takes more than a second */
    vigen_progress_begin("vigen design");
    rc = vigen_design_run(&res, &d, &opt, &err);
    vigen_progress_end();
    if (rc == VIGEN_OK) {
        print_header(&d, &res);
        print_table(&res, &d);
        rc = vigen_design_write(&res, &err);
    }
    int certified = 0;
    for (slong i = 0; rc == VIGEN_OK && i < res.nsol; i++) certified += res.sol[i].certified;
    if (rc == VIGEN_OK && certified == 0)
        printf("no solution: no root found satisfies every condition%s\n",
               res.complete ? " (and the search is complete: these are all the real roots)" : " (the search is not proved complete)");
    vigen_design_result_clear(&res);
    vigen_design_spec_clear(&d);
    if (rc != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    return certified ? 0 : 1;
}
