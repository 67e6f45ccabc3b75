/* refine.c — vigen_check_tableau: the precision loop.  Rounds of every check
 * (checks.c) at doubling precision until the verdicts settle, each run first
 * on the conjugate tableau when the entries are in Q(sqrt d).
 */
#include <stdlib.h>
#include <string.h>
#include "check/check_internal.h"
#include "vigen/limits.h"
#include "support/strbuf.h"

/* Evaluates t at prec (texts), retrying higher on precision-dependent domain
 * errors; a tableau without texts keeps its balls. */
static int evaluate(vigen_tableau *t, slong *prec, slong max_prec, vigen_error *err)
{
    if (!chk_has_texts(t)) {
        if (t->prec <= 0)
            return vigen_error_set(err, VIGEN_E_USAGE, "the tableau has neither entry texts nor evaluated balls");
        return VIGEN_OK;
    }
    for (;;) {
        int rc = vigen_tableau_evaluate(t, *prec, err);
        if (rc == VIGEN_OK) return VIGEN_OK;
        if (rc != VIGEN_E_DOMAIN || 2 * *prec > max_prec) return rc;
        vigen_error_clear(err);
        *prec *= 2;
    }
}

/* The conjugate of a tableau in Q(sqrt d): every entry a + b sqrt(d) becomes
 * a - b sqrt(d) (texts from ex->conj; ct and bt default as in t), with the
 * claims of t.  Evaluate it with vigen_tableau_evaluate. */
static void conj_tableau_init(vigen_tableau *tc, const vigen_tableau *t, const exactness *ex)
{
    slong s = t->s;
    vigen_tableau_init(tc, s);
    tc->has_At = t->has_At;
    tc->has_ct = t->has_At && t->has_ct;
    tc->has_bt = t->has_At && t->has_bt;
    tc->claim_order = t->claim_order;
    tc->claim_symplectic = t->claim_symplectic;
    char ***lists[6] = {&tc->c_text, &tc->b_text, &tc->ct_text, &tc->bt_text, &tc->A_text, &tc->At_text};
    slong lens[6] = {s, s, s, s, s * s, s * s};
    for (int l = 0; l < 6; l++) {
        if (ex->conj[l] == NULL) continue;
        *lists[l] = calloc((size_t)lens[l], sizeof(char *));
        for (slong k = 0; k < lens[l]; k++) (*lists[l])[k] = vigen_strdup(ex->conj[l][k]);
    }
}

/* Runs one round at prec on the conjugate tableau tc, recording in log the
 * conditions decided and the upper bounds of their values there.  Its report
 * is a scratch copy: rep (read for the settings the checks use) is untouched.
 * When tc cannot be evaluated the record stays empty: no proof this round. */
static void conj_record(conj_log *log, const vigen_check_report *rep, vigen_tableau *tc, const exactness *ex,
                        slong prec, int P)
{
    vigen_error err;
    vigen_error_init(&err);
    chk_conj_log_start(log, 1);
    if (vigen_tableau_evaluate(tc, prec, &err) == VIGEN_OK) {
        vigen_check_report scratch;
        vigen_check_report_init(&scratch);
        scratch.s = rep->s;
        scratch.max_order = rep->max_order;
        scratch.has_At = rep->has_At;
        scratch.has_bt = rep->has_bt;
        scratch.has_ct = rep->has_ct;
        scratch.claim_order = rep->claim_order;
        scratch.claim_symplectic = rep->claim_symplectic;
        scratch.rounded_entries = rep->rounded_entries;
        scratch.exact_entries = rep->exact_entries;
        ctx_t cx;
        chk_ctx_init(&cx, tc, ex, scratch.holds);
        cx.prec = prec;
        cx.conj = log;
        cx.conj_recording = 1;
        if (chk_round_run(&scratch, &cx, tc, NULL, NULL, P, &err) != VIGEN_OK) log->n = 0;
        vigen_check_report_clear(&scratch);
    }
    vigen_error_clear(&err);
}

int vigen_check_tableau(vigen_check_report *rep, vigen_tableau *t, vigen_tableau *against,
                        const vigen_check_options *opt_in, vigen_error *err)
{
    vigen_check_options opt;
    if (opt_in) opt = *opt_in;
    else vigen_check_options_init(&opt);
    if (opt.max_order <= 0) opt.max_order = CHK_DEFAULT_MAX_ORDER;
    if (opt.max_prec <= 0) opt.max_prec = CHK_DEFAULT_MAX_PREC;
    if (opt.max_order > VIGEN_TREE_MAX_ORDER)
        return vigen_error_set(err, VIGEN_E_USAGE, "--max-order %d: at most %d is supported", opt.max_order,
                               VIGEN_TREE_MAX_ORDER);

    /* a claim order = p is confirmed by a failing condition of order p + 1 */
    int P = opt.max_order;
    if (t->claim_order >= 0 && t->claim_order + 1 <= VIGEN_TREE_MAX_ORDER && t->claim_order + 1 > P)
        P = t->claim_order + 1;

    free(rep->path);
    free(rep->name);
    rep->path = opt.path ? vigen_strdup(opt.path) : NULL;
    rep->name = t->name ? vigen_strdup(t->name) : NULL;
    rep->s = t->s;
    rep->max_order = P;
    rep->has_At = t->has_At;
    rep->has_bt = t->has_At && t->has_bt;
    rep->has_ct = t->has_At && t->has_ct;
    rep->claim_order = t->claim_order;
    rep->claim_symplectic = t->claim_symplectic;
    rep->claim_order_family[0] = t->claim_order_sep;
    rep->claim_order_family[1] = t->claim_order_nys;

    slong prec = opt.prec > 0 ? opt.prec : chk_adequate_prec(t);
    if (against && opt.prec <= 0 && chk_adequate_prec(against) > prec) prec = chk_adequate_prec(against);
    /* the precision cap of the command (--max-prec) is never passed: not by
     * the precision the literals imply, not by --prec, not by the loop */
    if (vigen_prec_limit_check(prec, opt.prec > 0 ? "--prec asks for" : "the digits of the literals ask for", err))
        return VIGEN_E_LIMIT;
    /* the entries may ask for more than the cap: allow one confirmation above the start */
    slong cap = opt.max_prec > 2 * prec ? opt.max_prec : 2 * prec;
    if (cap > vigen_prec_limit()) cap = vigen_prec_limit();
    int refinable = chk_has_texts(t) || (against && chk_has_texts(against));
    exactness ex, ex_against;
    chk_exactness_init(&ex, t);
    if (against) chk_exactness_init(&ex_against, against);
    rep->rounded_entries = ex.any_rounded;
    rep->exact_entries = ex.any_exact;
    chk_collect_notes(rep, t);
    chk_collect_reducible(rep, t);
    /* the precision at which the data's radii, not the arithmetic, make the
     * balls of conditions on rounded entries: only there is a ball too wide
     * for the rule of rounded data a verdict on the data */
    slong data_prec = chk_adequate_prec(t);
    if (against && chk_adequate_prec(against) > data_prec) data_prec = chk_adequate_prec(against);
    flint_free(rep->rational_denominator);
    flint_free(rep->quadratic_d);
    flint_free(rep->quadratic_denominator);
    rep->rational_denominator = rep->quadratic_d = rep->quadratic_denominator = NULL;
    int quadratic = fmpz_cmp_ui(ex.qd, 1) > 0;
    if (fmpz_is_one(ex.qd)) rep->rational_denominator = fmpz_get_str(NULL, 10, ex.den);
    else if (quadratic) {
        rep->quadratic_d = fmpz_get_str(NULL, 10, ex.qd);
        rep->quadratic_denominator = fmpz_get_str(NULL, 10, ex.den);
    }
    /* entries in Q(sqrt d): each round is run on the conjugate tableau first,
     * for the bounds of the quadratic proof (twice the work, for these only) */
    vigen_tableau conj;
    conj_log log;
    chk_conj_log_init(&log);
    if (quadratic) conj_tableau_init(&conj, t, &ex);
    int rc = VIGEN_OK;
    rep->rounds = 0;
    rep->prec_first = 0;
    ulong last_hash = 0;
    slong last_undecided = -1;
    /* Exact conditions that hold are confirmed only at a round of at least
     * 1024 bits (and 4 times the start), reachable below the cap: a difference
     * such as exp(-200) ~ 2^-288 that no literal reveals hides below a 128- or
     * 256-bit radius, not below a 1024-bit one. */
    slong reachable = prec;
    while (2 * reachable <= cap) reachable *= 2;
    slong min_confirm = 4 * prec > 1024 ? 4 * prec : 1024;
    if (min_confirm > reachable) min_confirm = reachable;

    for (;;) {
        rep->undecided_reason = NULL;
        rc = evaluate(t, &prec, cap, err);
        if (rc == VIGEN_OK && !chk_has_texts(t)) prec = t->prec;
        if (rc == VIGEN_OK && against) {
            slong p2 = prec;
            rc = evaluate(against, &p2, cap, err);
            if (rc != VIGEN_OK) vigen_error_prefix(err, "--against: ");
        }
        if (rc != VIGEN_OK) break;
        rep->rounds++;
        if (rep->prec_first == 0) rep->prec_first = prec;
        rep->prec = prec;

        ctx_t cx;
        chk_ctx_init(&cx, t, &ex, rep->holds);
        cx.prec = prec;
        cx.skip_generalized = !opt.generalized;
        if (quadratic) {
            conj_record(&log, rep, &conj, &ex, prec, P);
            cx.conj = &log;
        }
        rc = chk_round_run(rep, &cx, t, against, against ? &ex_against : NULL, P, err);
        if (rc != VIGEN_OK) break;
        rep->proved = cx.n_proved;

        /* exact conditions that hold with a nonzero radius are confirmed when
         * the previous round, at half the precision, gave the same verdicts,
         * at min_confirm bits or more */
        int confirmed = cx.n_unconfirmed == 0 || (rep->rounds > 1 && cx.hash == last_hash && prec >= min_confirm);
        rep->undecided_left = cx.n_undecided;
        rep->undecided_short = cx.n_undecided_short;
        if (cx.n_undecided == 0 && confirmed) break;
        const char *stop = NULL;
        /* every undecided condition is on rounded data whose radii make its
         * ball too wide: more working precision cannot narrow them */
        int all_short = cx.n_undecided_exact == 0 && cx.n_undecided > 0 && cx.n_undecided == cx.n_undecided_short;
        if (all_short && confirmed && (prec >= data_prec || !refinable || 2 * prec > cap))
            stop = "the data are too short to decide: these conditions involve rounded entries, and their balls "
                   "contain 0 but are wider than 2^-10 of their terms (more working precision cannot narrow the "
                   "radii of the data; exact entries, such as \"1/2\" for \"0.5\", or more digits can)";
        else if (!refinable) stop = "the tableau has no entry texts to re-evaluate";
        else if (2 * prec > cap) stop = "the precision cap was reached";
        else if (cx.n_undecided_exact == 0 && cx.n_undecided > 0 && rep->rounds > 1 &&
                 cx.n_undecided >= last_undecided && confirmed)
            stop = "more precision does not help: the balls of the rounded entries are not finite";
        if (stop) {
            if (!confirmed) {
                /* the holding exact conditions cannot be confirmed: undecided */
                cx.strict = 1;
                cx.n_undecided = cx.n_undecided_exact = cx.n_unconfirmed = 0;
                cx.hash = 1469598103934665603ULL;
                rc = chk_round_run(rep, &cx, t, against, against ? &ex_against : NULL, P, err);
                if (rc != VIGEN_OK) break;
                rep->undecided_left = cx.n_undecided;
                rep->undecided_short = cx.n_undecided_short;
            }
            rep->undecided_reason = stop;
            break;
        }
        last_hash = cx.hash;
        last_undecided = cx.n_undecided;
        prec *= 2;
    }
    if (quadratic) vigen_tableau_clear(&conj);
    chk_conj_log_clear(&log);
    chk_exactness_clear(&ex);
    if (against) chk_exactness_clear(&ex_against);
    if (rc != VIGEN_OK) return rc;

    int code = 0;
    if (rep->consistent != VIGEN_CHECK_YES) code = 1;
    if (rep->claim_order >= 0 && rep->claim_order_status != VIGEN_CHECK_YES) code = 1;
    if (rep->claim_symplectic >= 0 && rep->claim_symplectic_status != VIGEN_CHECK_YES) code = 1;
    for (int f = 0; f < 2; f++)
        if (rep->claim_order_family[f] >= 0 && rep->claim_order_family_status[f] != VIGEN_CHECK_YES) code = 1;
    if (rep->against_differences > 0 || rep->against_undecided > 0) code = 1;
    if (rep->generalized && rep->generalized->claim_status >= 0 && rep->generalized->claim_status != VIGEN_CHECK_YES)
        code = 1;
    rep->exit_code = code;
    return VIGEN_OK;
}

