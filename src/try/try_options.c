/* try_options.c — the options of `vigen try` and `vigen order` as the command
 * line gives them (texts) made into vigen_try_options, with messages naming
 * the option and what it takes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "try/try_internal.h"
#include "support/strbuf.h"

static int positive(double *out, const char *name, const char *text, vigen_error *err)
{
    char *end = NULL;
    double v = text ? strtod(text, &end) : 0;
    if (text == NULL) return VIGEN_OK;
    if (end == text || *end != '\0' || !isfinite(v) || v <= 0)
        return vigen_error_set(err, VIGEN_E_USAGE, "%s takes a positive number, e.g. %s 0.01, not '%s'", name, name,
                               text);
    *out = v;
    return VIGEN_OK;
}

int vigen_try_options_set(vigen_try_options *opt, const char *problem, const char *params, const char *h,
                          const char *steps_per_period, const char *time, vigen_error *err)
{
    memset(opt, 0, sizeof *opt);
    opt->problem = problem;
    if (params) {
        /* "e=0.9\nn=3" (one --param each) -> "e=0.9,n=3" */
        char *joined = vigen_strdup(params);
        for (char *c = joined; *c; c++)
            if (*c == '\n') *c = ',';
        opt->params = joined;
    }
    int rc = positive(&opt->h, "--h", h, err);
    if (rc == VIGEN_OK) rc = positive(&opt->time, "--time", time, err);
    if (rc == VIGEN_OK && steps_per_period) {
        char *end = NULL;
        long v = strtol(steps_per_period, &end, 10);
        if (end == steps_per_period || *end != '\0' || v < 1 || v > 100000000)
            rc = vigen_error_set(err, VIGEN_E_USAGE,
                                 "--steps-per-period takes a whole number from 1 to 100000000, e.g. "
                                 "--steps-per-period 200, not '%s'", steps_per_period);
        else opt->steps_per_period = v;
    }
    if (rc == VIGEN_OK && h && steps_per_period)
        rc = vigen_error_set(err, VIGEN_E_USAGE, "give --h or --steps-per-period, not both");
    return rc;
}
