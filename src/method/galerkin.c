/* galerkin.c — Theorem 3 of Leok & Zhang in ball arithmetic, with a precision
 * loop that stops when every printed digit is certified. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <arb_mat.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include "method/basis.h"
#include "method/galerkin.h"
#include "method/nodes.h"
#include "vigen/limits.h"
#include "support/strbuf.h"

slong vigen_galerkin_initial_prec(slong digits, slong s)
{
    /* digits * log2(10) plus guard bits for the cancellation in M^-1 and in
     * the Lagrange polynomials, which grows with s. */
    return (slong)ceil((double)digits * 3.3219280948873623) + 64 + 4 * s;
}

slong vigen_galerkin_max_prec(slong digits, slong s)
{
    return 8 * vigen_galerkin_initial_prec(digits, s) + 4096;
}

static char *ball_text(const arb_t x)
{
    char *t = arb_get_str(x, 20, 0);
    char *copy = vigen_strdup(t);
    flint_free(t);
    return copy;
}

/* Nodes of the spec at precision prec, checked: finite, real, distinct. */
static int compute_nodes(arb_ptr c, vigen_spec *spec, slong prec, vigen_error *err)
{
    slong s = spec->s;
    if (spec->nodes_kind == VIGEN_SPEC_NODES_FAMILY) {
        int rc = vigen_nodes_family(c, spec->node_family, s, prec, err);
        if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s: nodes: ", spec->path);
    } else {
        for (slong i = 0; i < s; i++) {
            int rc = vigen_expr_eval_arb(c + i, spec->node_exprs[i], NULL, prec, err);
            if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s: nodes[%ld]: ", spec->path, (long)(i + 1));
            if (!arb_is_finite(c + i))
                return vigen_error_set(err, VIGEN_E_DOMAIN, "%s: nodes[%ld] = \"%s\" is not finite", spec->path,
                                       (long)(i + 1), vigen_expr_text(spec->node_exprs[i]));
        }
    }
    for (slong i = 0; i < s; i++)
        for (slong j = i + 1; j < s; j++) {
            if (!arb_overlaps(c + i, c + j)) continue;
            if (arb_is_exact(c + i) && arb_equal(c + i, c + j)) {
                char *v = ball_text(c + i);
                int code = vigen_error_set(err, VIGEN_E_MATH, "%s: nodes[%ld] and nodes[%ld] are equal (%s); the nodes "
                                           "must be distinct (M = [psi_i(c_j)] would be singular)",
                                           spec->path, (long)(i + 1), (long)(j + 1), v);
                free(v);
                return code;
            }
            return vigen_error_set(err, VIGEN_E_PRECISION, "%s: nodes[%ld] and nodes[%ld] cannot be told apart at "
                                   "%ld bits: they are equal or extremely close; the nodes must be distinct",
                                   spec->path, (long)(i + 1), (long)(j + 1), (long)prec);
        }
    return VIGEN_OK;
}

/* Explains a singular M from its midpoints: a left null vector y (y^T M = 0)
 * says which combination of basis functions vanishes at every node.  Returns 1
 * and sets err when M is numerically singular (condition number > 1e13). */
static int diagnose_singular(const arb_mat_t M, vigen_basis *basis, vigen_spec *spec, vigen_error *err)
{
    slong s = arb_mat_nrows(M);
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    gsl_matrix *U = gsl_matrix_alloc((size_t)s, (size_t)s); /* holds M^T: its right null vector is y */
    gsl_matrix *V = gsl_matrix_alloc((size_t)s, (size_t)s);
    gsl_vector *S = gsl_vector_alloc((size_t)s), *work = gsl_vector_alloc((size_t)s);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++)
            gsl_matrix_set(U, (size_t)j, (size_t)i, arf_get_d(arb_midref(arb_mat_entry(M, i, j)), ARF_RND_NEAR));
    int singular = 0;
    if (gsl_linalg_SV_decomp(U, V, S, work) == GSL_SUCCESS) {
        double smax = gsl_vector_get(S, 0), smin = gsl_vector_get(S, (size_t)s - 1);
        if (!(smin > 1e-13 * smax)) {
            singular = 1;
            /* y = last column of V, scaled so that its largest entry is 1 */
            double big = 0;
            for (slong i = 0; i < s; i++) big = fmax(big, fabs(gsl_matrix_get(V, (size_t)i, (size_t)s - 1)));
            vigen_strbuf sb;
            vigen_strbuf_init(&sb);
            int terms = 0;
            for (slong i = 0; i < s; i++) {
                double y = gsl_matrix_get(V, (size_t)i, (size_t)s - 1) / big;
                if (fabs(y) < 1e-9) continue;
                vigen_strbuf_printf(&sb, "%s%.6g*psi_%ld", terms ? " + " : "", y, (long)(i + 1));
                vigen_strbuf_printf(&sb, " [%s]", vigen_basis_label(basis, i));
                terms++;
            }
            vigen_error_set(err, VIGEN_E_MATH,
                            "%s: M = [psi_i(c_j)] is singular (condition number above 1e13): the combination %s "
                            "vanishes at every node; choose other nodes or basis functions",
                            spec->path, sb.data ? sb.data : "?");
            vigen_strbuf_clear(&sb);
        }
    }
    gsl_matrix_free(U);
    gsl_matrix_free(V);
    gsl_vector_free(S);
    gsl_vector_free(work);
    gsl_set_error_handler(old);
    return singular;
}

static void fill_metadata(vigen_tableau *t, const vigen_spec *spec)
{
    t->name = vigen_strdup(spec->name);
    t->description = vigen_strdup(spec->description);
    t->source = vigen_strdup(spec->source);
    /* the spec's `basis = "lagrange"` is recorded as the word, not a quoted string */
    t->basis = vigen_strdup(spec->basis_text && strcmp(spec->basis_text, "\"lagrange\"") == 0 ? "lagrange"
                                                                                             : spec->basis_text);
    t->nodes = vigen_strdup(spec->nodes_text);
    t->generator = vigen_strdup("vigen " VIGEN_VERSION);
    t->claim_order = spec->claim_order;
    t->generated_now = 1;
    t->has_At = 1;
    t->has_ct = 1;
}

static int compute(vigen_tableau *t, vigen_spec *spec, slong prec, int last_attempt, vigen_error *err)
{
    slong s = spec->s;
    vigen_tableau_init(t, s);
    fill_metadata(t, spec);
    t->prec = prec;
    if (spec->basis_count != s)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: basis has %ld functions but nodes has %ld entries; Theorem 3 needs "
                               "one node per basis function", spec->path, (long)spec->basis_count, (long)s);

    int rc = compute_nodes(t->c, spec, prec, err);
    if (rc != VIGEN_OK) return rc;

    vigen_basis *basis = NULL;
    rc = vigen_basis_new(&basis, spec, t->c, prec, err);
    if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s: basis: ", spec->path);

    arb_mat_t M, rhs, X;
    arb_mat_init(M, s, s);
    arb_mat_init(rhs, s, s + 1); /* [B | Apsi^T] */
    arb_mat_init(X, s, s + 1);
    arb_t tmp, one;
    arb_init(tmp);
    arb_init(one);
    arb_one(one);

    /* M_ij = psi_i(c_j), B_i = int_0^1 psi_i, (Apsi^T)_ji = int_0^c_i psi_j */
    for (slong i = 0; i < s && rc == VIGEN_OK; i++) {
        if (!vigen_basis_is_interpolating(basis))
            for (slong j = 0; j < s && rc == VIGEN_OK; j++)
                rc = vigen_basis_value(arb_mat_entry(M, i, j), basis, i, t->c + j, prec, err);
        if (rc == VIGEN_OK) rc = vigen_basis_integral(arb_mat_entry(rhs, i, 0), basis, i, one, prec, err);
        for (slong j = 0; j < s && rc == VIGEN_OK; j++)
            rc = vigen_basis_integral(arb_mat_entry(rhs, i, j + 1), basis, i, t->c + j, prec, err);
        /* messages from Lua basis functions already name the file and entry */
        if (rc != VIGEN_OK && (err->message == NULL || strncmp(err->message, spec->path, strlen(spec->path)) != 0))
            vigen_error_prefix(err, "%s: basis[%ld]: ", spec->path, (long)(i + 1));
    }

    /* X = M^-1 [B | Apsi^T]: column 0 is b, columns 1..s are the rows of A */
    if (rc == VIGEN_OK) {
        if (vigen_basis_is_interpolating(basis)) arb_mat_set(X, rhs);
        else if (!arb_mat_solve(X, M, rhs, prec)) {
            if (!diagnose_singular(M, basis, spec, err))
                rc = vigen_error_set(err, VIGEN_E_PRECISION, "%s: M = [psi_i(c_j)] could not be inverted at %ld bits",
                                     spec->path, (long)prec);
            else rc = err->code;
        }
    }
    if (rc == VIGEN_OK) {
        for (slong i = 0; i < s; i++) {
            arb_set(t->b + i, arb_mat_entry(X, i, 0));
            for (slong j = 0; j < s; j++) arb_set(arb_mat_entry(t->A, i, j), arb_mat_entry(X, j, i + 1));
        }
        /* structural exactness: c_i = 0 gives a_ij = 0; c_i = 1 gives a_ij = int_0^1 phi_j = b_j */
        for (slong i = 0; i < s; i++) {
            if (arb_is_zero(t->c + i))
                for (slong j = 0; j < s; j++) arb_zero(arb_mat_entry(t->A, i, j));
            if (arb_is_one(t->c + i))
                for (slong j = 0; j < s; j++) arb_set(arb_mat_entry(t->A, i, j), t->b + j);
        }
        /* Theorem 3 divides by b_i.  A ball around 0 may still separate at a
         * higher precision (b_i = 1e-70 is legal): only the last attempt,
         * at the precision cap, concludes that b_i vanishes. */
        for (slong i = 0; i < s && rc == VIGEN_OK; i++) {
            if (!arb_contains_zero(t->b + i)) continue;
            char *cv = ball_text(t->c + i);
            arf_t u;
            arf_init(u);
            arb_get_abs_ubound_arf(u, t->b + i, 30);
            slong ex = arf_is_zero(u) ? -prec : arf_abs_bound_lt_2exp_si(u);   /* |b_i| < 2^ex */
            arf_clear(u);
            if (arb_is_zero(t->b + i) || last_attempt)
                rc = vigen_error_set(err, VIGEN_E_MATH, "%s: b_%ld = 0 (|b_%ld| < 2^%ld, certified at %ld bits) for "
                                     "node c_%ld = %s: the quadrature weight of this node vanishes and Theorem 3 "
                                     "divides by b_i; choose other nodes or basis functions", spec->path,
                                     (long)(i + 1), (long)(i + 1), (long)ex, (long)prec, (long)(i + 1), cv);
            else
                rc = vigen_error_set(err, VIGEN_E_PRECISION, "%s: b_%ld cannot be separated from 0 at %ld bits",
                                     spec->path, (long)(i + 1), (long)prec);
            free(cv);
        }
    }
    if (rc == VIGEN_OK) {
        /* at_ij = b_j (b_i - a_ji) / b_i, exactly 0 when c_j = 1 and exactly b_j when c_j = 0 */
        for (slong i = 0; i < s; i++)
            for (slong j = 0; j < s; j++) {
                arb_ptr at = arb_mat_entry(t->At, i, j);
                if (arb_is_one(t->c + j)) arb_zero(at);
                else if (arb_is_zero(t->c + j)) arb_set(at, t->b + j);
                else {
                    arb_sub(tmp, t->b + i, arb_mat_entry(t->A, j, i), prec);
                    arb_mul(tmp, tmp, t->b + j, prec);
                    arb_div(at, tmp, t->b + i, prec);
                }
            }
        for (slong i = 0; i < s; i++) {
            arb_zero(t->ct + i);
            for (slong j = 0; j < s; j++) arb_add(t->ct + i, t->ct + i, arb_mat_entry(t->At, i, j), prec);
        }
        _arb_vec_set(t->bt, t->b, s);
        for (slong i = 0; i < s && rc == VIGEN_OK; i++)
            if (!arb_is_finite(t->b + i) || !arb_is_finite(t->ct + i))
                rc = vigen_error_set(err, VIGEN_E_PRECISION, "non-finite entries at %ld bits", (long)prec);
    }

    arb_clear(tmp);
    arb_clear(one);
    arb_mat_clear(M);
    arb_mat_clear(rhs);
    arb_mat_clear(X);
    vigen_basis_free(basis);
    return rc;
}

int vigen_galerkin_compute(vigen_tableau *t, vigen_spec *spec, slong prec, vigen_error *err)
{
    return compute(t, spec, prec, 0, err);
}

/* Warnings that do not stop generation: nodes outside [0, 1] and sum b != 1
 * (the constants are not in span(psi): the method is not even consistent). */
static void warn_about(const vigen_tableau *t, const vigen_spec *spec)
{
    slong s = t->s;
    arb_t one, sum;
    arb_init(one);
    arb_init(sum);
    arb_one(one);
    for (slong i = 0; i < s; i++)
        if (arb_is_negative(t->c + i) || arb_gt(t->c + i, one)) {
            char *v = ball_text(t->c + i);
            vigen_warn("%s: node c_%ld = %s lies outside [0, 1]", spec->path, (long)(i + 1), v);
            free(v);
        }
    /* c_i = sum_j a_ij holds exactly when the constants are in the span; warn
     * about each row that certainly differs (vigen check would flag it) */
    for (slong i = 0; i < s; i++) {
        arb_zero(sum);
        for (slong j = 0; j < s; j++) arb_add(sum, sum, arb_mat_entry(t->A, i, j), t->prec);
        if (!arb_overlaps(sum, t->c + i)) {
            char *v = ball_text(sum), *c = ball_text(t->c + i);
            vigen_warn("%s: row %ld of A sums to %s, not to its node c_%ld = %s: the constant function is not in "
                       "the span of the basis (vigen check will report the row sums)", spec->path, (long)(i + 1), v,
                       (long)(i + 1), c);
            free(v);
            free(c);
        }
    }
    arb_zero(sum);
    for (slong i = 0; i < s; i++) arb_add(sum, sum, t->b + i, t->prec);
    if (!arb_contains(sum, one)) {
        char *v = ball_text(sum);
        vigen_warn("%s: sum of b = %s differs from 1: the constant function is not in the span of the basis, so "
                   "the method is not consistent (not even first order); include psi = 1 in the basis",
                   spec->path, v);
        free(v);
    }
    arb_clear(one);
    arb_clear(sum);
}

int vigen_galerkin_generate(vigen_tableau *out, vigen_spec *spec, slong digits, vigen_error *err)
{
    if (digits < 1 || digits > 100000)
        return vigen_error_set(err, VIGEN_E_USAGE, "--digits must be between 1 and 100000 (got %ld)", (long)digits);
    slong prec = vigen_galerkin_initial_prec(digits, spec->s);
    slong max_prec = vigen_galerkin_max_prec(digits, spec->s);
    /* the precision cap of the command (--max-prec) bounds both */
    char *what = vigen_strdup_printf("%s: %ld certified digits of %ld stages ask for", spec->path, (long)digits,
                                     (long)spec->s);
    int rc0 = vigen_prec_limit_check(prec, what, err);
    free(what);
    if (rc0 != VIGEN_OK) return rc0;
    int capped = max_prec > vigen_prec_limit();
    if (capped) max_prec = vigen_prec_limit();
    int integral_failures = 0;
    for (;;) {
        vigen_error_clear(err);
        int rc = compute(out, spec, prec, prec >= max_prec, err);
        if (rc == VIGEN_OK) rc = vigen_tableau_texts_from_balls(out, digits, err);
        if (rc == VIGEN_OK) break;
        vigen_tableau_clear(out);
        if (rc == VIGEN_E_INTEGRAL) {
            /* acb_calc_integrate converges for functions analytic near the
             * interval; failing at two precisions means it is not */
            if (++integral_failures >= 2) {
                char *why = vigen_strdup(err->message ? err->message : "");
                vigen_error_set(err, VIGEN_E_DOMAIN, "%s at %ld bits nor at the precision before: the basis function "
                                "has a singularity, a branch point or complex values on or near the interval; "
                                "vigen integrates only functions analytic on a neighbourhood of [0, 1]",
                                why, (long)prec);
                free(why);
                return VIGEN_E_DOMAIN;
            }
            rc = VIGEN_E_PRECISION;
        }
        if (rc != VIGEN_E_PRECISION) return rc;
        if (prec >= max_prec && capped) {
            char *why = vigen_strdup(err->message ? err->message : "");
            vigen_error_set(err, VIGEN_E_LIMIT, "%s (gave up certifying %ld digits at %ld bits, the precision cap: "
                            "--max-prec BITS raises it)", why, (long)digits, (long)prec);
            free(why);
            return VIGEN_E_LIMIT;
        }
        if (prec >= max_prec) {
            char *why = vigen_strdup(err->message ? err->message : "");
            vigen_error_set(err, VIGEN_E_PRECISION, "%s (gave up certifying %ld digits at %ld bits, the cap)", why,
                            (long)digits, (long)prec);
            free(why);
            return VIGEN_E_PRECISION;
        }
        prec = prec * 2 > max_prec ? max_prec : prec * 2;
    }
    warn_about(out, spec);
    return VIGEN_OK;
}
