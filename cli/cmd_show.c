/* cmd_show.c — `vigen show FILE`: a tableau (or the tableau of a spec) as
 * text, LaTeX, JSON or a tableau file on standard output. */
#include <stdlib.h>
#include "cli.h"
#include "vigen/method.h"
#include "vigen/show.h"

int vigen_cmd_show(const vigen_cli_args *args)
{
    long long digits = VIGEN_CLI_DEFAULT_DIGITS;
    int rc;
    if (args->value[VIGEN_OPT_show_digits] &&
        (rc = vigen_cli_whole(&digits, args, VIGEN_OPT_show_digits, 1, 100000)) >= 0)
        return rc;
    const char *format = args->value[VIGEN_OPT_show_format] ? args->value[VIGEN_OPT_show_format] : "text";
    vigen_show_format fmt;
    if (!vigen_show_parse_format(&fmt, format))
        return vigen_cli_usage_error(args->command, "unknown format '%s' (use %s)", format,
                                     vigen_show_format_names());

    vigen_error err;
    vigen_error_init(&err);
    vigen_method *m = NULL;
    if (vigen_method_load(&m, args->operand, NULL, &err) != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    vigen_tableau t;
    rc = vigen_method_tableau(&t, m, (slong)digits, &err);
    vigen_method_free(m);
    if (rc != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    char *text = NULL;
    rc = vigen_show_render(&text, &t, fmt, (slong)digits, &err);
    vigen_tableau_clear(&t);
    if (rc != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    fputs(text, stdout);
    free(text);
    return 0;
}
