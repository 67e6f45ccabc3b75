/* design_run.c — a design solved (vigen/design.h): the base method resolved,
 * loaded and certified symmetric of order q, the order conditions of the
 * family, the square subsystem solved from many starts, each root proved by
 * the Krawczyk operator, the other conditions decided on the proving box, and
 * the method file of each proved solution checked. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "design/design_internal.h"
#include "design/design_method.h"
#include "design/design_minimize.h"
#include "core/decimal.h"
#include "vigen/check.h"
#include "vigen/library.h"
#include "vigen/method.h"
#include "support/strbuf.h"

/* The starts are drawn in [-box, box]^k: the published compositions have
 * steps of at most about 2.5 in size. */
#define START_BOX 3.0
#define SAME_ROOT 1e-7
/* The conditions are counted before they are built up to this order (the
 * words of that weight number in the tens of thousands). */
#define COUNT_MAX_ORDER DESIGN_WORD_MAX
#define DEFAULT_DIGITS 40

void vigen_design_options_init(vigen_design_options *opt)
{
    opt->outdir = ".";
    opt->digits = DEFAULT_DIGITS;
}

static void solution_clear(vigen_design_solution *s)
{
    for (slong j = 0; s->digits && j < s->nunknowns; j++) free(s->digits[j]);
    free(s->digits);
    free(s->x);
    free(s->radius);
    free(s->error_constant);
    free(s->error_constant_sep);
    free(s->error_constant_nystrom);
    free(s->file);
    free(s->text);
    free(s->why);
    memset(s, 0, sizeof *s);
}

void vigen_design_result_clear(vigen_design_result *res)
{
    for (slong i = 0; i < res->nsol; i++) solution_clear(&res->sol[i]);
    free(res->sol);
    for (slong i = 0; res->conditions && i < res->nconditions; i++) free(res->conditions[i]);
    free(res->conditions);
    free(res->condition_degree);
    memset(res, 0, sizeof *res);
}

/* Substeps k and n-1-k of the same kind with equal coefficients: the
 * splitting is its own adjoint (symmetric). */
static int palindromic(const vigen_tableau *t)
{
    if (t->nsubsteps == 0) return 0;
    int ok = 1;
    arb_t a, b;
    arb_init(a);
    arb_init(b);
    for (slong k = 0; ok && k < t->nsubsteps / 2; k++) {
        slong l = t->nsubsteps - 1 - k;
        if (t->substep_drift[k] != t->substep_drift[l]) ok = 0;
        else if (strcmp(t->substep_coef[k], t->substep_coef[l]) != 0) {
            vigen_error e;
            vigen_error_init(&e);
            ok = vigen_tableau_entry_eval(a, t->substep_coef[k], 256, &e) == VIGEN_OK &&
                 vigen_tableau_entry_eval(b, t->substep_coef[l], 256, &e) == VIGEN_OK && arb_is_exact(a) &&
                 arb_equal(a, b);
            vigen_error_clear(&e);
        }
    }
    arb_clear(a);
    arb_clear(b);
    return ok;
}

/* The base: resolved (did-you-mean for an unknown name), a symmetric
 * splitting, its order certified.  *written: how the method files name it. */
static int load_base(int *q, char **written, const vigen_design_spec *d, vigen_error *err)
{
    char *path = NULL;
    if (vigen_library_resolve(&path, d->base, err) != VIGEN_OK) {
        err->code = VIGEN_E_SPEC;
        return vigen_error_prefix(err, "%s: base: ", d->path);
    }
    vigen_tableau t;
    int rc = vigen_source_load(&t, path, 34, err);
    if (rc != VIGEN_OK) {
        free(path);
        return vigen_error_prefix(err, "%s: base: ", d->path);
    }
    if (!palindromic(&t))
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: base: %s is not a symmetric splitting (its kicks and drifts "
                             "must read the same backwards); design composes symmetric bases", d->path, d->base);
    if (rc == VIGEN_OK) {
        int claimed = t.claim_order;
        t.claim_order = -1;
        rc = vigen_check_certify(&t, path, err);
        if (rc == VIGEN_OK && (t.claim_order < 2 || t.claim_order % 2 != 0))
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: base: the order of %s is not certified as an even order "
                                 "(claimed %d)", d->path, d->base, claimed);
        *q = t.claim_order;
    }
    vigen_tableau_clear(&t);
    /* a library name stays a name; a file is named by its absolute path */
    if (rc == VIGEN_OK) {
        int is_name = strchr(d->base, '/') == NULL && strstr(d->base, ".lua") == NULL;
        char *abs = is_name ? NULL : realpath(path, NULL);
        *written = vigen_strdup(is_name ? d->base : abs ? abs : path);
        free(abs);
    }
    free(path);
    return rc;
}

static slong bezout_bound(const design_system *sys, const slong *rows, slong m)
{
    double b = 1;
    for (slong i = 0; i < m; i++) b *= (double)sys->cond[rows[i]].degree;
    return b > 1e15 ? -1 : (slong)b;
}

static int cmp_first(const void *a, const void *b)
{
    const vigen_design_solution *x = a, *y = b;
    for (slong j = 0; j < x->nunknowns; j++)
        if (x->x[j] != y->x[j]) return x->x[j] < y->x[j] ? -1 : 1;
    return 0;
}

/* Every root of the square subsystem by a total-degree homotopy, when its
 * Bezout number is small enough: the real roots the Newton search missed
 * join *roots (res->nfound of them), and res gets the paths' account. */
static void homotopy(vigen_design_result *res, double **roots, const design_system *sys, const slong *rows,
                     unsigned long seed, long max_paths)
{
    design_homotopy h;
    slong k = sys->k;
    if (max_paths <= 0 || design_homotopy_solve(&h, sys, rows, seed, max_paths) < 0) return;
    res->homotopy_paths = h.paths;
    res->homotopy_finite = h.finite;
    res->homotopy_real = h.real;
    res->homotopy_infinite = h.infinite;
    res->homotopy_lost = h.singular + h.failed + h.repeated;
    res->homotopy_complete = h.complete;
    for (slong r = 0; r < h.real; r++) {
        const double *x = h.real_roots + r * k;
        int seen = 0;
        for (slong s = 0; s < res->nfound && !seen; s++) {
            double dist = 0;
            for (slong j = 0; j < k; j++) dist = fmax(dist, fabs(x[j] - (*roots)[s * k + j]) / (1 + fabs(x[j])));
            seen = dist < SAME_ROOT;
        }
        if (seen) continue;
        *roots = realloc(*roots, (size_t)((res->nfound + 1) * k) * sizeof(double));
        memcpy(*roots + res->nfound * k, x, (size_t)k * sizeof(double));
        res->nfound++;
        res->homotopy_new++;
    }
    design_homotopy_clear(&h);
}

/* The outcome of the root sol->x: proved (digits), excluded by a condition
 * outside the subsystem, or checked as a method file. */
static void settle(vigen_design_solution *sol, const design_system *sys, const slong *rows, slong m,
                   const vigen_design_options *opt)
{
    slong k = sys->k;
    arb_ptr box = _arb_vec_init(k);
    slong prec = (slong)(opt->digits * 3.33) + 96;
    for (int attempt = 0; attempt < 3 && !sol->proved; attempt++, prec *= 2)
        sol->proved = design_krawczyk_prove(box, sys, rows, sol->x, prec);
    prec /= 2;
    if (!sol->proved) sol->why = vigen_strdup("not proved: the Krawczyk test failed on every box tried");
    if (sol->proved) {
        sol->digits = calloc((size_t)k, sizeof(char *));
        mag_t r;
        mag_init(r);
        for (slong j = 0; j < k; j++) {
            mag_max(r, r, arb_radref(box + j));
            if (j >= k - sys->nmultipliers) continue;     /* a Lagrange multiplier: not written */
            sol->digits[j] = design_pinned_zero(sys, rows, m, j) ? vigen_strdup("0")
                                                                 : vigen_decimal_format(box + j, opt->digits);
            if (sol->digits[j] == NULL) {
                sol->proved = 0;
                sol->why = vigen_strdup("not proved to the digits asked (the box is too wide)");
            }
        }
        arb_t rr;
        arb_init(rr);
        arf_set_mag(arb_midref(rr), r);
        char *s = arb_get_str(rr, 3, ARB_STR_NO_RADIUS);
        sol->radius = vigen_strdup(s);
        flint_free(s);
        arb_clear(rr);
        mag_clear(r);
    }
    /* the conditions outside the square subsystem: on the box */
    for (slong i = 0; sol->proved && i < sys->n; i++) {
        int in = 0;
        for (slong r = 0; r < m; r++) in |= rows[r] == i;
        if (in) continue;
        arb_t v;
        arb_init(v);
        design_poly_eval_arb(v, &sys->cond[i], box, prec);
        if (!arb_contains_zero(v)) {
            sol->excluded = 1;
            char *s = arb_get_str(v, 5, 0);
            sol->why = vigen_strdup_printf("excluded: the condition %s is %s on the proving box, not 0", sys->what[i], s);
            flint_free(s);
        }
        arb_clear(v);
        if (sol->excluded) break;
    }
    _arb_vec_clear(box, k);
}

/* A processed design: the corrector of each proved kernel, proved with it
 * (the digits become the kernel's and the corrector's); a kernel without a
 * proved corrector is not written. */
static void add_corrector(vigen_design_solution *sol, const vigen_design_spec *d, const design_system *sys,
                          const slong *rows, const vigen_design_options *opt, vigen_error *err)
{
    if (!sol->proved || sol->excluded) return;
    char **digits = NULL, *radius = NULL, *why = NULL;
    if (design_corrector_find(&digits, &radius, &why, d, sys, rows, sol->x, opt->digits, err) == 1) {
        for (slong j = 0; j < sol->nunknowns; j++) free(sol->digits[j]);
        free(sol->digits);
        free(sol->radius);
        sol->digits = digits;
        sol->radius = radius;
        sol->nunknowns += DESIGN_CORRECTOR_UNKNOWNS;
    } else {
        sol->proved = 0;
        sol->why = why ? why : vigen_strdup(err->message ? err->message : "no corrector");
        free(radius);
    }
}

/* The method file of each proved solution that no condition excludes. */
static int certify_all(vigen_design_result *res, const vigen_design_spec *d, const vigen_design_options *opt,
                       const char *base, const char *how, vigen_error *err)
{
    slong count = 0;
    for (slong i = 0; i < res->nsol; i++) count += res->sol[i].proved && !res->sol[i].excluded;
    slong index = 0;
    for (slong i = 0; i < res->nsol; i++) {
        vigen_design_solution *s = &res->sol[i];
        if (!s->proved || s->excluded) continue;
        index++;
        char *name = vigen_strdup_printf("%s_%ld", d->name, (long)index);
        s->file = vigen_strdup_printf("%s/%s.lua", opt->outdir, name);
        slong nv = design_family_nvalues(d);
        char **gamma = malloc((size_t)nv * sizeof(char *));
        for (slong st = 0; st < nv; st++) {
            slong j = design_family_value_unknown(d, st);
            gamma[st] = s->digits[j];
            /* a fixed unknown is written as the rational it is */
            for (long f = 0; f < d->nfix; f++)
                if (d->fix_unknown[f] == j) gamma[st] = d->fix_value[f];
        }
        /* first the claims of the order asked for (general H for a
         * composition, separable H for a splitting) and symplectic, then also
         * the orders the checker certified for the other families, checked
         * again */
        int splitting = design_family_is_splitting(d);
        int claims[3] = {splitting ? -1 : d->order, splitting && !d->nystrom ? d->order : -1,
                         d->nystrom ? d->order : -1};
        if (d->flow_b) {
            /* named flows: the classical order is the least r_j */
            claims[0] = d->order;
            claims[1] = -1;
            for (int j = 0; j < d->ngeneralized; j++) claims[0] = d->generalized[j] < claims[0] ? d->generalized[j]
                                                                                              : claims[0];
        }
        s->text = vigen_design_method_text(d, base, name, index, count, gamma, how, claims, d->generalized,
                                           d->ngeneralized);
        int rc = vigen_design_method_check(s, s->text, s->file, d->order, err);
        if (rc == VIGEN_OK && d->flow_b && !s->certified && s->ngeneralized > 0 && s->order >= claims[0]) {
            /* a solution beyond the order asked (r_j above it): it claims
             * what the checker finds */
            int gen[VIGEN_DESIGN_MAX_GENERALIZED], n = s->ngeneralized;
            memcpy(gen, s->generalized, sizeof gen);
            claims[0] = s->order;
            free(s->text);
            free(s->why);
            free(s->error_constant);
            free(s->error_constant_sep);
            free(s->error_constant_nystrom);
            s->why = s->error_constant = s->error_constant_sep = s->error_constant_nystrom = NULL;
            s->text = vigen_design_method_text(d, base, name, index, count, gamma, how, claims, gen, n);
            rc = vigen_design_method_check(s, s->text, s->file, d->order, err);
        } else if (rc == VIGEN_OK && !d->flow_b && s->certified &&
                   (s->order >= 0 || s->order_separable >= 0 || s->order_nystrom >= 0)) {
            free(s->text);
            free(s->error_constant);
            free(s->error_constant_sep);
            free(s->error_constant_nystrom);
            s->error_constant = s->error_constant_sep = s->error_constant_nystrom = NULL;
            claims[0] = s->order;
            claims[1] = s->order_separable;
            claims[2] = s->order_nystrom;
            s->text = vigen_design_method_text(d, base, name, index, count, gamma, how, claims, NULL, 0);
            rc = vigen_design_method_check(s, s->text, s->file, d->order, err);
        }
        /* a processed method steps its kernel; C and C^-1 run once */
        if (d->processed) s->force = d->stages;
        free(gamma);
        free(name);
        if (rc != VIGEN_OK) return rc;
    }
    return VIGEN_OK;
}

double vigen_design_solution_criterion(const vigen_design_solution *sol, const vigen_design_spec *d)
{
    double c = d->minimize_family == VIGEN_CHECK_EC_SEPARABLE ? sol->error_constant_sep_d
             : d->minimize_family == VIGEN_CHECK_EC_NYSTROM   ? sol->error_constant_nystrom_d
                                                              : sol->error_constant_d;
    if (c < 0 || !d->minimize_effective) return c;
    return c * pow((double)sol->force, d->order);
}

/* minimize among finitely many solutions: only the certified one with the
 * smallest figure asked keeps its file. */
static void keep_best(vigen_design_result *res, const vigen_design_spec *d)
{
    slong best = -1;
    double vbest = 0;
    for (slong i = 0; i < res->nsol; i++) {
        double v = vigen_design_solution_criterion(&res->sol[i], d);
        if (res->sol[i].certified && v >= 0 && (best < 0 || v < vbest)) best = i, vbest = v;
    }
    for (slong i = 0; i < res->nsol; i++)
        if (i != best && res->sol[i].file) {
            free(res->sol[i].file);
            res->sol[i].file = NULL;
            if (res->sol[i].why == NULL)
                res->sol[i].why = vigen_strdup_printf("not written: a smaller %s exists", d->minimize);
        }
}

/* The family has free parameters (or one asks the best of finitely many):
 * the best point found by design_minimize, proved and certified. */
static int minimize(vigen_design_result *res, design_system *sys, slong *rows, slong m, const vigen_design_spec *d,
                    const vigen_design_options *opt, const char *base, vigen_error *err)
{
    slong k = sys->k;
    double *x = malloc((size_t)k * sizeof(double)), ec = 0;
    slong nminima = 0;
    long evals = 0;
    int found = design_minimize(x, &ec, &nminima, &evals, sys, rows, m, d, base, res->base_order, START_BOX);
    res->starts = d->starts;
    res->nfound = nminima;
    res->bezout = -1;
    res->minimized = 1;
    res->nfree = k - m;
    res->evaluations = evals;
    int rc = VIGEN_OK;
    if (found) {
        res->sol = calloc(1, sizeof *res->sol);
        res->nsol = 1;
        res->sol[0].nunknowns = k;
        res->sol[0].order = res->sol[0].order_separable = res->sol[0].order_nystrom = -1;
        res->sol[0].x = x;
        x = NULL;
        settle(&res->sol[0], sys, rows, k, opt);
        if (d->processed) add_corrector(&res->sol[0], d, sys, rows, opt, err);
        char *screen = d->screen > 0 ? vigen_strdup_printf(" (the starts the best minima of the Lyndon norm of "
                                                           "the principal error from %ld random points)", d->screen)
                                     : vigen_strdup("");
        char *how = vigen_strdup_printf(
            "the %ld order conditions (polynomials in the steps, from the BCH series of the method) leave %ld "
            "free; these were chosen by Nelder-Mead minimising the checker's %s from %ld starts%s (%ld local minima, "
            "this the best found, not proved global), held exactly, and the others proved by the Krawczyk operator",
            (long)res->nconditions, (long)(k - m), d->minimize, (long)d->starts, screen, (long)nminima);
        free(screen);
        rc = certify_all(res, d, opt, base, how, err);
        free(how);
    }
    free(x);
    return rc;
}

int vigen_design_run(vigen_design_result *res, const vigen_design_spec *d, const vigen_design_options *opt,
                     vigen_error *err)
{
    memset(res, 0, sizeof *res);
    slong k = design_family_unknowns(d);
    res->nunknowns = k;
    int q = 0;
    char *base = NULL;
    int rc = design_family_is_splitting(d) ? VIGEN_OK : load_base(&q, &base, d, err);
    if (rc != VIGEN_OK) return rc;
    res->base_order = q;
    if (d->order > VIGEN_DESIGN_MAX_ORDER) {
        slong n = d->order <= COUNT_MAX_ORDER ? design_family_count(d, q) : -1;
        int at_least = 0;
        if (n < 0 && design_family_mods(d)) {
            /* the conditions modulo a subspace are counted up to a lower
             * order: those are among the conditions of the order asked */
            vigen_design_spec lower = *d;
            lower.order = DESIGN_QUOTIENT_MAX_DEGREE;
            n = design_family_count(&lower, q);
            at_least = 1;
        }
        free(base);
        if (n > k)
            return vigen_error_set(err, VIGEN_E_SPEC, "%s: order: %d is impossible with %d stages: it asks for %s%ld "
                                   "conditions of %ld unknowns (and design handles orders up to %d)", d->path,
                                   d->order, d->stages, at_least ? "at least " : "", (long)n, (long)k,
                                   VIGEN_DESIGN_MAX_ORDER);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: order: %d is beyond the orders design handles (up to %d)",
                               d->path, d->order, VIGEN_DESIGN_MAX_ORDER);
    }
    if (base && d->order <= q) {
        free(base);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: order: %d is not above the order %d of the base %s", d->path,
                               d->order, q, d->base);
    }
    design_system sys;
    rc = design_family_conditions(&sys, d, q, err);
    if (rc == VIGEN_OK && design_system_fix(&sys, d) != VIGEN_OK)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: fix: a value does not read as a rational", d->path);
    if (rc != VIGEN_OK) {
        free(base);
        return rc;
    }
    res->nconditions = sys.n;
    res->conditions = calloc((size_t)(sys.n + 1), sizeof(char *));
    res->condition_degree = calloc((size_t)(sys.n + 1), sizeof(int));
    for (slong i = 0; i < sys.n; i++) {
        res->conditions[i] = vigen_strdup(sys.what[i]);
        res->condition_degree[i] = sys.h_degree[i];
    }
    slong *rows = malloc((size_t)(k + 1) * sizeof(slong));
    if (d->first_kick) design_system_add_pin(&sys, design_family_value_unknown(d, 0));
    slong m = design_square_rows(rows, &sys, d->seed);
    res->nsquare = m;
    int criterion = d->stationary != NULL || d->nnearest > 0;
    if (criterion && (rc = design_criterion_replace(&sys, &rows, &m, d, q, err)) == VIGEN_OK) {
        k = sys.k;
        res->nunknowns = k;
    }
    if (rc != VIGEN_OK) {
    } else if (m < k && d->goal == VIGEN_DESIGN_ALL) {
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: solutions: the %ld conditions leave %ld of the %ld unknowns "
                             "free (a family, not finitely many solutions); ask minimize = \"error_constant\", a "
                             "higher order or fewer stages", d->path, (long)sys.n, (long)(k - m), (long)k);
    } else if (m < k) {
        rc = minimize(res, &sys, rows, m, d, opt, base, err);
    } else {
        /* minimize over finitely many roots: a search for all of them */
        long starts = d->goal == VIGEN_DESIGN_MINIMIZE && d->starts_asked == 0 ? VIGEN_DESIGN_DEFAULT_STARTS
                                                                               : d->starts;
        res->bezout = bezout_bound(&sys, rows, m);
        double *roots = NULL;
        res->starts = starts;
        res->nfound = criterion ? design_criterion_search(&roots, &sys, rows, d, design_family_unknowns(d), START_BOX)
                                : design_newton_search(&roots, &sys, rows, starts, d->seed, START_BOX);
        /* not for nearest, which asks one member, not every stationary
         * point of the distance */
        if (d->nnearest == 0) homotopy(res, &roots, &sys, rows, d->seed, d->homotopy);
        res->complete = (res->bezout > 0 && res->nfound == res->bezout) || res->homotopy_complete;
        res->sol = calloc((size_t)(res->nfound + 1), sizeof *res->sol);
        res->nsol = res->nfound;
        for (slong i = 0; i < res->nsol; i++) {
            res->sol[i].nunknowns = k;
            res->sol[i].order = res->sol[i].order_separable = res->sol[i].order_nystrom = -1;
            res->sol[i].x = malloc((size_t)k * sizeof(double));
            memcpy(res->sol[i].x, roots + i * k, (size_t)k * sizeof(double));
        }
        free(roots);
        qsort(res->sol, (size_t)res->nsol, sizeof *res->sol, cmp_first);
        for (slong i = 0; i < res->nsol; i++) settle(&res->sol[i], &sys, rows, m, opt);
        for (slong i = 0; d->processed && i < res->nsol; i++) add_corrector(&res->sol[i], d, &sys, rows, opt, err);
        char *how = criterion ? design_criterion_how(d, res->nconditions) : vigen_strdup_printf(
            "the %ld order conditions (polynomials in the steps, from the BCH series of the method) solved by "
            "Newton from %ld random starts on a square subsystem of %ld, this root refined in arb and proved by the "
            "Krawczyk operator, the rest decided on its box and the file certified by the checker", (long)sys.n,
            (long)starts, (long)m);
        if (rc == VIGEN_OK) rc = certify_all(res, d, opt, base, how, err);
        free(how);
        if (rc == VIGEN_OK && d->goal == VIGEN_DESIGN_MINIMIZE) keep_best(res, d);
    }
    free(rows);
    design_system_clear(&sys);
    free(base);
    return rc;
}
