/* prec_limit.c — the process-wide cap on working precision (--max-prec):
 * every place that chooses a precision from a file or an option asks here
 * before computing at it. */
#include "vigen/limits.h"

static long prec_limit = VIGEN_MAX_PREC_DEFAULT;

long vigen_prec_limit(void)
{
    return prec_limit;
}

void vigen_prec_limit_set(long bits)
{
    prec_limit = bits > 0 ? bits : VIGEN_MAX_PREC_DEFAULT;
}

int vigen_prec_limit_check(long prec, const char *what, vigen_error *err)
{
    if (prec <= prec_limit) return VIGEN_OK;
    return vigen_error_set(err, VIGEN_E_LIMIT,
                           "%s %ld bits of working precision, above the cap of %ld bits "
                           "(--max-prec BITS raises it)", what, prec, prec_limit);
}
