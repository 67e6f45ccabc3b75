/* expr_exact.c — exact values of constant expressions in Q and in one real
 * quadratic field Q(sqrt d): the walk that decides whether a tree's value
 * lies in such a field, with the arithmetic of expr_quad.c. */
#include "core/expr_internal.h"

/* Largest power worth raising an exact value to. */
#define EXPR_RAT_MAX_EXP 4096

/* The value of a constant subtree in Q or one Q(sqrt d); the functions with
 * an exact hook in functions.def (sqrt) only when allow_sqrt (otherwise the
 * value must be rational).  0 when it is not such a value, or when it
 * outgrows the size limits. */
static int quad_node(expr_quad *res, const node *n, int allow_sqrt)
{
    expr_quad y;
    int ok = 1;
    switch (n->kind) {
    case N_NUM:
        if (!n->q_exact || n->rounded) return 0;
        fmpq_set(res->a, n->q);
        fmpq_zero(res->b);
        fmpz_one(res->d);
        return 1;
    case N_NEG:
        if (!quad_node(res, n->a, allow_sqrt)) return 0;
        fmpq_neg(res->a, res->a);
        fmpq_neg(res->b, res->b);
        return 1;
    case N_ADD: case N_SUB: case N_MUL: case N_DIV:
        if (!quad_node(res, n->a, allow_sqrt)) return 0;
        expr_quad_init(&y);
        ok = quad_node(&y, n->b, allow_sqrt);
        if (ok && n->kind == N_DIV) ok = expr_quad_inv(&y);
        if (ok) ok = n->kind == N_ADD ? expr_quad_add(res, res, &y, 1)
                     : n->kind == N_SUB ? expr_quad_add(res, res, &y, -1)
                                        : expr_quad_mul(res, res, &y);
        expr_quad_clear(&y);
        break;
    case N_POW:
    {
        if (!n->int_exp || !fmpz_fits_si(n->k)) return 0;
        slong k = fmpz_get_si(n->k);
        if (k > EXPR_RAT_MAX_EXP || k < -EXPR_RAT_MAX_EXP || !quad_node(res, n->a, allow_sqrt)) return 0;
        ok = expr_quad_pow(res, k);
        break;
    }
    case N_FUNC: {
        expr_quad_fn exact = expr_functions[n->fn].exact;
        if (!allow_sqrt || exact == NULL || !quad_node(res, n->a, allow_sqrt)) return 0;
        ok = exact(res);
        break;
    }
    default:
        return 0;   /* constants, t */
    }
    return ok && expr_quad_small(res);
}

int vigen_expr_to_fmpq(fmpq_t res, const vigen_expr *e)
{
    if (e->root->has_t) return 0;
    expr_quad x;
    expr_quad_init(&x);
    int ok = quad_node(&x, e->root, 0);
    if (ok) fmpq_set(res, x.a);
    expr_quad_clear(&x);
    return ok;
}

int vigen_expr_to_quadratic(fmpq_t a, fmpq_t b, fmpz_t d, const vigen_expr *e)
{
    if (e->root->has_t) return 0;
    expr_quad x;
    expr_quad_init(&x);
    int ok = quad_node(&x, e->root, 1);
    if (ok) {
        fmpq_set(a, x.a);
        fmpq_set(b, x.b);
        fmpz_set(d, x.d);
    }
    expr_quad_clear(&x);
    return ok;
}

