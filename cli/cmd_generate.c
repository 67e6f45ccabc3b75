/* cmd_generate.c — `vigen generate SPEC`: the tableau of a spec, written as a
 * tableau file, with a one-line summary on standard error. */
#include <stdlib.h>
#include "cli.h"
#include "vigen/check.h"
#include "vigen/method.h"
#include "support/printable.h"
#include "support/file.h"
#include "support/progress.h"
#include "vigen/tableau.h"

static void print_summary(vigen_tableau *t, slong digits)
{
    arb_t res;
    arb_init(res);
    vigen_tableau_symplectic_residual(res, t, t->prec);
    char *r = arb_get_str(res, 5, 0);
    char *name = vigen_printable(t->name);   /* the name comes from the file */
    fprintf(stderr, "vigen: %s: %ld stages, %ld certified digits (working precision %ld bits); "
                    "symplecticity residual %s\n",
            name, (long)t->s, (long)digits, (long)t->prec, r);
    free(name);
    flint_free(r);
    arb_clear(res);
}

int vigen_cmd_generate(const vigen_cli_args *args)
{
    long long digits = VIGEN_CLI_DEFAULT_DIGITS;
    int rc;
    if (args->value[VIGEN_OPT_generate_digits] &&
        (rc = vigen_cli_whole(&digits, args, VIGEN_OPT_generate_digits, 1, 100000)) >= 0)
        return rc;
    const char *out_path = args->value[VIGEN_OPT_generate_output];

    vigen_error err;
    vigen_error_init(&err);
    vigen_method *m = NULL;
    if (vigen_method_load(&m, args->operand, NULL, &err) != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    if (!vigen_method_is_generated(m)) {
        vigen_method_free(m);
        return vigen_cli_usage_error(args->command,
                                     "%s is a tableau file, not a spec (nodes and basis); 'vigen show %s --format lua' "
                                     "prints it", args->operand, args->operand);
    }
    vigen_tableau t;
    /* a line on a terminal when the generation takes more than a second */
    vigen_progress_begin("vigen generate");
    vigen_progress_set("%s: %lld digits", args->operand, (long long)digits);
    rc = vigen_method_tableau(&t, m, (slong)digits, &err);
    vigen_progress_end();
    vigen_method_free(m);
    if (rc != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    /* the order and symplecticity the checker certifies become the file's
     * claims (a spec's own order = p is checked here) */
    if (vigen_check_certify(&t, args->operand, &err) != VIGEN_OK) {
        vigen_tableau_clear(&t);
        return vigen_cli_fail(args->command, &err);
    }

    char *text = vigen_tableau_to_lua(&t);
    rc = vigen_write_file_atomic(out_path ? out_path : "-", text, &err);
    free(text);
    if (rc == VIGEN_OK && !args->value[VIGEN_OPT_generate_quiet]) print_summary(&t, (slong)digits);
    vigen_tableau_clear(&t);
    if (rc != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    return 0;
}
