/* check_figures.c — what the text and JSON reports of `vigen check` (and
 * `vigen compare`) say of the figures: the family a method is designed for,
 * whose error constant is the method's (docs/analysis.md). */
#include "report/check_figures.h"

const char *const vigen_report_ec_title[VIGEN_CHECK_EC_FAMILIES] = {"general H", "separable H", "Nystrom H"};
const char *const vigen_report_ec_key[VIGEN_CHECK_EC_FAMILIES] = {"general", "separable", "nystrom"};

int vigen_report_higher_family(const vigen_check_report *rep)
{
    static const int fam[3] = {VIGEN_CHECK_GENERAL, VIGEN_CHECK_SEPARABLE, VIGEN_CHECK_NYSTROM};
    const vigen_check_level *g = &rep->orders[VIGEN_CHECK_GENERAL].level;
    if (g->capped) return -1;
    int best = -1, value = g->value;
    for (int f = 1; f < 3; f++) {
        const vigen_check_level *L = &rep->orders[fam[f]].level;
        if (L->value > value) {
            best = f;
            value = L->value;
        }
    }
    return best;
}

int vigen_report_design_family(const vigen_check_report *rep)
{
    int hf = vigen_report_higher_family(rep);
    if (hf >= 0) return hf;   /* VIGEN_CHECK_EC_SEPARABLE or VIGEN_CHECK_EC_NYSTROM */
    /* a splitting method (explicit for separable H only) is made for separable H */
    if (rep->cost.explicit_separable && !rep->cost.explicit_general) return VIGEN_CHECK_EC_SEPARABLE;
    return VIGEN_CHECK_EC_GENERAL;
}
