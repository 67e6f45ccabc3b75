/* audit.c — the audit `vigen emit` runs on every tableau it compiles: the
 * checker on row sums, symplecticity and a claimed order, with a warning for
 * each certain failure; the stepper is written all the same.  Also the order
 * NAME_ORDER carries: the one the checker certifies. */
#include <stdio.h>
#include "vigen/check.h"
#include "vigen/emit.h"

/* The first problem of the report of a kind that certainly fails (diagnosed
 * = 1: the one naming a single entry; 0: a plain failing condition). */
static const vigen_check_failure *first_failing(const vigen_check_report *rep, int kind, int diagnosed)
{
    for (slong k = 0; k < rep->nfailures; k++) {
        const vigen_check_failure *p = rep->failures + k;
        if (p->kind == kind && !p->undecided && p->diagnosed == diagnosed && p->message) return p;
    }
    return NULL;
}

int vigen_emit_audit(vigen_tableau *t, const char *path, int *warnings, vigen_error *err)
{
    *warnings = 0;
    const char *label = path ? path : (t->name ? t->name : "tableau");
    /* NAME_ORDER and the type's order field carry the certified order, which
     * programs print; one claim is certainly false without any evaluation:
     * an s-stage (P)RK method has order at most 2s (its q part alone is an
     * s-stage Runge-Kutta method). */
    if (t->claim_order > 2 * t->s) {
        vigen_warn("%s: the file claims order %d, but a %ld-stage method has order at most %ld; the stepper's order "
                   "field is the certified order: run 'vigen check %s'", label, t->claim_order, (long)t->s,
                   (long)(2 * t->s), label);
        (*warnings)++;
    }
    vigen_check_options copt;
    vigen_check_options_init(&copt);
    /* Row sums and symplecticity do not depend on the order conditions; order
     * 1 is the cheapest level the checker evaluates.  A claim order = p would
     * make it evaluate order p + 1 (up to 12, slow for many stages), and a
     * claim symplectic = true only changes how bt != b is listed: both are
     * set aside for the audit and restored. */
    copt.max_order = 1;
    copt.path = label;
    int claim_order = t->claim_order, claim_symplectic = t->claim_symplectic;
    t->claim_order = -1;
    t->claim_symplectic = -1;
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    int rc = vigen_check_tableau(&rep, t, NULL, &copt, err);
    t->claim_order = claim_order;
    t->claim_symplectic = claim_symplectic;
    if (rc != VIGEN_OK) {
        vigen_check_report_clear(&rep);
        return rc;
    }
    /* Only certain failures are reported: a condition on rounded decimals that
     * holds within the precision of the data, or an undecided one, is no
     * evidence against the tableau. */
    if (rep.consistent == VIGEN_CHECK_NO) {
        const vigen_check_failure *p = first_failing(&rep, VIGEN_CHECK_FAIL_ROWSUM, 0);
        vigen_warn("%s: the tableau is not consistent (%ld of %ld conditions c_i = sum_j a_ij%s, sum b = 1%s fail%s%s)",
                   label, (long)rep.row_fail, (long)rep.row_total, rep.has_ct ? ", ct_i = sum_j at_ij" : "",
                   rep.has_bt ? ", sum bt = 1" : "", p ? "; first: " : "", p ? p->message : "");
        (*warnings)++;
    }
    if (rep.symplectic == VIGEN_CHECK_NO && rep.symplectic_separable == VIGEN_CHECK_YES) {
        vigen_warn("%s: the tableau is symplectic only for separable H = T(p) + V(t, q) (bt != b); "
                   "for other H the stepper is not symplectic", label);
        (*warnings)++;
    } else if (rep.symplectic == VIGEN_CHECK_NO && claim_symplectic != 0) {
        /* (a file that says symplectic = false knows: no warning) */
        const vigen_check_failure *p = first_failing(&rep, VIGEN_CHECK_FAIL_SYMPLECTIC, 0);
        vigen_warn("%s: the tableau is not symplectic (%ld of %ld conditions b_i at_ij + b_j a_ji - b_i b_j = 0%s "
                   "fail%s%s)",
                   label, (long)rep.sym_fail, (long)rep.sym_total, rep.has_bt ? ", bt = b" : "",
                   p ? "; first: " : "", p ? p->message : "");
        (*warnings)++;
    }
    /* A false claim is warned about: NAME_ORDER is the certified order
     * (vigen_emit_certified_order) and may differ from what the file says. */
    if (claim_order >= 0 && claim_order <= 2 * t->s) {
        vigen_check_options oopt;
        vigen_check_options_init(&oopt);
        oopt.max_order = claim_order + 1 <= VIGEN_TREE_MAX_ORDER ? claim_order + 1 : VIGEN_TREE_MAX_ORDER;
        oopt.path = label;
        vigen_check_report orep;
        vigen_check_report_init(&orep);
        vigen_error oerr;
        vigen_error_init(&oerr);
        if (vigen_check_tableau(&orep, t, NULL, &oopt, &oerr) == VIGEN_OK &&
            orep.claim_order_status == VIGEN_CHECK_NO) {
            const vigen_check_level *L = &orep.orders[VIGEN_CHECK_GENERAL].level;
            vigen_warn("%s: the file claims order %d, which is false (%s %d); the stepper's order field is the "
                       "certified order: run 'vigen check %s'", label, claim_order,
                       L->capped ? "the order conditions hold up to order" : "the order is", L->value, label);
            (*warnings)++;
        }
        vigen_error_clear(&oerr);
        vigen_check_report_clear(&orep);
    }
    if (*warnings > 0) {
        const vigen_check_failure *d = first_failing(&rep, VIGEN_CHECK_FAIL_ROWSUM, 1);
        if (d == NULL) d = first_failing(&rep, VIGEN_CHECK_FAIL_SYMPLECTIC, 1);
        if (d) vigen_warn("%s: a misprint? %s", label, d->message);
        vigen_warn("%s: the stepper is emitted as the tableau says; run 'vigen check %s' for details", label, label);
    }
    vigen_check_report_clear(&rep);
    return VIGEN_OK;
}

int vigen_emit_certified_order(const vigen_tableau *t) { return vigen_emit_certified_order_family(t, VIGEN_CHECK_GENERAL); }

int vigen_emit_certified_order_family(const vigen_tableau *t, int family)
{
    vigen_tableau u;
    vigen_tableau_copy(&u, t);
    if (u.claim_order > 2 * u.s) u.claim_order = -1;     /* impossible: not evaluated as a claim */
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    if (u.claim_order + 1 > opt.max_order)
        opt.max_order = u.claim_order + 1 <= VIGEN_TREE_MAX_ORDER ? u.claim_order + 1 : VIGEN_TREE_MAX_ORDER;
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    vigen_error err;
    vigen_error_init(&err);
    int order = -1;
    if (vigen_check_tableau(&rep, &u, NULL, &opt, &err) == VIGEN_OK) {
        int at_least, undecided;
        int p = vigen_check_certified_order(&rep, family, &at_least, &undecided);
        if (!at_least && !undecided) order = p;
        /* bracket flows, which the tableau leaves out: the order of the step's Lie series */
        const vigen_check_generalized *g = rep.generalized;
        if (u.flows != NULL && u.flows->nstep > 0)
            order = g != NULL && g->computed && g->why == NULL && g->classical_state == VIGEN_GEN_DECIDED
                        ? g->classical : -1;
    }
    vigen_error_clear(&err);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&u);
    return order;
}
