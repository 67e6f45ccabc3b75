/* cmd_compare.c — `vigen compare FILE...`: the checker's figures of several
 * methods side by side (vigen/compare.h). */
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "vigen/compare.h"
#include "vigen/method.h"
#include "support/strbuf.h"

enum { MAX_FILES = 64 };

int vigen_cmd_compare(const vigen_cli_args *args)
{
    int format = VIGEN_COMPARE_TEXT;
    const char *f = args->value[VIGEN_OPT_compare_format];
    if (f && strcmp(f, "latex") == 0) format = VIGEN_COMPARE_LATEX;
    else if (f && strcmp(f, "json") == 0) format = VIGEN_COMPARE_JSON;
    else if (f && strcmp(f, "text") != 0)
        return vigen_cli_usage_error(args->command, "--format %s: choose text, latex or json", f);
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.load = vigen_source_load;
    long long n;
    int rc;
    if (args->value[VIGEN_OPT_compare_max_order]) {
        if ((rc = vigen_cli_whole(&n, args, VIGEN_OPT_compare_max_order, 1, VIGEN_TREE_MAX_ORDER)) >= 0) return rc;
        opt.max_order = (int)n;
    }
    /* the operand holds the files one a line (option_parser.c collects them) */
    char *text = vigen_strdup(args->operand);
    const char *paths[MAX_FILES];
    size_t count = 0;
    for (char *line = text; line != NULL;) {
        char *nl = strchr(line, '\n');
        if (nl) *nl = '\0';
        if (count == MAX_FILES) {
            free(text);
            return vigen_cli_usage_error(args->command, "at most %d files at a time", MAX_FILES);
        }
        paths[count++] = line;
        line = nl ? nl + 1 : NULL;
    }
    vigen_error err;
    vigen_error_init(&err);
    int status = 0;
    if (vigen_compare_run(paths, count, &opt, format, stdout, &err) != VIGEN_OK)
        status = vigen_cli_fail(args->command, &err);
    free(text);
    return status;
}
