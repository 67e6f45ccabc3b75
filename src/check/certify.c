/* certify.c — what the checker certifies about a tableau, as the claims a
 * file states: the order (certified_order.c) and symplecticity, set in the
 * tableau.  Used by `vigen generate`, which records them in the files it
 * writes.  A tableau the generator has just made is decided by Butcher's
 * theorem on its balls where the theorem decides (certify_theorem.c), in a
 * few products per condition; otherwise, or for a tableau read from a file,
 * by `vigen check` on its texts, every tree to order 8. */
#include <stdlib.h>
#include "check/check_internal.h"

/* The claims decided by Butcher's theorem on t's balls (certify_theorem.c):
 * what the tree walk below would record, without it. */
static int certify_by_theorem(vigen_tableau *t)
{
    chk_theorem_verdict v;
    if (!chk_certify_theorem(&v, t)) return 0;
    if (v.order >= 0) {
        if (t->claim_order < 0) t->claim_order = v.order;
        if (t->claim_order_sep < 0) t->claim_order_sep = v.order;
        if (t->claim_order_nys < 0) t->claim_order_nys = v.order;
    }
    if (t->claim_symplectic < 0) t->claim_symplectic = v.symplectic;
    return 1;
}

int vigen_check_certify(vigen_tableau *t, const char *path, vigen_error *err)
{
    /* set VIGEN_CERTIFY_TREES to walk the trees always (to compare the paths) */
    const char *trees = getenv("VIGEN_CERTIFY_TREES");
    /* the generator's balls contain the exact coefficients: the theorem path's data */
    if ((trees == NULL || *trees == '\0' || *trees == '0') && t->generated_now && certify_by_theorem(t))
        return VIGEN_OK;
    vigen_tableau u;
    vigen_tableau_copy(&u, t);
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.path = path;
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    int rc = vigen_check_tableau(&rep, &u, NULL, &opt, err);
    vigen_tableau_clear(&u);
    if (rc == VIGEN_OK) {
        int at_least, undecided;
        int p = vigen_check_certified_order(&rep, VIGEN_CHECK_GENERAL, &at_least, &undecided);
        int decided = !at_least && !undecided;
        if (t->claim_order >= 0 && rep.claim_order_status == VIGEN_CHECK_NO)
            rc = vigen_error_set(err, VIGEN_E_MATH, "%s: the spec claims order %d, but the tableau has %s %d%s%s%s; "
                                 "correct the claim or the spec", path, t->claim_order,
                                 decided ? "order" : "order at least", p,
                                 rep.orders[VIGEN_CHECK_GENERAL].fail_tree ? " (the condition of the tree " : "",
                                 rep.orders[VIGEN_CHECK_GENERAL].fail_tree ? rep.orders[VIGEN_CHECK_GENERAL].fail_tree : "",
                                 rep.orders[VIGEN_CHECK_GENERAL].fail_tree ? " fails)" : "");
        else if (t->claim_order < 0) t->claim_order = decided ? p : -1;
        static const int families[2] = {VIGEN_CHECK_SEPARABLE, VIGEN_CHECK_NYSTROM};
        for (int f = 0; f < 2 && rc == VIGEN_OK; f++) {
            int *claim = f ? &t->claim_order_nys : &t->claim_order_sep;
            int q = vigen_check_certified_order(&rep, families[f], &at_least, &undecided);
            if (*claim < 0 && !at_least && !undecided) *claim = q;
        }
        if (rc == VIGEN_OK && t->claim_symplectic < 0)
            t->claim_symplectic = rep.symplectic == VIGEN_CHECK_YES ? 1 : rep.symplectic == VIGEN_CHECK_NO ? 0 : -1;
    }
    vigen_check_report_clear(&rep);
    return rc;
}
