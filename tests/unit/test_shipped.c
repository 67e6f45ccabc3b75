/* test_shipped.c — identities every shipped generated tableau must satisfy,
 * read back from the committed files (decimals as half-unit balls):
 *   symplecticity  b_i at_ij + b_j a_ji - b_i b_j = 0 (the ball contains 0),
 *   ct_i = sum_j at_ij, c_i = sum_j a_ij, sum_i b_i = 1,
 * and the file's digits field matches the digits actually written. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/decimal.h"
#include "vigen/tableau.h"
#include "testlib.h"

static void check_file(const char *path)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau t;
    if (vigen_tableau_load(&t, path, NULL, &err) != VIGEN_OK || vigen_tableau_evaluate(&t, 400, &err) != VIGEN_OK) {
        CHECK_MSG(0, "%s: %s", path, err.message);
        vigen_error_clear(&err);
        return;
    }
    slong s = t.s, prec = 400;
    arb_t r, one;
    arb_init(r);
    arb_init(one);
    arb_one(one);
    CHECK_MSG(t.has_At && t.has_ct, "%s: At and ct must be present", path);
    vigen_tableau_symplectic_residual(r, &t, prec);
    CHECK_MSG(arb_contains_zero(r), "%s: symplecticity residual excludes 0", path);
    for (slong i = 0; i < s; i++) {
        arb_zero(r);
        for (slong j = 0; j < s; j++) arb_add(r, r, arb_mat_entry(t.At, i, j), prec);
        CHECK_MSG(arb_overlaps(r, t.ct + i), "%s: ct_%ld != sum_j at_ij", path, (long)(i + 1));
        arb_zero(r);
        for (slong j = 0; j < s; j++) arb_add(r, r, arb_mat_entry(t.A, i, j), prec);
        CHECK_MSG(arb_overlaps(r, t.c + i), "%s: c_%ld != sum_j a_ij", path, (long)(i + 1));
    }
    arb_zero(r);
    for (slong i = 0; i < s; i++) arb_add(r, r, t.b + i, prec);
    CHECK_MSG(arb_contains(r, one), "%s: sum b != 1", path);
    /* every decimal entry carries exactly `digits` significant digits */
    for (slong k = 0; k < s * s; k++) {
        const char *e = t.A_text[k];
        if (vigen_decimal_is_rounded(e) && strncmp(e, "0e", 2) != 0)
            CHECK_MSG(vigen_decimal_significant_digits(e) == t.digits, "%s: A entry %s", path, e);
    }
    CHECK_MSG(t.digits == 50, "%s: shipped tableaux carry 50 digits", path);
    arb_clear(r);
    arb_clear(one);
    vigen_tableau_clear(&t);
}

int main(void)
{
    DIR *d = opendir("tableaux/generated");
    CHECK(d != NULL);
    int count = 0;
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL) {
        size_t n = strlen(e->d_name);
        if (n < 5 || strcmp(e->d_name + n - 4, ".lua") != 0) continue;
        char path[512];
        snprintf(path, sizeof path, "tableaux/generated/%s", e->d_name);
        check_file(path);
        count++;
    }
    if (d) closedir(d);
    CHECK_MSG(count >= 26, "only %d shipped tableaux", count);
    TEST_MAIN_END();
}
