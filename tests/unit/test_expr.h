/* test_expr.h — what the tests of the expression parser share
 * (test_expr.c, test_expr_calculus.c, test_expr_exact.c): evaluating a text
 * with its checks, and finding a phrase in a message. */
#ifndef VIGEN_TEST_EXPR_H
#define VIGEN_TEST_EXPR_H

#include <string.h>
#include "core/expr.h"
#include "testlib.h"

/* Parses and evaluates text (t may be NULL); checks success. */
static inline int eval_text(arb_t res, const char *text, const arb_t t, slong prec)
{
    vigen_error err;
    vigen_expr *e = NULL;
    vigen_error_init(&err);
    int rc = vigen_expr_parse(&e, text, t != NULL, &err);
    CHECK_MSG(rc == VIGEN_OK, "parse \"%s\": %s", text, err.message ? err.message : "");
    if (rc == VIGEN_OK) {
        rc = vigen_expr_eval_arb(res, e, t, prec, &err);
        CHECK_MSG(rc == VIGEN_OK, "eval \"%s\": %s", text, err.message ? err.message : "");
    }
    vigen_expr_free(e);
    vigen_error_clear(&err);
    return rc;
}

static inline int contains(const char *haystack, const char *needle)
{
    return haystack != NULL && strstr(haystack, needle) != NULL;
}

#endif
