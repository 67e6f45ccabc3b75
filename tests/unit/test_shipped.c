/* test_shipped.c — identities every shipped generated tableau must satisfy,
 * read back from the committed files (decimals as half-unit balls):
 *   symplecticity  b_i at_ij + b_j a_ji - b_i b_j = 0 (the ball contains 0),
 *   ct_i = sum_j at_ij, c_i = sum_j a_ij, sum_i b_i = 1,
 * and the file's digits field matches the digits actually written.  Each is
 * also written out again (vigen_tableau_to_lua, vigen_write_file_atomic) and
 * read back: the same file, byte for byte. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "core/decimal.h"
#include "vigen/tableau.h"
#include "testlib.h"
#include "support/strbuf.h"
#include "support/file.h"

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) return NULL;
    vigen_strbuf b;
    vigen_strbuf_init(&b);
    vigen_strbuf_append(&b, "");
    char chunk[4096];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) vigen_strbuf_appendn(&b, chunk, n);
    fclose(f);
    return b.data;
}

/* The file read and written again is the same file. */
static void check_round_trip(const char *path, const vigen_tableau *t)
{
    vigen_error err;
    vigen_error_init(&err);
    char tmp[] = "/tmp/vigen-test-shipped-XXXXXX";
    int fd = mkstemp(tmp);
    CHECK(fd >= 0);
    if (fd < 0) return;
    close(fd);
    char *text = vigen_tableau_to_lua(t);
    CHECK_MSG(vigen_write_file_atomic(tmp, text, &err) == VIGEN_OK, "%s: %s", path, err.message);
    char *original = slurp(path), *written = slurp(tmp);
    CHECK_MSG(original && written && strcmp(original, written) == 0, "%s: written again, it differs", path);
    free(original);
    free(written);
    free(text);
    remove(tmp);
    vigen_error_clear(&err);
}

/* A write that cannot happen is VIGEN_E_WRITE, naming the file. */
static void check_write_failure(void)
{
    vigen_error err;
    vigen_error_init(&err);
    const char *path = "/nonexistent-vigen-dir/out.lua";
    CHECK(vigen_write_file_atomic(path, "return {}\n", &err) == VIGEN_E_WRITE);
    CHECK(err.message != NULL && strstr(err.message, path) != NULL);
    CHECK(access(path, F_OK) != 0);
    vigen_error_clear(&err);
}

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
    check_round_trip(path, &t);
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
    check_write_failure();
    TEST_MAIN_END();
}
