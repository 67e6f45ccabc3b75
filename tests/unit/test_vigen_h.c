/* test_vigen_h.c — <vigen/vigen.h> alone is the whole public API: this file
 * includes nothing else of vigen and calls a function of every public header
 * (cli_layout checks that vigen.h includes each of them).  The expectations
 * are facts about the methods and objects, not outputs of the code:
 *  - Gauss–Legendre with s = 2 (the implicit midpoint's two-stage sibling) has
 *    2 stages and order 2s = 4 (Butcher), and is symplectic;
 *  - bicoloured rooted trees of order 1, 2, 3: 2, 4, 14 (OEIS A038055);
 *  - the documented defaults and refusals of the options. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/vigen.h>
#include "testlib.h"

#define GAUSS2 "tableaux/published/gauss_2.lua"

static int is_c_identifier(const char *s)
{
    if (s == NULL || !(isalpha((unsigned char)s[0]) || s[0] == '_')) return 0;
    for (; *s; s++)
        if (!(isalnum((unsigned char)*s) || *s == '_')) return 0;
    return 1;
}

int main(void)
{
    vigen_error err;
    vigen_error_init(&err);

    /* vigen.h */
    const char *v = vigen_version();
    int major, minor, patch;
    CHECK(v != NULL && sscanf(v, "%d.%d.%d", &major, &minor, &patch) == 3);

    /* error.h */
    CHECK(vigen_status_exit_code(VIGEN_OK) == 0);
    CHECK(vigen_status_exit_code(VIGEN_E_USAGE) != 0);

    /* limits.h: 256 MiB and 50 million instructions by default */
    vigen_sandbox_limits lim;
    vigen_sandbox_limits_default(&lim);
    CHECK(lim.memory_limit == (size_t)256 << 20 && lim.instruction_limit == 50000000L);

    /* method.h, tableau.h */
    vigen_method *m = NULL;
    vigen_tableau t;
    CHECK(vigen_method_load(&m, GAUSS2, NULL, &err) == VIGEN_OK);
    CHECK(m != NULL && !vigen_method_is_generated(m));
    int have_tableau = m != NULL && vigen_method_tableau(&t, m, 30, &err) == VIGEN_OK;
    CHECK(have_tableau);
    vigen_method_free(m);
    if (have_tableau) {
        CHECK(t.s == 2);

        /* check.h */
        vigen_check_options opt;
        vigen_check_options_init(&opt);
        vigen_check_report rep;
        vigen_check_report_init(&rep);
        CHECK(vigen_check_tableau(&rep, &t, NULL, &opt, &err) == VIGEN_OK);
        int at_least = 0, undecided = 0;
        CHECK(vigen_check_certified_order(&rep, VIGEN_CHECK_GENERAL, &at_least, &undecided) == 4);
        vigen_check_report_clear(&rep);

        /* show.h */
        vigen_show_format fmt;
        CHECK(vigen_show_parse_format(&fmt, "json") == 1);
        CHECK(vigen_show_parse_format(&fmt, "yaml") == 0);
        char *text = NULL;
        CHECK(vigen_show_render(&text, &t, fmt, 10, &err) == VIGEN_OK && text != NULL && text[0] == '{');
        free(text);
        vigen_tableau_clear(&t);
    }

    /* trees.h */
    vigen_treeset ts;
    CHECK(vigen_treeset_init(&ts, 3, &err) == VIGEN_OK);
    CHECK(vigen_treeset_count(&ts, 1) == 2 && vigen_treeset_count(&ts, 2) == 4 && vigen_treeset_count(&ts, 3) == 14);
    vigen_treeset_clear(&ts);

    /* compare.h: the table names the method compared */
    FILE *out = tmpfile();
    CHECK(out != NULL);
    if (out != NULL) {
        const char *paths[] = { GAUSS2 };
        vigen_check_options opt;
        vigen_check_options_init(&opt);
        CHECK(vigen_compare_run(paths, 1, &opt, VIGEN_COMPARE_TEXT, out, &err) == VIGEN_OK);
        CHECK(ftell(out) > 0);
        fclose(out);
    }

    /* emit.h */
    char *ident = vigen_emit_identifier("2-stage Gauss");
    CHECK(is_c_identifier(ident));
    free(ident);

    /* try.h: h must be a positive number */
    vigen_try_options topt;
    memset(&topt, 0, sizeof topt);
    CHECK(vigen_try_options_set(&topt, "kepler", NULL, "0.5", NULL, NULL, &err) == VIGEN_OK && topt.h == 0.5);
    vigen_error_clear(&err);
    CHECK(vigen_try_options_set(&topt, "kepler", NULL, "-1", NULL, NULL, &err) == VIGEN_E_USAGE);
    vigen_error_clear(&err);

    /* library.h: the folders a name is looked up in, NULL-terminated */
    char **dirs = vigen_library_dirs();
    CHECK(dirs != NULL);
    vigen_library_dirs_free(dirs);

    if (err.message) fprintf(stderr, "last error: %s\n", err.message);
    vigen_error_clear(&err);
    return testlib_failures ? 1 : 0;
}
