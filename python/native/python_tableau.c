/* python_tableau.c — tableaux for the Python package: `vigen generate`,
 * `vigen show` and a tableau file written atomically (vigen_python.h),
 * through the library functions the command line calls. */
#include <stdlib.h>
#include "python_internal.h"
#include "vigen/check.h"
#include "vigen/method.h"
#include "vigen/show.h"
#include "vigen/tableau.h"
#include "support/file.h"
#include "support/printable.h"
#include "support/strbuf.h"

/* the digits the command line uses when --digits is not given */
enum { DEFAULT_DIGITS = 34, MAX_DIGITS = 100000 };

/* the summary `vigen generate` prints on standard error */
static char *summary(vigen_tableau *t, slong digits)
{
    arb_t res;
    arb_init(res);
    vigen_tableau_symplectic_residual(res, t, t->prec);
    char *rs = arb_get_str(res, 5, 0);
    char *name = vigen_printable(t->name);
    char *line = vigen_strdup_printf("vigen: %s: %ld stages, %ld certified digits (working precision %ld bits); "
                                     "symplecticity residual %s",
                                     name, (long)t->s, (long)digits, (long)t->prec, rs);
    free(name);
    flint_free(rs);
    arb_clear(res);
    return line;
}

int vigen_python_generate(vigen_python_result *r, const char *spec, const char *digits_text)
{
    pyn_begin(r, "generate");
    long long digits = DEFAULT_DIGITS;
    int rc = pyn_whole(r, &digits, "--digits", digits_text, 1, MAX_DIGITS);
    char *path = NULL;
    if (rc == VIGEN_OK) rc = pyn_resolve(r, &path, spec);
    if (rc != VIGEN_OK) return pyn_end(r, rc);
    vigen_error err;
    vigen_error_init(&err);
    vigen_method *m = NULL;
    if (vigen_method_load(&m, path, NULL, &err) != VIGEN_OK) {
        free(path);
        return pyn_end(r, pyn_fail(r, &err));
    }
    if (!vigen_method_is_generated(m)) {
        vigen_method_free(m);
        rc = pyn_usage(r, "%s is a tableau file, not a spec (nodes and basis); 'vigen show %s --format lua' prints it",
                       path, path);
        free(path);
        return pyn_end(r, rc);
    }
    vigen_tableau t;
    rc = vigen_method_tableau(&t, m, (slong)digits, &err);
    vigen_method_free(m);
    if (rc != VIGEN_OK) {
        free(path);
        return pyn_end(r, pyn_fail(r, &err));
    }
    /* the certified order and symplecticity become the file's claims */
    rc = vigen_check_certify(&t, path, &err);
    free(path);
    if (rc == VIGEN_OK) {
        r->text = vigen_tableau_to_lua(&t);
        rc = vigen_show_render(&r->extra, &t, VIGEN_SHOW_JSON, (slong)digits, &err);
    }
    if (rc == VIGEN_OK) r->message = summary(&t, (slong)digits);
    vigen_tableau_clear(&t);
    if (rc != VIGEN_OK) {
        free(r->text);
        free(r->extra);
        r->text = r->extra = NULL;
        rc = pyn_fail(r, &err);
    }
    return pyn_end(r, rc);
}

int vigen_python_show(vigen_python_result *r, const char *file, const char *format, const char *digits_text)
{
    pyn_begin(r, "show");
    long long digits = DEFAULT_DIGITS;
    int rc = pyn_whole(r, &digits, "--digits", digits_text, 1, MAX_DIGITS);
    if (rc != VIGEN_OK) return pyn_end(r, rc);
    vigen_show_format fmt;
    if (!vigen_show_parse_format(&fmt, format ? format : "text"))
        return pyn_end(r, pyn_usage(r, "unknown format '%s' (use %s)", format, vigen_show_format_names()));
    char *path = NULL;
    if ((rc = pyn_resolve(r, &path, file)) != VIGEN_OK) return pyn_end(r, rc);
    vigen_error err;
    vigen_error_init(&err);
    vigen_method *m = NULL;
    rc = vigen_method_load(&m, path, NULL, &err);
    free(path);
    if (rc != VIGEN_OK) return pyn_end(r, pyn_fail(r, &err));
    vigen_tableau t;
    rc = vigen_method_tableau(&t, m, (slong)digits, &err);
    vigen_method_free(m);
    if (rc == VIGEN_OK) {
        rc = vigen_show_render(&r->text, &t, fmt, (slong)digits, &err);
        vigen_tableau_clear(&t);
    }
    if (rc != VIGEN_OK) rc = pyn_fail(r, &err);
    return pyn_end(r, rc);
}

int vigen_python_write_file(vigen_python_result *r, const char *command, const char *path, const char *text)
{
    pyn_begin(r, command);
    vigen_error err;
    vigen_error_init(&err);
    int rc = vigen_write_file_atomic(path, text, &err);
    if (rc != VIGEN_OK) rc = pyn_fail(r, &err);
    return pyn_end(r, rc);
}
