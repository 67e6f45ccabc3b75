/* cmd_order.c — `vigen order METHOD --problem NAME`: the empirical order
 * under step halving next to the certified order (vigen/try.h), as a table
 * (or JSON) and, with --plot, a figure. */
#include <stdlib.h>
#include "cli.h"
#include "vigen/try.h"

int vigen_cmd_order(const vigen_cli_args *args)
{
    long long levels = 5;
    int rc;
    if (args->value[VIGEN_OPT_order_levels] &&
        (rc = vigen_cli_whole(&levels, args, VIGEN_OPT_order_levels, 2, 12)) >= 0)
        return rc;
    vigen_error err;
    vigen_error_init(&err);
    vigen_try_options opt;
    if (vigen_try_options_set(&opt, args->value[VIGEN_OPT_order_problem], args->value[VIGEN_OPT_order_param],
                              args->value[VIGEN_OPT_order_h], args->value[VIGEN_OPT_order_steps_per_period],
                              args->value[VIGEN_OPT_order_time], &err) != VIGEN_OK) {
        rc = vigen_cli_usage_error(args->command, "%s", err.message);
        vigen_error_clear(&err);
        free((char *)opt.params);
        return rc;
    }
    opt.progress = 1;
    opt.allow_inexact = args->value[VIGEN_OPT_order_allow_inexact] != NULL;
    vigen_try_order_result res;
    int status = 0;
    if (vigen_try_order(args->operand, &opt, (int)levels, &res, &err) != VIGEN_OK)
        status = vigen_cli_fail(args->command, &err);
    else {
        vigen_try_order_print(stdout, &opt, &res, args->value[VIGEN_OPT_order_json] != NULL);
        const char *dir = args->value[VIGEN_OPT_order_plot];
        if (dir && vigen_try_order_plot(dir, &opt, &res, &err) != VIGEN_OK) status = vigen_cli_fail(args->command, &err);
        else if (dir) fprintf(stderr, "vigen order: wrote %s/order.{svg,png,csv}\n", dir);
        vigen_try_order_clear(&res);
    }
    free((char *)opt.params);
    return status;
}
