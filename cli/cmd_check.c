/* cmd_check.c — `vigen check FILE`: runs the checker and prints its report
 * as text or, with --json, as one JSON object; the report's verdict is the
 * exit status (0 or 1). */
#include "cli.h"
#include "vigen/check.h"
#include "vigen/method.h"

int vigen_cmd_check(const vigen_cli_args *args)
{
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.load = vigen_source_load; /* FILE and FILE2, each run once */
    opt.path = args->operand;
    opt.against = args->value[VIGEN_OPT_check_against];
    long long n;
    int rc;
    if (args->value[VIGEN_OPT_check_max_order]) {
        if ((rc = vigen_cli_whole(&n, args, VIGEN_OPT_check_max_order, 1, VIGEN_TREE_MAX_ORDER)) >= 0) return rc;
        opt.max_order = (int)n;
    }
    if (args->value[VIGEN_OPT_check_prec]) {
        if ((rc = vigen_cli_whole(&n, args, VIGEN_OPT_check_prec, 16, 1000000)) >= 0) return rc;
        opt.prec = (slong)n;
        if (opt.max_prec < opt.prec) opt.max_prec = opt.prec;
    }
    vigen_error err;
    vigen_error_init(&err);
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    rc = vigen_check_file(&rep, &opt, &err);
    if (rc == VIGEN_OK) {
        if (args->value[VIGEN_OPT_check_json]) vigen_check_print_json(stdout, &rep);
        else vigen_check_print_text(stdout, &rep);
    }
    int verdict = rep.exit_code;
    vigen_check_report_clear(&rep);
    if (err.code != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    if (rc != VIGEN_OK) return vigen_status_exit_code(rc);
    return verdict;
}
