/* test_leok_zhang.c — the generator against the closed forms of Leok & Zhang,
 * "Discrete Hamiltonian variational integrators", section 4.5, Examples 2–5.
 *
 * The closed forms live in tests/data/leok_zhang/ (one tableau file per example) as exact expressions,
 * transcribed from the paper and re-derived by hand/sympy where the paper is
 * inconsistent (each corrected entry carries a comment there; see
 * docs/published.md).  Every entry of the generated tableau must agree to 50
 * digits (the issue asks for 40), and the committed 50-digit files in
 * tableaux/generated/ must contain the exact values in their rounding balls. */
#include <stdio.h>
#include <string.h>
#include "galerkin.h"
#include "spec.h"
#include "testlib.h"

static const char *const pairs[][2] = {
    {"leok_zhang_ex2_c0", "leok_zhang_ex2_i"},    {"leok_zhang_ex2_c12", "leok_zhang_ex2_ii"},
    {"leok_zhang_ex2_c1", "leok_zhang_ex2_iii"},  {"leok_zhang_ex3", "leok_zhang_ex3"},
    {"leok_zhang_ex4", "leok_zhang_ex4"},         {"leok_zhang_ex5_s1", "leok_zhang_ex5_i"},
    {"leok_zhang_ex5_s2", "leok_zhang_ex5_ii"},   {"leok_zhang_ex5_s3", "leok_zhang_ex5_iii"},
};

#define PREC 512

/* every entry of x agrees with the closed form y to `digits` digits */
static void compare(const vigen_tableau *x, const vigen_tableau *y, slong digits, const char *what)
{
    slong s = x->s;
    for (slong i = 0; i < s; i++) {
        CHECK_MSG(testlib_arb_close(x->c + i, y->c + i, digits, PREC), "%s c[%ld]", what, (long)(i + 1));
        CHECK_MSG(testlib_arb_close(x->b + i, y->b + i, digits, PREC), "%s b[%ld]", what, (long)(i + 1));
        if (y->has_ct)
            CHECK_MSG(testlib_arb_close(x->ct + i, y->ct + i, digits, PREC), "%s ct[%ld]", what, (long)(i + 1));
        for (slong j = 0; j < s; j++) {
            CHECK_MSG(testlib_arb_close(arb_mat_entry(x->A, i, j), arb_mat_entry(y->A, i, j), digits, PREC),
                      "%s A[%ld][%ld]", what, (long)(i + 1), (long)(j + 1));
            CHECK_MSG(testlib_arb_close(arb_mat_entry(x->At, i, j), arb_mat_entry(y->At, i, j), digits, PREC),
                      "%s At[%ld][%ld]", what, (long)(i + 1), (long)(j + 1));
        }
    }
}

/* the closed form lies in every rounding ball of the committed file */
static void contained(const vigen_tableau *file, const vigen_tableau *y, const char *what)
{
    slong s = file->s;
    for (slong i = 0; i < s; i++) {
        CHECK_MSG(arb_contains(file->c + i, y->c + i), "%s c[%ld]", what, (long)(i + 1));
        CHECK_MSG(arb_contains(file->b + i, y->b + i), "%s b[%ld]", what, (long)(i + 1));
        if (y->has_ct) CHECK_MSG(arb_contains(file->ct + i, y->ct + i), "%s ct[%ld]", what, (long)(i + 1));
        for (slong j = 0; j < s; j++) {
            CHECK_MSG(arb_contains(arb_mat_entry(file->A, i, j), arb_mat_entry(y->A, i, j)), "%s A[%ld][%ld]", what,
                      (long)(i + 1), (long)(j + 1));
            CHECK_MSG(arb_contains(arb_mat_entry(file->At, i, j), arb_mat_entry(y->At, i, j)), "%s At[%ld][%ld]",
                      what, (long)(i + 1), (long)(j + 1));
        }
    }
}

int main(void)
{
    for (size_t k = 0; k < sizeof pairs / sizeof pairs[0]; k++) {
        char spec_path[256], data_path[256], gen_path[256];
        snprintf(spec_path, sizeof spec_path, "tableaux/specs/%s.lua", pairs[k][0]);
        snprintf(data_path, sizeof data_path, "tests/data/leok_zhang/%s.lua", pairs[k][1]);
        snprintf(gen_path, sizeof gen_path, "tableaux/generated/%s.lua", pairs[k][0]);
        vigen_error err;
        vigen_error_init(&err);

        vigen_tableau exact;
        int ok = vigen_tableau_load(&exact, data_path, NULL, &err) == VIGEN_OK;
        CHECK_MSG(ok, "%s", err.message);
        if (!ok) { vigen_error_clear(&err); continue; }
        CHECK_MSG(vigen_tableau_evaluate(&exact, PREC, &err) == VIGEN_OK, "%s", err.message);

        vigen_spec *spec = NULL;
        vigen_tableau gen;
        ok = vigen_spec_load(&spec, spec_path, NULL, &err) == VIGEN_OK &&
             vigen_galerkin_generate(&gen, spec, 60, &err) == VIGEN_OK;
        CHECK_MSG(ok, "%s: %s", spec_path, err.message);
        if (spec) vigen_spec_free(spec);
        if (ok) {
            CHECK(gen.s == exact.s);
            if (gen.s == exact.s) compare(&gen, &exact, 50, pairs[k][0]);
            vigen_tableau_clear(&gen);
        }

        vigen_tableau file;
        ok = vigen_tableau_load(&file, gen_path, NULL, &err) == VIGEN_OK &&
             vigen_tableau_evaluate(&file, PREC, &err) == VIGEN_OK;
        CHECK_MSG(ok, "%s: %s", gen_path, err.message);
        if (ok) {
            if (file.s == exact.s) contained(&file, &exact, gen_path);
            vigen_tableau_clear(&file);
        }
        vigen_tableau_clear(&exact);
        vigen_error_clear(&err);
    }
    TEST_MAIN_END();
}
