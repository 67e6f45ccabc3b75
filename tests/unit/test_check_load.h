/* test_check_load.h — for the checker's tests: check a tableau file of the
 * source tree, as `vigen check` would. */
#ifndef VIGEN_TEST_CHECK_LOAD_H
#define VIGEN_TEST_CHECK_LOAD_H

#include <stdio.h>
#include "vigen/check.h"
#include "vigen/method.h"

/* Checks the file at rel (from the source tree) with its order claim replaced
 * by claim (-1: none; -2: as the file states) and orders up to P enumerated
 * (0: the default).  rep is initialised; clear it. */
static int check_file_claim(vigen_check_report *rep, const char *rel, int claim, int P)
{
    char path[1024];
    snprintf(path, sizeof(path), "%s/%s", VIGEN_SOURCE_DIR, rel);
    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau t;
    vigen_check_report_init(rep);
    /* any method file read as it states its tableau (splitting files too) */
    vigen_method *m = NULL;
    int rc = vigen_method_load(&m, path, NULL, &err);
    if (rc == VIGEN_OK) rc = vigen_method_tableau(&t, m, 0, &err);
    vigen_method_free(m);
    if (rc == VIGEN_OK) {
        if (claim != -2) t.claim_order = claim;
        vigen_check_options opt;
        vigen_check_options_init(&opt);
        if (P > 0) opt.max_order = P;
        opt.path = rel;
        rc = vigen_check_tableau(rep, &t, NULL, &opt, &err);
        vigen_tableau_clear(&t);
    }
    if (rc != VIGEN_OK) fprintf(stderr, "%s: %s\n", rel, err.message ? err.message : "?");
    vigen_error_clear(&err);
    return rc;
}

#endif
