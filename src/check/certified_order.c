/* certified_order.c — the order a check report certifies for a family of
 * problems: the enumerated trees, a claim of the file confirmed beyond
 * them, or Butcher's theorem (B, C, D) with the bushy trees that bound it.
 * A reading of a finished report, below the round of checks: the claims
 * check (claims.c) and the certification of a tableau (certify.c) both
 * use it. */
#include "check/check_internal.h"

int vigen_check_certified_order(const vigen_check_report *rep, int family, int *at_least, int *undecided)
{
    const vigen_check_level *L = &rep->orders[family].level;
    *at_least = L->capped;
    *undecided = L->undecided;
    /* a claim of the file confirmed beyond the enumerated trees is the order */
    if (family == VIGEN_CHECK_GENERAL && rep->claim_order >= 0 && rep->claim_order_status == VIGEN_CHECK_YES &&
        !rep->claim_order_separable) {
        *at_least = *undecided = 0;
        return rep->claim_order;
    }
    /* every enumerated order holds: Butcher's theorem (B, C, D) may prove
     * more, for every family, and a failing bushy tree bounds it */
    const vigen_check_theorem *th = &rep->theorem;
    if (L->capped && th->applies && th->order >= L->value) {
        *at_least = th->bushy_fail[family == VIGEN_CHECK_GENERAL ? 0 : 1] != th->order + 1;
        return th->order;
    }
    return L->value;
}
