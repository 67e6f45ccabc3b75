/* expr_eval.c — evaluation of an expression tree in ball arithmetic: real
 * (arb, with domain checks and messages) and complex (acb, for rigorous
 * integration, with branch cuts refused when analytic), the magnitude span
 * of the constant parts, and parse-and-evaluate of a constant string.
 * Every result ball contains the exact value. */
#include "core/expr_internal.h"

/* ------------------------------------------------------------------------ */
/* Error messages                                                             */

/* "<what> in "<text>" at column N", plus ": cannot decide at this precision"
 * when the ball merely fails to decide the question. */
static int domain_error(const expr_arb_ctx *c, const node *n, const char *what, int undecided)
{
    if (c->err == NULL) return VIGEN_E_DOMAIN;
    return vigen_error_set(c->err, VIGEN_E_DOMAIN, "%s in \"%s\" at column %lu%s",
                           what, c->e->text, (unsigned long)(n->start + 1),
                           undecided ? ": cannot decide at this precision" : "");
}

/* ------------------------------------------------------------------------ */
/* Real evaluation                                                            */

/* res += [0 +/- 10^unit / 2]: a rounded decimal literal */
static void add_half_unit(arb_t res, const fmpz_t unit, slong prec)
{
    arb_t r;
    arb_init(r);
    arb_set_ui(r, 10);
    arb_pow_fmpz(r, r, unit, prec);
    arb_mul_2exp_si(r, r, -1);
    arb_add_error(res, r);
    arb_clear(r);
}

static void num_eval_arb(arb_t res, const node *n, slong prec)
{
    if (n->q_exact) {
        arb_set_fmpq(res, n->q, prec);
        if (n->rounded) add_half_unit(res, n->unit, prec);
        return;
    }
    /* m * 10^e with a huge |e|: round 10^|e| and multiply or divide once. */
    arb_t p;
    fmpz_t ae;
    arb_init(p);
    fmpz_init(ae);
    fmpz_abs(ae, n->e);
    arb_set_ui(p, 10);
    arb_pow_fmpz(p, p, ae, prec + 10);
    if (fmpz_sgn(n->e) > 0) {
        arb_mul_fmpz(res, p, n->m, prec);
    } else {
        arb_set_fmpz(res, n->m);          /* exact */
        arb_div(res, res, p, prec);
    }
    fmpz_clear(ae);
    arb_clear(p);
    if (n->rounded) add_half_unit(res, n->unit, prec);
}

int expr_eval_arb_node(arb_t res, const node *n, const expr_arb_ctx *c)
{
    int rc = VIGEN_OK;
    slong prec = c->prec;
    arb_t y;

    switch (n->kind) {
    case N_NUM:
        num_eval_arb(res, n, prec);
        return VIGEN_OK;
    case N_CONST:
        expr_constants[n->fn].eval_arb(res, prec);
        return VIGEN_OK;
    case N_T:
        if (c->t == NULL) {
            arb_indeterminate(res);
            if (c->err == NULL) return VIGEN_E_DOMAIN;
            return vigen_error_set(c->err, VIGEN_E_DOMAIN,
                "the expression \"%s\" depends on t but no value of t was given", c->e->text);
        }
        if (!arb_is_finite(c->t)) {
            arb_indeterminate(res);
            return domain_error(c, n, "the value of t is not finite", 0);
        }
        arb_set(res, c->t);
        return VIGEN_OK;
    case N_NEG:
        rc = expr_eval_arb_node(res, n->a, c);
        arb_neg(res, res);
        return rc;
    default:
        break;
    }

    rc = expr_eval_arb_node(res, n->a, c);
    if (rc != VIGEN_OK) return rc;

    switch (n->kind) {
    case N_ADD: case N_SUB: case N_MUL: case N_DIV:
        arb_init(y);
        rc = expr_eval_arb_node(y, n->b, c);
        if (rc == VIGEN_OK) {
            if (n->kind == N_ADD) arb_add(res, res, y, prec);
            else if (n->kind == N_SUB) arb_sub(res, res, y, prec);
            else if (n->kind == N_MUL) arb_mul(res, res, y, prec);
            else if (arb_contains_zero(y))
                rc = domain_error(c, n, "division by a value that is not certainly nonzero",
                                  !arb_is_zero(y));
            else arb_div(res, res, y, prec);
        }
        arb_clear(y);
        break;
    case N_POW:
        if (n->int_exp) {
            if (fmpz_sgn(n->k) < 0 && arb_contains_zero(res))
                rc = domain_error(c, n, "negative integer power of a value that is not certainly nonzero",
                                  !arb_is_zero(res));
            else arb_pow_fmpz(res, res, n->k, prec);
            break;
        }
        arb_init(y);
        rc = expr_eval_arb_node(y, n->b, c);
        if (rc == VIGEN_OK) {
            if (!arb_is_positive(res))
                rc = domain_error(c, n, "non-integer power x^y of a value x that is not certainly positive "
                                  "(x^y is exp(y log x) unless y is a constant integer)",
                                  !arb_is_nonpositive(res));
            else arb_pow(res, res, y, prec);
        }
        arb_clear(y);
        break;
    case N_FUNC: {
        int undecided = 0;
        const char *why = expr_functions[n->fn].eval_arb(res, res, prec, &undecided);
        if (why != NULL) rc = domain_error(c, n, why, undecided);
        break;
    }
    default:
        arb_indeterminate(res);
        rc = domain_error(c, n, "internal error: unknown expression node", 0);
        break;
    }
    if (rc != VIGEN_OK) arb_indeterminate(res);
    return rc;
}

int vigen_expr_eval_arb(arb_t res, const vigen_expr *e, const arb_t t, slong prec, vigen_error *err)
{
    expr_arb_ctx c = { e, err, t, prec };
    int rc;
    if (res == t) {                 /* the result must not overwrite t mid-walk */
        arb_t tmp;
        arb_init(tmp);
        rc = expr_eval_arb_node(tmp, e->root, &c);
        arb_swap(res, tmp);
        arb_clear(tmp);
    } else {
        rc = expr_eval_arb_node(res, e->root, &c);
    }
    if (rc == VIGEN_OK && !arb_is_finite(res)) {
        arb_indeterminate(res);
        rc = domain_error(&c, e->root, "the value is not finite", 0);
    }
    return rc;
}

int expr_eval_constant(arb_t res, const node *n, slong prec)
{
    expr_arb_ctx c = { NULL, NULL, NULL, prec };
    return expr_eval_arb_node(res, n, &c) == VIGEN_OK && arb_is_finite(res);
}

/* ------------------------------------------------------------------------ */
/* Complex evaluation                                                         */

typedef struct {
    acb_srcptr t;
    int analytic;
    slong prec;
} acb_ctx;

static int eval_acb_node(acb_t res, const node *n, const acb_ctx *c)
{
    int rc = VIGEN_OK;
    slong prec = c->prec;
    acb_t y;

    switch (n->kind) {
    case N_NUM:
        num_eval_arb(acb_realref(res), n, prec);
        arb_zero(acb_imagref(res));
        return VIGEN_OK;
    case N_CONST:
        expr_constants[n->fn].pub.eval_acb(res, prec);
        return VIGEN_OK;
    case N_T:
        if (c->t == NULL) {
            acb_indeterminate(res);
            return VIGEN_E_DOMAIN;
        }
        acb_set(res, c->t);
        return VIGEN_OK;
    default:
        break;
    }

    rc = eval_acb_node(res, n->a, c);
    if (rc != VIGEN_OK) return rc;

    switch (n->kind) {
    case N_NEG:
        acb_neg(res, res);
        break;
    case N_ADD: case N_SUB: case N_MUL: case N_DIV:
        acb_init(y);
        rc = eval_acb_node(y, n->b, c);
        if (n->kind == N_ADD) acb_add(res, res, y, prec);
        else if (n->kind == N_SUB) acb_sub(res, res, y, prec);
        else if (n->kind == N_MUL) acb_mul(res, res, y, prec);
        else acb_div(res, res, y, prec);     /* a ball containing 0 gives indeterminate */
        acb_clear(y);
        break;
    case N_POW:
        if (n->int_exp) {
            acb_pow_fmpz(res, res, n->k, prec);
            break;
        }
        acb_init(y);
        rc = eval_acb_node(y, n->b, c);
        acb_pow_analytic(res, res, y, c->analytic, prec);
        acb_clear(y);
        break;
    case N_FUNC:
        expr_functions[n->fn].pub.eval_acb(res, res, c->analytic, prec);
        break;
    default:
        rc = VIGEN_E_DOMAIN;
        break;
    }
    if (rc != VIGEN_OK) acb_indeterminate(res);
    return rc;
}

int vigen_expr_eval_acb(acb_t res, const vigen_expr *e, const acb_t t, int analytic, slong prec)
{
    acb_ctx c = { t, analytic, prec };
    int rc;
    if (res == t) {
        acb_t tmp;
        acb_init(tmp);
        rc = eval_acb_node(tmp, e->root, &c);
        acb_swap(res, tmp);
        acb_clear(tmp);
    } else {
        rc = eval_acb_node(res, e->root, &c);
    }
    return rc;
}

/* ------------------------------------------------------------------------ */
/* Magnitude span                                                             */

/* Walks the constant subtrees, evaluated at 64 bits, keeping the largest and
 * smallest exponent of a value certainly nonzero. */
static void span_node(const node *n, slong *lo, slong *hi, int *any)
{
    if (n == NULL || n->has_t) {
        if (n) { span_node(n->a, lo, hi, any); span_node(n->b, lo, hi, any); }
        return;
    }
    arb_t v;
    arb_init(v);
    if (expr_eval_constant(v, n, 64) && !arb_contains_zero(v)) {
        /* |v| lies in [2^(e-1), 2^e) up to the ball's tiny radius; e is
         * clamped to +-2^40 (far beyond any precision) so that hi - lo
         * cannot overflow */
        const fmpz *x = ARF_EXPREF(arb_midref(v));
        const slong cap = (slong)1 << 40;
        slong e = fmpz_cmp_si(x, cap) > 0 ? cap : fmpz_cmp_si(x, -cap) < 0 ? -cap : fmpz_get_si(x);
        if (!*any || e < *lo) *lo = e;
        if (!*any || e > *hi) *hi = e;
        *any = 1;
    }
    arb_clear(v);
    span_node(n->a, lo, hi, any);
    span_node(n->b, lo, hi, any);
}

double vigen_expr_magnitude_span_bits(const vigen_expr *e)
{
    slong lo = 0, hi = 0;
    int any = 0;
    span_node(e->root, &lo, &hi, &any);
    return any ? (double)(hi - lo) : 0.0;
}
