/* design_processed.c — the corrector of a kernel of effective order 4.
 *
 * A proved kernel K (design_quotient.c: its h^3 term is mu [A+B,[A,B]])
 * becomes a method of order 4 when conjugated, C K C^-1, by a corrector C
 * with log C = mu h^2 [A,B] + O(h^4) (docs/design.md).  The corrector written
 * is drift y1, kick y2, drift y3, kick y4, drift y5, kick y6; its five
 * conditions (the Lyndon words A, B, AB, AAB, ABB of log C) depend on the
 * kernel through mu, a polynomial in the kernel's steps.  Five substeps
 * (drift, kick, drift, kick, drift) gave no real solution in a search, six
 * leave one free: y6 is held at a binary fraction, exactly, tried from a
 * short list until a corrector is found.  The kernel's square subsystem and
 * the corrector's conditions together are one square system in (x, y),
 * exact rational polynomials: Newton from the kernel's root with random y,
 * the smallest corrector found, and one Krawczyk proof of the whole, so
 * that the kernel's and the corrector's digits are certified together.
 * Several correctors exist (the conditions are not linear); any one does.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "design/design_internal.h"
#include "core/decimal.h"
#include "support/strbuf.h"

#define CORRECTOR_STARTS 400
#define CORRECTOR_BOX 2.0
#define SAME_KERNEL 1e-8

int design_corrector_find(char ***digits, char **radius, char **why, const vigen_design_spec *d,
                          const design_system *ksys, const slong *rows, const double *x, long ndigits,
                          vigen_error *err)
{
    *digits = NULL;
    *radius = *why = NULL;
    design_system kernel, sys;
    unsigned mods = d->nystrom ? DESIGN_MOD_NYSTROM : 0;
    int rc = design_splitting_conditions(&kernel, d->stages, 1, 4, mods | DESIGN_MOD_PROCESSED, err);
    if (rc != VIGEN_OK) return -1;
    slong kernel_rows = kernel.n + d->nfix + d->nequal, kx = kernel.k;
    design_system_clear(&kernel);
    rc = design_processed_conditions(&sys, d->stages, mods, err);
    if (rc != VIGEN_OK) return -1;
    design_system_fix(&sys, d);                  /* as the kernel's rows were: the same row numbers */
    slong k = sys.k;
    if (sys.n != kernel_rows + DESIGN_CORRECTOR_CONDITIONS) {
        *why = vigen_strdup("no corrector: its conditions are degenerate");
        design_system_clear(&sys);
        return 0;
    }
    slong *rows2 = malloc((size_t)k * sizeof(slong));
    /* the kernel's conditions keep their rows; its pins (the free steps a
     * minimisation holds, a first kick held at 0) are copied */
    for (slong i = 0; i < kx; i++)
        rows2[i] = rows[i] < kernel_rows ? rows[i] : design_system_copy_pin(&sys, ksys, rows[i]);
    for (slong i = 0; i < DESIGN_CORRECTOR_CONDITIONS; i++) rows2[kx + i] = kernel_rows + i;
    rows2[k - 1] = design_system_add_pin(&sys, k - 1);
    static const double last_kick[] = {0.5, -0.5, 0.25, -0.25, 1, -1, 0.125, -0.125};
    double *roots = NULL;
    slong n = 0, best = -1;
    for (size_t t = 0; t < sizeof last_kick / sizeof *last_kick && n == 0; t++) {
        free(roots);
        roots = NULL;
        design_system_set_pin(&sys, rows2[k - 1], last_kick[t]);
        n = design_newton_search_anchored(&roots, &sys, rows2, CORRECTOR_STARTS, d->seed, CORRECTOR_BOX, x, kx);
        for (slong r = 0; r < n; r++) {
            double dist = 0;
            for (slong j = 0; j < kx; j++) dist = fmax(dist, fabs(roots[r * k + j] - x[j]) / (1 + fabs(x[j])));
            if (dist < SAME_KERNEL) best = -2;
        }
        if (best == -1) n = 0;
    }
    best = -1;
    double best_size = 0;
    for (slong r = 0; r < n; r++) {
        double dist = 0, size = 0;
        for (slong j = 0; j < kx; j++) dist = fmax(dist, fabs(roots[r * k + j] - x[j]) / (1 + fabs(x[j])));
        for (slong j = kx; j < k; j++) size = fmax(size, fabs(roots[r * k + j]));
        if (dist < SAME_KERNEL && (best < 0 || size < best_size)) best = r, best_size = size;
    }
    int found = 0;
    if (best < 0) {
        *why = vigen_strdup_printf("no corrector found: Newton from %d starts for each last kick tried found "
                                   "none for this kernel", CORRECTOR_STARTS);
    } else {
        arb_ptr box = _arb_vec_init(k);
        slong prec = (slong)((double)ndigits * 3.33) + 96;
        for (int attempt = 0; attempt < 3 && !found; attempt++, prec *= 2)
            found = design_krawczyk_prove(box, &sys, rows2, roots + best * k, prec);
        if (!found) *why = vigen_strdup("the corrector was not proved: the Krawczyk test failed on every box tried");
        if (found) {
            *digits = calloc((size_t)k, sizeof(char *));
            mag_t rad;
            mag_init(rad);
            for (slong j = 0; j < k && found; j++) {
                mag_max(rad, rad, arb_radref(box + j));
                found = ((*digits)[j] = vigen_decimal_format(box + j, ndigits)) != NULL;
            }
            if (found) {
                arb_t rr;
                arb_init(rr);
                arf_set_mag(arb_midref(rr), rad);
                char *s = arb_get_str(rr, 3, ARB_STR_NO_RADIUS);
                *radius = vigen_strdup(s);
                flint_free(s);
                arb_clear(rr);
            } else {
                *why = vigen_strdup("the corrector was not proved to the digits asked (the box is too wide)");
                for (slong j = 0; j < k; j++) free((*digits)[j]);
                free(*digits);
                *digits = NULL;
            }
            mag_clear(rad);
        }
        _arb_vec_clear(box, k);
    }
    free(roots);
    free(rows2);
    design_system_clear(&sys);
    return found;
}
