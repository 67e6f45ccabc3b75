/* expr.c — exact real expressions: a recursive-descent parser to an AST, and
 * evaluation of the AST in arb (real) and acb (complex, for integration) ball
 * arithmetic.  See expr.h for the grammar and the contract.
 *
 * The text is parsed once; evaluation only walks the tree.  Numbers are kept
 * exact (mantissa * 10^exponent, and as an fmpq when the exponent is moderate)
 * and rounded to a ball only at evaluation time, at the requested precision.
 * The exponent of a power is classified once, at parse time: a constant
 * exponent whose value is an exact integer makes x^k an exact integer power;
 * any other exponent means exp(y log x) with x > 0.
 */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq.h>
#include <flint/fmpz_factor.h>
#include <flint/ulong_extras.h>
#include "core/expr.h"

/* Nesting limit: keeps the recursive parser, evaluator and destructor far
 * away from the end of the C stack.  Real expressions nest a few levels. */
#define EXPR_MAX_DEPTH 1000

/* Exact exponents are stored as fmpq when |exponent| <= this (10^4096 needs
 * 1.7 KB); beyond that a number is rounded through an arb power of ten. */
#define EXPR_MAX_FMPQ_EXP 4096

/* Precision at which a constant exponent is evaluated to decide whether it is
 * an exact integer (an exact ball is the exact value, at any precision). */
#define EXPR_EXPONENT_PREC 1024

/* to_arb_poly refuses polynomials of higher degree. */
#define EXPR_MAX_POLY_DEGREE 100000

enum {
    N_NUM, N_PI, N_T,
    N_NEG, N_ADD, N_SUB, N_MUL, N_DIV, N_POW,
    N_SQRT, N_EXP, N_LOG, N_SIN, N_COS, N_TAN
};

typedef struct node {
    int kind;
    int has_t;           /* the subtree depends on t */
    int depth;           /* height of the subtree (a leaf has 1) */
    size_t start, end;   /* source span [start, end) in the text */
    struct node *a, *b;  /* operands (a only for unary nodes and functions) */
    /* N_NUM: value m * 10^e, and q = that value when q_exact */
    fmpz_t m, e;
    fmpq_t q;
    int q_exact;
    /* N_POW: int_exp when the exponent is a constant exact integer k */
    int int_exp;
    fmpz_t k;
} node;

struct vigen_expr {
    char *text;
    node *root;
};

static const struct { const char *name; int kind; } expr_functions[] = {
    { "sqrt", N_SQRT }, { "exp", N_EXP }, { "log", N_LOG },
    { "sin", N_SIN }, { "cos", N_COS }, { "tan", N_TAN }
};
#define EXPR_NFUNCTIONS ((int)(sizeof(expr_functions) / sizeof(expr_functions[0])))
#define EXPR_KNOWN_NAMES "pi, t, sqrt, exp, log, sin, cos, tan"

/* ------------------------------------------------------------------------ */
/* Nodes                                                                      */

static node *node_new(int kind, size_t start, size_t end)
{
    node *n = calloc(1, sizeof(node));
    if (n == NULL) {
        flint_printf("vigen: out of memory\n");
        flint_abort();
    }
    n->kind = kind;
    n->depth = 1;
    n->start = start;
    n->end = end;
    fmpz_init(n->m);
    fmpz_init(n->e);
    fmpq_init(n->q);
    fmpz_init(n->k);
    return n;
}

static void node_free(node *n)
{
    if (n == NULL) return;
    node_free(n->a);
    node_free(n->b);
    fmpz_clear(n->m);
    fmpz_clear(n->e);
    fmpq_clear(n->q);
    fmpz_clear(n->k);
    free(n);
}

/* Links operands into n and sets its derived fields. */
static node *node_link(node *n, node *a, node *b)
{
    n->a = a;
    n->b = b;
    n->has_t = (n->kind == N_T) || (a && a->has_t) || (b && b->has_t);
    int d = 0;
    if (a && a->depth > d) d = a->depth;
    if (b && b->depth > d) d = b->depth;
    n->depth = d + 1;
    return n;
}

/* ------------------------------------------------------------------------ */
/* Evaluation context and error messages                                      */

typedef struct {
    const vigen_expr *e;
    vigen_error *err;      /* may be NULL (internal evaluations) */
    arb_srcptr t;          /* may be NULL */
    slong prec;
} arb_ctx;

/* "<what> in "<text>" at column N", plus ": cannot decide at this precision"
 * when the ball merely fails to decide the question. */
static int domain_error(const arb_ctx *c, const node *n, const char *what, int undecided)
{
    if (c->err == NULL) return VIGEN_E_DOMAIN;
    return vigen_error_set(c->err, VIGEN_E_DOMAIN, "%s in \"%s\" at column %lu%s",
                           what, c->e->text, (unsigned long)(n->start + 1),
                           undecided ? ": cannot decide at this precision" : "");
}

/* ------------------------------------------------------------------------ */
/* Real evaluation                                                            */

static void num_eval_arb(arb_t res, const node *n, slong prec)
{
    if (n->q_exact) {
        arb_set_fmpq(res, n->q, prec);
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
}

static int eval_arb_node(arb_t res, const node *n, const arb_ctx *c)
{
    int rc = VIGEN_OK;
    slong prec = c->prec;
    arb_t y;

    switch (n->kind) {
    case N_NUM:
        num_eval_arb(res, n, prec);
        return VIGEN_OK;
    case N_PI:
        arb_const_pi(res, prec);
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
        rc = eval_arb_node(res, n->a, c);
        arb_neg(res, res);
        return rc;
    default:
        break;
    }

    rc = eval_arb_node(res, n->a, c);
    if (rc != VIGEN_OK) return rc;

    switch (n->kind) {
    case N_ADD: case N_SUB: case N_MUL: case N_DIV:
        arb_init(y);
        rc = eval_arb_node(y, n->b, c);
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
        rc = eval_arb_node(y, n->b, c);
        if (rc == VIGEN_OK) {
            if (!arb_is_positive(res))
                rc = domain_error(c, n, "non-integer power x^y of a value x that is not certainly positive "
                                  "(x^y is exp(y log x) unless y is a constant integer)",
                                  !arb_is_nonpositive(res));
            else arb_pow(res, res, y, prec);
        }
        arb_clear(y);
        break;
    case N_SQRT:
        if (!arb_is_nonnegative(res))
            rc = domain_error(c, n, "sqrt of a value that is not certainly nonnegative",
                              !arb_is_negative(res));
        else arb_sqrt(res, res, prec);
        break;
    case N_LOG:
        if (!arb_is_positive(res))
            rc = domain_error(c, n, "log of a value that is not certainly positive",
                              !arb_is_nonpositive(res));
        else arb_log(res, res, prec);
        break;
    case N_EXP:
        arb_exp(res, res, prec);
        break;
    case N_SIN:
        arb_sin(res, res, prec);
        break;
    case N_COS:
        arb_cos(res, res, prec);
        break;
    case N_TAN:
        arb_tan(res, res, prec);
        if (!arb_is_finite(res))
            rc = domain_error(c, n, "tan at a pole, or too close to one", 1);
        break;
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
    arb_ctx c = { e, err, t, prec };
    int rc;
    if (res == t) {                 /* the result must not overwrite t mid-walk */
        arb_t tmp;
        arb_init(tmp);
        rc = eval_arb_node(tmp, e->root, &c);
        arb_swap(res, tmp);
        arb_clear(tmp);
    } else {
        rc = eval_arb_node(res, e->root, &c);
    }
    if (rc == VIGEN_OK && !arb_is_finite(res)) {
        arb_indeterminate(res);
        rc = domain_error(&c, e->root, "the value is not finite", 0);
    }
    return rc;
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
    case N_PI:
        acb_const_pi(res, prec);
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
    case N_SQRT:
        acb_sqrt_analytic(res, res, c->analytic, prec);
        break;
    case N_LOG:
        acb_log_analytic(res, res, c->analytic, prec);
        break;
    case N_EXP:
        acb_exp(res, res, prec);
        break;
    case N_SIN:
        acb_sin(res, res, prec);
        break;
    case N_COS:
        acb_cos(res, res, prec);
        break;
    case N_TAN:
        acb_tan(res, res, prec);
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
/* Polynomials in t                                                           */

static int poly_node(arb_poly_t res, const node *n, slong prec)
{
    int ok = 0;
    arb_poly_t q;

    if (!n->has_t) {
        arb_t v;
        arb_ctx c = { NULL, NULL, NULL, prec };
        arb_init(v);
        ok = eval_arb_node(v, n, &c) == VIGEN_OK && arb_is_finite(v);
        if (ok) arb_poly_set_arb(res, v);
        arb_clear(v);
        return ok;
    }

    switch (n->kind) {
    case N_T:
        arb_poly_zero(res);
        arb_poly_set_coeff_si(res, 1, 1);
        return 1;
    case N_NEG:
        if (!poly_node(res, n->a, prec)) return 0;
        arb_poly_neg(res, res);
        return 1;
    case N_ADD: case N_SUB: case N_MUL:
        if (!poly_node(res, n->a, prec)) return 0;
        arb_poly_init(q);
        ok = poly_node(q, n->b, prec);
        if (ok) {
            if (n->kind == N_ADD) arb_poly_add(res, res, q, prec);
            else if (n->kind == N_SUB) arb_poly_sub(res, res, q, prec);
            else if (arb_poly_degree(res) + arb_poly_degree(q) > EXPR_MAX_POLY_DEGREE) ok = 0;
            else arb_poly_mul(res, res, q, prec);
        }
        arb_poly_clear(q);
        return ok;
    case N_DIV:
        if (n->b->has_t) return 0;
        if (!poly_node(res, n->a, prec)) return 0;
        {
            arb_t v;
            arb_ctx c = { NULL, NULL, NULL, prec };
            arb_init(v);
            ok = eval_arb_node(v, n->b, &c) == VIGEN_OK && arb_is_finite(v) && !arb_contains_zero(v);
            if (ok) arb_poly_scalar_div(res, res, v, prec);
            arb_clear(v);
        }
        return ok;
    case N_POW:
        if (!n->int_exp || fmpz_sgn(n->k) < 0) return 0;
        if (!poly_node(res, n->a, prec)) return 0;
        {
            slong d = arb_poly_degree(res);
            if (d > 0 && fmpz_cmp_si(n->k, EXPR_MAX_POLY_DEGREE / d) > 0) return 0;
            arb_poly_pow_ui(res, res, fmpz_get_ui(n->k), prec);
        }
        return 1;
    default:
        return 0;    /* functions of t, and t in an exponent or a divisor */
    }
}

int vigen_expr_to_arb_poly(arb_poly_t res, const vigen_expr *e, slong prec)
{
    int ok = poly_node(res, e->root, prec);
    if (!ok) arb_poly_zero(res);
    return ok;
}

/* ------------------------------------------------------------------------ */
/* Closed-form integrals                                                      */

/* res = int_0^x n(t) dt when n is built from polynomials in t, sin, cos and
 * exp of linear arguments a t + b (a != 0), sums, and constant factors or
 * divisors: then the antiderivative is exact and cheap, where rigorous
 * quadrature at thousands of digits is slow.  Returns 0 (res undefined) for
 * anything else. */
static int closed_integral(arb_t res, const node *n, const arb_t x, slong prec)
{
    arb_ctx c = { NULL, NULL, NULL, prec };
    if (!n->has_t) {
        if (eval_arb_node(res, n, &c) != VIGEN_OK || !arb_is_finite(res)) return 0;
        arb_mul(res, res, x, prec);
        return 1;
    }
    arb_poly_t p;
    arb_poly_init(p);
    int ok = 0;
    if (poly_node(p, n, prec)) {
        arb_poly_integral(p, p, prec);
        arb_poly_evaluate(res, p, x, prec);
        arb_poly_clear(p);
        return 1;
    }
    arb_t u, v;
    arb_init(u);
    arb_init(v);
    switch (n->kind) {
    case N_NEG:
        ok = closed_integral(res, n->a, x, prec);
        if (ok) arb_neg(res, res);
        break;
    case N_ADD: case N_SUB:
        ok = closed_integral(u, n->a, x, prec) && closed_integral(v, n->b, x, prec);
        if (ok) {
            if (n->kind == N_ADD) arb_add(res, u, v, prec);
            else arb_sub(res, u, v, prec);
        }
        break;
    case N_MUL: {
        const node *k = n->a->has_t ? n->b : n->a, *f = n->a->has_t ? n->a : n->b;
        if (k->has_t) break;                       /* a product of two functions of t */
        ok = eval_arb_node(u, k, &c) == VIGEN_OK && arb_is_finite(u) && closed_integral(v, f, x, prec);
        if (ok) arb_mul(res, u, v, prec);
        break;
    }
    case N_DIV:
        if (n->b->has_t) break;
        ok = eval_arb_node(u, n->b, &c) == VIGEN_OK && arb_is_finite(u) && !arb_contains_zero(u) &&
             closed_integral(v, n->a, x, prec);
        if (ok) arb_div(res, v, u, prec);
        break;
    case N_SIN: case N_COS: case N_EXP:
        /* f(a t + b): int_0^x = (F(a x + b) - F(b)) / a with F' = f */
        if (!poly_node(p, n->a, prec) || arb_poly_degree(p) != 1) break;
        {
            arb_srcptr b = arb_poly_get_coeff_ptr(p, 0) ? arb_poly_get_coeff_ptr(p, 0) : NULL;
            arb_srcptr a = arb_poly_get_coeff_ptr(p, 1);
            arb_t zero, fx, fb;
            arb_init(zero);
            arb_init(fx);
            arb_init(fb);
            if (b == NULL) b = zero;
            if (!arb_contains_zero(a)) {
                arb_mul(u, a, x, prec);
                arb_add(u, u, b, prec);                    /* a x + b */
                if (n->kind == N_EXP) {
                    arb_exp(fx, u, prec);
                    arb_exp(fb, b, prec);
                    arb_sub(v, fx, fb, prec);              /* exp(ax+b) - exp(b) */
                } else if (n->kind == N_SIN) {
                    arb_cos(fx, u, prec);
                    arb_cos(fb, b, prec);
                    arb_sub(v, fb, fx, prec);              /* -cos(ax+b) + cos(b) */
                } else {
                    arb_sin(fx, u, prec);
                    arb_sin(fb, b, prec);
                    arb_sub(v, fx, fb, prec);              /* sin(ax+b) - sin(b) */
                }
                arb_div(res, v, a, prec);
                ok = arb_is_finite(res);
            }
            arb_clear(zero);
            arb_clear(fx);
            arb_clear(fb);
        }
        break;
    default:
        break;
    }
    arb_clear(u);
    arb_clear(v);
    arb_poly_clear(p);
    return ok;
}

int vigen_expr_integral_closed_form(arb_t res, const vigen_expr *e, const arb_t x, slong prec)
{
    return closed_integral(res, e->root, x, prec);
}

/* ------------------------------------------------------------------------ */
/* Lexer                                                                      */

enum { T_END, T_NUM, T_IDENT, T_OP, T_BAD };

typedef struct {
    int kind;
    size_t start, end;
} token;

typedef struct {
    const char *text;
    size_t pos;           /* next unread byte */
    int allow_t;
    int depth;            /* recursion depth of the descent */
    vigen_error *err;
} parser;

/* Sets a syntax error "<what> at column <pos+1> in "<text>"<tail>".  what and
 * tail are plain strings (tail may be NULL). */
static int syntax_error(parser *p, size_t pos, const char *what, const char *tail)
{
    return vigen_error_set(p->err, VIGEN_E_SYNTAX, "%s at column %lu in \"%s\"%s%s",
                           what, (unsigned long)(pos + 1), p->text,
                           tail ? " " : "", tail ? tail : "");
}

/* Same, with a what that is a heap string (freed here). */
static int syntax_error_owned(parser *p, size_t pos, char *what, char *tail)
{
    syntax_error(p, pos, what, tail);
    free(what);
    free(tail);
    return VIGEN_E_SYNTAX;
}

/* A printable description of one character, for messages. */
static char *describe_char(unsigned char ch)
{
    if (ch >= 0x20 && ch < 0x7f) return vigen_strdup_printf("'%c'", ch);
    return vigen_strdup_printf("byte 0x%02x", (unsigned)ch);
}

static void skip_space(parser *p)
{
    while (p->text[p->pos] != '\0' && isspace((unsigned char)p->text[p->pos])) p->pos++;
}

static int is_ident_start(char ch) { return isalpha((unsigned char)ch) || ch == '_'; }
static int is_ident_char(char ch) { return isalnum((unsigned char)ch) || ch == '_'; }
static int is_digit(char ch) { return ch >= '0' && ch <= '9'; }

static int same_name_ignoring_case(const char *a, const char *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (tolower((unsigned char)a[i]) != tolower((unsigned char)b[i])) return 0;
    return 1;
}

/* Scans a number starting at pos (a digit or '.') into tok.  Returns VIGEN_OK
 * or a syntax error for a malformed number. */
static int scan_number(parser *p, size_t pos, token *tok)
{
    const char *s = p->text;
    size_t i = pos;
    while (is_digit(s[i])) i++;
    if (s[i] == '.') {
        i++;
        if (!is_digit(s[i])) {
            char *what = vigen_strdup_printf("malformed number '%.*s'", (int)(i - pos), s + pos);
            return syntax_error_owned(p, pos, what, vigen_strdup("(expected a digit after the decimal point)"));
        }
        while (is_digit(s[i])) i++;
    }
    if (s[i] == 'e' || s[i] == 'E') {
        size_t j = i + 1;
        if (s[j] == '+' || s[j] == '-') j++;
        if (is_digit(s[j])) {
            while (is_digit(s[j])) j++;
            i = j;
        } else if (s[j] != '\0' && j == i + 1 && is_ident_char(s[j])) {
            /* "2exp(1)": not an exponent; the caller reports the missing '*' */
        } else {
            char *what = vigen_strdup_printf("malformed number '%.*s'", (int)(j - pos), s + pos);
            return syntax_error_owned(p, pos, what, vigen_strdup("(expected digits in the exponent)"));
        }
    }
    if (s[i] == '.') {
        size_t j = i;
        while (is_digit(s[j]) || s[j] == '.' || s[j] == 'e' || s[j] == 'E') j++;
        char *what = vigen_strdup_printf("malformed number '%.*s'", (int)(j - pos), s + pos);
        return syntax_error_owned(p, pos, what, vigen_strdup("(a number has at most one decimal point)"));
    }
    tok->kind = T_NUM;
    tok->start = pos;
    tok->end = i;
    return VIGEN_OK;
}

/* Reads the next token without consuming it. */
static int peek(parser *p, token *tok)
{
    skip_space(p);
    size_t pos = p->pos;
    char ch = p->text[pos];
    tok->start = pos;
    tok->end = pos + 1;
    if (ch == '\0') {
        tok->kind = T_END;
        tok->end = pos;
        return VIGEN_OK;
    }
    if (is_digit(ch) || ch == '.') return scan_number(p, pos, tok);
    if (is_ident_start(ch)) {
        size_t i = pos;
        while (is_ident_char(p->text[i])) i++;
        tok->kind = T_IDENT;
        tok->end = i;
        return VIGEN_OK;
    }
    tok->kind = strchr("+-*/^()", ch) ? T_OP : T_BAD;
    return VIGEN_OK;
}

static int tok_is(const parser *p, const token *tok, char op)
{
    return tok->kind == T_OP && p->text[tok->start] == op;
}

static int tok_is_name(const parser *p, const token *tok, const char *name)
{
    size_t n = strlen(name);
    return tok->kind == T_IDENT && tok->end - tok->start == n && memcmp(p->text + tok->start, name, n) == 0;
}

/* ------------------------------------------------------------------------ */
/* Parser                                                                     */

static int parse_expr(node **out, parser *p);
static int parse_unary(node **out, parser *p);

static int depth_error(parser *p, size_t pos)
{
    char *what = vigen_strdup_printf("expression nested too deeply (more than %d levels)", EXPR_MAX_DEPTH);
    return syntax_error_owned(p, pos, what, NULL);
}

/* Links a binary (or unary) node and enforces the depth limit. */
static int make_node(node **out, parser *p, int kind, size_t start, size_t end, node *a, node *b)
{
    node *n = node_link(node_new(kind, start, end), a, b);
    if (n->depth > EXPR_MAX_DEPTH) {
        node_free(n);
        *out = NULL;
        return depth_error(p, start);
    }
    *out = n;
    return VIGEN_OK;
}

/* Converts the digits of a number token into m * 10^e (and q). */
static void number_value(node *n, const char *s, size_t start, size_t end)
{
    size_t len = end - start, i = start;
    char *digits = malloc(len + 1);
    size_t nd = 0;
    slong frac = 0;
    if (digits == NULL) {
        flint_printf("vigen: out of memory\n");
        flint_abort();
    }
    while (i < end && is_digit(s[i])) digits[nd++] = s[i++];
    if (i < end && s[i] == '.') {
        i++;
        while (i < end && is_digit(s[i])) { digits[nd++] = s[i++]; frac++; }
    }
    digits[nd] = '\0';
    if (nd == 0) fmpz_zero(n->m);
    else fmpz_set_str(n->m, digits, 10);
    fmpz_zero(n->e);
    if (i < end && (s[i] == 'e' || s[i] == 'E')) {
        i++;
        int neg = 0;
        if (s[i] == '+' || s[i] == '-') { neg = (s[i] == '-'); i++; }
        size_t ne = 0;
        while (i < end && is_digit(s[i])) digits[ne++] = s[i++];
        digits[ne] = '\0';
        fmpz_set_str(n->e, digits, 10);
        if (neg) fmpz_neg(n->e, n->e);
    }
    free(digits);
    fmpz_sub_si(n->e, n->e, frac);
    if (fmpz_is_zero(n->m)) fmpz_zero(n->e);

    n->q_exact = fmpz_cmp_si(n->e, EXPR_MAX_FMPQ_EXP) <= 0 && fmpz_cmp_si(n->e, -EXPR_MAX_FMPQ_EXP) >= 0;
    if (n->q_exact) {
        fmpz_t pw, one;
        fmpz_init(pw);
        fmpz_init_set_ui(one, 1);
        fmpz_abs(pw, n->e);
        fmpz_ui_pow_ui(pw, 10, fmpz_get_ui(pw));
        if (fmpz_sgn(n->e) >= 0) {
            fmpz_mul(pw, pw, n->m);
            fmpq_set_fmpz_frac(n->q, pw, one);
        } else {
            fmpq_set_fmpz_frac(n->q, n->m, pw);
        }
        fmpz_clear(pw);
        fmpz_clear(one);
    }
}

/* Decides once whether the constant exponent of a power is an exact integer
 * (evaluating it exactly gives a ball of radius 0 with an integer midpoint). */
static void classify_exponent(node *pw)
{
    const node *y = pw->b;
    pw->int_exp = 0;
    if (y->has_t) return;
    arb_t v;
    arb_ctx c = { NULL, NULL, NULL, EXPR_EXPONENT_PREC };   /* silent: no messages */
    arb_init(v);
    if (eval_arb_node(v, y, &c) == VIGEN_OK && arb_is_int(v)
        && arf_cmpabs_2exp_si(arb_midref(v), 62) < 0) {
        arf_get_fmpz(pw->k, arb_midref(v), ARF_RND_DOWN);
        pw->int_exp = 1;
    }
    arb_clear(v);
}

/* After a complete operand: a number, a name or '(' right after it means a
 * missing operator (implicit multiplication is not supported). */
static int check_missing_operator(parser *p, const node *prev)
{
    token tok;
    int rc = peek(p, &tok);
    if (rc != VIGEN_OK) return rc;
    if (tok.kind != T_NUM && tok.kind != T_IDENT && !tok_is(p, &tok, '(')) return VIGEN_OK;
    char *tail;
    if (tok.kind == T_OP)
        tail = vigen_strdup_printf("(implicit multiplication is not supported: write %.*s*(...))",
                                   (int)(prev->end - prev->start), p->text + prev->start);
    else
        tail = vigen_strdup_printf("(implicit multiplication is not supported: write %.*s*%.*s)",
                                   (int)(prev->end - prev->start), p->text + prev->start,
                                   (int)(tok.end - tok.start), p->text + tok.start);
    return syntax_error_owned(p, tok.start, vigen_strdup("missing operator"), tail);
}

/* Expects ')' closing the '(' at open_pos. */
static int expect_close(parser *p, size_t open_pos)
{
    token tok;
    int rc = peek(p, &tok);
    if (rc != VIGEN_OK) return rc;
    if (tok_is(p, &tok, ')')) {
        p->pos = tok.end;
        return VIGEN_OK;
    }
    if (tok.kind == T_END)
        return syntax_error_owned(p, tok.start, vigen_strdup("unbalanced parentheses: missing ')'"),
                                  vigen_strdup_printf("(to close the '(' at column %lu)", (unsigned long)(open_pos + 1)));
    char *found = tok.kind == T_BAD ? describe_char((unsigned char)p->text[tok.start])
                                    : vigen_strdup_printf("'%.*s'", (int)(tok.end - tok.start), p->text + tok.start);
    char *tail = vigen_strdup_printf("(found %s; the '(' at column %lu is not closed)", found,
                                     (unsigned long)(open_pos + 1));
    free(found);
    return syntax_error_owned(p, tok.start, vigen_strdup("expected ')'"), tail);
}

static int parse_primary(node **out, parser *p)
{
    token tok;
    int rc;
    *out = NULL;
    rc = peek(p, &tok);
    if (rc != VIGEN_OK) return rc;

    switch (tok.kind) {
    case T_END:
        return syntax_error(p, tok.start, "unexpected end of expression", NULL);
    case T_NUM: {
        node *n = node_new(N_NUM, tok.start, tok.end);
        number_value(n, p->text, tok.start, tok.end);
        p->pos = tok.end;
        *out = n;
        return VIGEN_OK;
    }
    case T_IDENT: {
        if (tok_is_name(p, &tok, "pi")) {
            p->pos = tok.end;
            *out = node_new(N_PI, tok.start, tok.end);
            return VIGEN_OK;
        }
        if (tok_is_name(p, &tok, "t")) {
            if (!p->allow_t)
                return syntax_error(p, tok.start, "the variable t is not allowed here (constants only)", NULL);
            p->pos = tok.end;
            *out = node_link(node_new(N_T, tok.start, tok.end), NULL, NULL);
            return VIGEN_OK;
        }
        for (int f = 0; f < EXPR_NFUNCTIONS; f++) {
            if (!tok_is_name(p, &tok, expr_functions[f].name)) continue;
            token open;
            p->pos = tok.end;
            rc = peek(p, &open);
            if (rc != VIGEN_OK) return rc;
            if (!tok_is(p, &open, '(')) {
                char *what = vigen_strdup_printf("expected '(' after the function name '%s'", expr_functions[f].name);
                return syntax_error_owned(p, open.start, what, NULL);
            }
            p->pos = open.end;
            node *arg;
            rc = parse_expr(&arg, p);
            if (rc != VIGEN_OK) return rc;
            rc = expect_close(p, open.start);
            if (rc == VIGEN_OK) rc = make_node(out, p, expr_functions[f].kind, tok.start, p->pos, arg, NULL);
            else node_free(arg);
            return rc;
        }
        /* unknown name: a hint for near misses */
        size_t len = tok.end - tok.start;
        const char *name = p->text + tok.start;
        const char *hint = NULL;
        static const char *known[] = { "pi", "t", "sqrt", "exp", "log", "sin", "cos", "tan" };
        for (size_t i = 0; i < sizeof(known) / sizeof(known[0]); i++)
            if (strlen(known[i]) == len && same_name_ignoring_case(known[i], name, len)) hint = known[i];
        char *what = vigen_strdup_printf("unknown name '%.*s'", (int)len, name);
        char *tail;
        if (hint)
            tail = vigen_strdup_printf("(known: " EXPR_KNOWN_NAMES "; names are case-sensitive: did you mean '%s'?)", hint);
        else if (len == 1 && (name[0] == 'e' || name[0] == 'E'))
            tail = vigen_strdup("(known: " EXPR_KNOWN_NAMES "; write exp(1) for Euler's number)");
        else
            tail = vigen_strdup("(known: " EXPR_KNOWN_NAMES ")");
        return syntax_error_owned(p, tok.start, what, tail);
    }
    case T_OP:
        if (tok_is(p, &tok, '(')) {
            p->pos = tok.end;
            node *inner;
            rc = parse_expr(&inner, p);
            if (rc != VIGEN_OK) return rc;
            rc = expect_close(p, tok.start);
            if (rc != VIGEN_OK) {
                node_free(inner);
                return rc;
            }
            inner->start = tok.start;     /* the span includes the parentheses */
            inner->end = p->pos;
            *out = inner;
            return VIGEN_OK;
        }
        {
            char *what = vigen_strdup_printf("unexpected '%c'", p->text[tok.start]);
            return syntax_error_owned(p, tok.start, what,
                                      vigen_strdup("(expected a number, pi, t, a function or '(')"));
        }
    default: {
        char *c = describe_char((unsigned char)p->text[tok.start]);
        char *what = vigen_strdup_printf("unexpected character %s", c);
        free(c);
        return syntax_error_owned(p, tok.start, what, NULL);
    }
    }
}

/* power := primary ('^' unary)? */
static int parse_power(node **out, parser *p)
{
    node *base, *ex;
    token tok;
    int rc = parse_primary(&base, p);
    if (rc != VIGEN_OK) return rc;
    rc = check_missing_operator(p, base);
    if (rc == VIGEN_OK) rc = peek(p, &tok);
    if (rc != VIGEN_OK) {
        node_free(base);
        return rc;
    }
    if (!tok_is(p, &tok, '^')) {
        *out = base;
        return VIGEN_OK;
    }
    p->pos = tok.end;
    rc = parse_unary(&ex, p);
    if (rc != VIGEN_OK) {
        node_free(base);
        return rc;
    }
    rc = make_node(out, p, N_POW, base->start, ex->end, base, ex);
    if (rc == VIGEN_OK) classify_exponent(*out);
    return rc;
}

/* unary := ('+' | '-') unary | power */
static int parse_unary(node **out, parser *p)
{
    token tok;
    int rc;
    *out = NULL;
    if (++p->depth > EXPR_MAX_DEPTH) return depth_error(p, p->pos);
    rc = peek(p, &tok);
    if (rc == VIGEN_OK) {
        if (tok_is(p, &tok, '+') || tok_is(p, &tok, '-')) {
            node *a;
            p->pos = tok.end;
            rc = parse_unary(&a, p);
            if (rc == VIGEN_OK) {
                if (tok_is(p, &tok, '-')) rc = make_node(out, p, N_NEG, tok.start, a->end, a, NULL);
                else { a->start = tok.start; *out = a; }
            }
        } else {
            rc = parse_power(out, p);
        }
    }
    p->depth--;
    return rc;
}

/* term := unary (('*' | '/') unary)* */
static int parse_term(node **out, parser *p)
{
    node *left, *right;
    token tok;
    int rc = parse_unary(&left, p);
    *out = NULL;
    while (rc == VIGEN_OK) {
        rc = peek(p, &tok);
        if (rc != VIGEN_OK) break;
        if (!tok_is(p, &tok, '*') && !tok_is(p, &tok, '/')) {
            *out = left;
            return VIGEN_OK;
        }
        p->pos = tok.end;
        rc = parse_unary(&right, p);
        if (rc != VIGEN_OK) break;
        rc = make_node(&left, p, tok_is(p, &tok, '*') ? N_MUL : N_DIV, left->start, right->end, left, right);
        if (rc != VIGEN_OK) return rc;     /* make_node freed both operands */
    }
    node_free(left);
    return rc;
}

/* expr := term (('+' | '-') term)* */
static int parse_expr(node **out, parser *p)
{
    node *left = NULL, *right;
    token tok;
    int rc;
    *out = NULL;
    if (++p->depth > EXPR_MAX_DEPTH) return depth_error(p, p->pos);
    rc = parse_term(&left, p);
    while (rc == VIGEN_OK) {
        rc = peek(p, &tok);
        if (rc != VIGEN_OK) break;
        if (!tok_is(p, &tok, '+') && !tok_is(p, &tok, '-')) {
            *out = left;
            left = NULL;
            break;
        }
        p->pos = tok.end;
        rc = parse_term(&right, p);
        if (rc != VIGEN_OK) break;
        rc = make_node(&left, p, tok_is(p, &tok, '+') ? N_ADD : N_SUB, left->start, right->end, left, right);
    }
    node_free(left);
    p->depth--;
    return rc;
}

int vigen_expr_parse(vigen_expr **out, const char *text, int allow_t, vigen_error *err)
{
    *out = NULL;
    if (text == NULL) return vigen_error_set(err, VIGEN_E_SYNTAX, "empty expression (no text given)");

    vigen_expr *e = calloc(1, sizeof(vigen_expr));
    if (e == NULL) return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory parsing \"%s\"", text);
    e->text = vigen_strdup(text);

    parser p = { e->text, 0, allow_t, 0, err };
    token tok;
    int rc;
    size_t i = 0;
    while (text[i] != '\0' && isspace((unsigned char)text[i])) i++;
    if (text[i] == '\0') rc = vigen_error_set(err, VIGEN_E_SYNTAX, "empty expression in \"%s\"", text);
    else rc = parse_expr(&e->root, &p);
    if (rc == VIGEN_OK) rc = peek(&p, &tok);
    if (rc == VIGEN_OK && tok.kind != T_END) {
        if (tok_is(&p, &tok, ')')) {
            rc = syntax_error(&p, tok.start, "unbalanced parentheses: unexpected ')'", NULL);
        } else {
            char *c = describe_char((unsigned char)p.text[tok.start]);
            char *what = vigen_strdup_printf("unexpected %s after the end of the expression", c);
            free(c);
            rc = syntax_error_owned(&p, tok.start, what, NULL);
        }
    }
    if (rc != VIGEN_OK) {
        vigen_expr_free(e);
        return rc;
    }
    *out = e;
    return VIGEN_OK;
}

void vigen_expr_free(vigen_expr *e)
{
    if (e == NULL) return;
    node_free(e->root);
    free(e->text);
    free(e);
}

int vigen_expr_depends_on_t(const vigen_expr *e) { return e->root->has_t; }

const char *vigen_expr_text(const vigen_expr *e) { return e->text; }

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
    arb_ctx c = { NULL, NULL, NULL, 64 };
    if (eval_arb_node(v, n, &c) == VIGEN_OK && arb_is_finite(v) && !arb_contains_zero(v)) {
        /* |v| lies in [2^(e-1), 2^e) up to the ball's tiny radius */
        slong e = fmpz_get_si(ARF_EXPREF(arb_midref(v)));
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

/* ------------------------------------------------------------------------ */
/* Rational and real quadratic values                                         */

/* Sizes beyond which a "rational" expression is not worth treating as one. */
#define EXPR_RAT_MAX_EXP 4096
#define EXPR_RAT_MAX_BITS 65536

/* sqrt(p/q) is reduced to m sqrt(d)/q, d squarefree, by factoring p and q:
 * trial division by the primes below EXPR_QUAD_TRIAL_BOUND, then fmpz_factor
 * on a cofactor of at most EXPR_QUAD_MAX_FACTOR_BITS bits, which it factors
 * at once; a larger cofactor that is not a perfect square is refused rather
 * than factored slowly. */
#define EXPR_QUAD_TRIAL_BOUND 4096
#define EXPR_QUAD_MAX_FACTOR_BITS 64

/* a + b sqrt(d), normalised: d = 1 and b = 0 for a rational, otherwise d > 1
 * squarefree and b != 0, so that the field of a value is read off d. */
typedef struct {
    fmpq_t a, b;
    fmpz_t d;
} quad;

static void quad_init(quad *x)
{
    fmpq_init(x->a);
    fmpq_init(x->b);
    fmpz_init_set_ui(x->d, 1);
}

static void quad_clear(quad *x)
{
    fmpq_clear(x->a);
    fmpq_clear(x->b);
    fmpz_clear(x->d);
}

static void quad_normalise(quad *x)
{
    if (fmpq_is_zero(x->b)) fmpz_one(x->d);
}

static int fmpq_small(const fmpq_t q)
{
    return fmpz_bits(fmpq_numref(q)) <= EXPR_RAT_MAX_BITS && fmpz_bits(fmpq_denref(q)) <= EXPR_RAT_MAX_BITS;
}

static int quad_small(const quad *x) { return fmpq_small(x->a) && fmpq_small(x->b); }

/* The field of x op y: d when both lie in Q(sqrt d) (one may be rational);
 * 0 when they need two different square roots. */
static int quad_field(fmpz_t d, const quad *x, const quad *y)
{
    if (fmpz_is_one(x->d)) fmpz_set(d, y->d);
    else if (fmpz_is_one(y->d) || fmpz_equal(x->d, y->d)) fmpz_set(d, x->d);
    else return 0;
    return 1;
}

/* res = x + sign y (sign = +1 or -1); res may alias x or y. */
static int quad_add(quad *res, const quad *x, const quad *y, int sign)
{
    if (!quad_field(res->d, x, y)) return 0;
    if (sign > 0) {
        fmpq_add(res->a, x->a, y->a);
        fmpq_add(res->b, x->b, y->b);
    } else {
        fmpq_sub(res->a, x->a, y->a);
        fmpq_sub(res->b, x->b, y->b);
    }
    quad_normalise(res);
    return 1;
}

static void quad_swap(quad *x, quad *y)
{
    fmpq_swap(x->a, y->a);
    fmpq_swap(x->b, y->b);
    fmpz_swap(x->d, y->d);
}

/* res = x y = (x_a y_a + d x_b y_b) + (x_a y_b + x_b y_a) sqrt(d); res may alias. */
static int quad_mul(quad *res, const quad *x, const quad *y)
{
    quad r;
    quad_init(&r);
    int ok = quad_field(r.d, x, y);
    if (ok) {
        fmpq_t t;
        fmpq_init(t);
        fmpq_mul(r.a, x->a, y->a);
        fmpq_mul(t, x->b, y->b);
        fmpq_mul_fmpz(t, t, r.d);
        fmpq_add(r.a, r.a, t);
        fmpq_mul(r.b, x->a, y->b);
        fmpq_mul(t, x->b, y->a);
        fmpq_add(r.b, r.b, t);
        fmpq_clear(t);
        quad_normalise(&r);
        quad_swap(res, &r);
    }
    quad_clear(&r);
    return ok;
}

/* x = 1/x = (a - b sqrt d)/(a^2 - d b^2); 0 when x = 0 (the norm vanishes
 * only then, d not being a square). */
static int quad_inv(quad *x)
{
    if (fmpq_is_zero(x->a) && fmpq_is_zero(x->b)) return 0;
    fmpq_t nrm, t;
    fmpq_init(nrm);
    fmpq_init(t);
    fmpq_mul(nrm, x->a, x->a);
    fmpq_mul(t, x->b, x->b);
    fmpq_mul_fmpz(t, t, x->d);
    fmpq_sub(nrm, nrm, t);
    fmpq_div(x->a, x->a, nrm);
    fmpq_div(x->b, x->b, nrm);
    fmpq_neg(x->b, x->b);
    fmpq_clear(nrm);
    fmpq_clear(t);
    return 1;
}

/* m *= p^(e/2), d *= p^(e mod 2): the prime power p^e split into a square
 * and a squarefree part. */
static void square_part_add(fmpz_t m, fmpz_t d, const fmpz_t p, ulong e)
{
    fmpz_t t;
    fmpz_init(t);
    fmpz_pow_ui(t, p, e / 2);
    fmpz_mul(m, m, t);
    if (e % 2) fmpz_mul(d, d, p);
    fmpz_clear(t);
}

/* n = m^2 d with d squarefree, for n > 0.  The primes below
 * EXPR_QUAD_TRIAL_BOUND are divided out (10^60 = 2^60 5^60 is then done);
 * what is left must be a square or small enough to factor at once, else 0. */
static int square_part(fmpz_t m, fmpz_t d, const fmpz_t n)
{
    fmpz_t c, p;
    fmpz_init_set(c, n);
    fmpz_init(p);
    fmpz_one(m);
    fmpz_one(d);
    n_primes_t it;
    n_primes_init(it);
    for (ulong q = n_primes_next(it); q < EXPR_QUAD_TRIAL_BOUND && !fmpz_is_one(c); q = n_primes_next(it)) {
        fmpz_set_ui(p, q);
        slong e = fmpz_remove(c, c, p);
        if (e > 0) square_part_add(m, d, p, (ulong)e);
    }
    n_primes_clear(it);
    int ok = 1;
    fmpz_sqrtrem(p, c, c);   /* p = floor(sqrt(c)), c = the remainder */
    if (fmpz_is_zero(c)) fmpz_mul(m, m, p);
    else {
        fmpz_mul(p, p, p);
        fmpz_add(c, c, p);   /* the cofactor again */
        ok = fmpz_bits(c) <= EXPR_QUAD_MAX_FACTOR_BITS;
        if (ok) {
            fmpz_factor_t f;
            fmpz_factor_init(f);
            fmpz_factor(f, c);
            for (slong i = 0; i < f->num; i++) square_part_add(m, d, f->p + i, f->exp[i]);
            fmpz_factor_clear(f);
        }
    }
    fmpz_clear(c);
    fmpz_clear(p);
    return ok;
}

/* x = sqrt(x) for a rational x = p/q >= 0 in lowest terms: with p = m_p^2 d_p
 * and q = m_q^2 d_q, sqrt(p/q) = sqrt(p q)/q = m_p m_q sqrt(d_p d_q)/q, and
 * d_p d_q is squarefree since p and q are coprime (sqrt(2/3) = sqrt(6)/3;
 * sqrt(2/10^60) = sqrt(2)/10^30, the large q being a square). */
static int quad_sqrt(quad *x)
{
    if (!fmpz_is_one(x->d) || fmpq_sgn(x->a) < 0) return 0;
    if (fmpq_is_zero(x->a)) return 1;
    fmpz_t mp, dp, mq, dq;
    fmpz_init(mp);
    fmpz_init(dp);
    fmpz_init(mq);
    fmpz_init(dq);
    int ok = square_part(mp, dp, fmpq_numref(x->a)) && square_part(mq, dq, fmpq_denref(x->a));
    if (ok) {
        quad r;
        quad_init(&r);
        fmpz_mul(mp, mp, mq);
        fmpq_set_fmpz_frac(r.b, mp, fmpq_denref(x->a));   /* m_p m_q / q */
        fmpz_mul(r.d, dp, dq);
        if (fmpz_is_one(r.d)) fmpq_swap(r.a, r.b);        /* a rational: the value itself */
        quad_swap(x, &r);
        quad_clear(&r);
    }
    fmpz_clear(mp);
    fmpz_clear(dp);
    fmpz_clear(mq);
    fmpz_clear(dq);
    return ok;
}

/* x = x^k by squaring, giving up as soon as a value outgrows the size limits. */
static int quad_pow(quad *x, slong k)
{
    if (k < 0 && !quad_inv(x)) return 0;
    ulong e = k < 0 ? (ulong)(-k) : (ulong)k;
    quad r;
    quad_init(&r);
    fmpq_one(r.a);
    int ok = 1;
    while (e && ok) {
        if (e & 1) ok = quad_mul(&r, &r, x) && quad_small(&r);
        e >>= 1;
        if (e && ok) ok = quad_mul(x, x, x) && quad_small(x);
    }
    if (ok) quad_swap(x, &r);
    quad_clear(&r);
    return ok;
}

/* The value of a constant subtree in Q or one Q(sqrt d); sqrt only when
 * allow_sqrt (otherwise the value must be rational).  0 when it is not such
 * a value, or when it outgrows the size limits. */
static int quad_node(quad *res, const node *n, int allow_sqrt)
{
    quad y;
    int ok = 1;
    switch (n->kind) {
    case N_NUM:
        if (!n->q_exact) return 0;
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
        quad_init(&y);
        ok = quad_node(&y, n->b, allow_sqrt);
        if (ok && n->kind == N_DIV) ok = quad_inv(&y);
        if (ok) ok = n->kind == N_ADD ? quad_add(res, res, &y, 1)
                     : n->kind == N_SUB ? quad_add(res, res, &y, -1)
                                        : quad_mul(res, res, &y);
        quad_clear(&y);
        break;
    case N_POW:
    {
        if (!n->int_exp || !fmpz_fits_si(n->k)) return 0;
        slong k = fmpz_get_si(n->k);
        if (k > EXPR_RAT_MAX_EXP || k < -EXPR_RAT_MAX_EXP || !quad_node(res, n->a, allow_sqrt)) return 0;
        ok = quad_pow(res, k);
        break;
    }
    case N_SQRT:
        if (!allow_sqrt || !quad_node(res, n->a, allow_sqrt)) return 0;
        ok = quad_sqrt(res);
        break;
    default:
        return 0;   /* pi, t, other functions */
    }
    return ok && quad_small(res);
}

int vigen_expr_to_fmpq(fmpq_t res, const vigen_expr *e)
{
    if (e->root->has_t) return 0;
    quad x;
    quad_init(&x);
    int ok = quad_node(&x, e->root, 0);
    if (ok) fmpq_set(res, x.a);
    quad_clear(&x);
    return ok;
}

int vigen_expr_to_quadratic(fmpq_t a, fmpq_t b, fmpz_t d, const vigen_expr *e)
{
    if (e->root->has_t) return 0;
    quad x;
    quad_init(&x);
    int ok = quad_node(&x, e->root, 1);
    if (ok) {
        fmpq_set(a, x.a);
        fmpq_set(b, x.b);
        fmpz_set(d, x.d);
    }
    quad_clear(&x);
    return ok;
}

/* ------------------------------------------------------------------------ */
/* LaTeX                                                                      */

/* Binding strength of a node as LaTeX shows it: sums 1, products 2, unary
 * minus 3, powers 4, atoms (numbers, pi, t, functions, fractions) 5. */
static int latex_rank(const node *n)
{
    switch (n->kind) {
    case N_ADD: case N_SUB: return 1;
    case N_MUL: return 2;
    case N_NEG: return 3;
    case N_POW: return 4;
    default: return 5;
    }
}

static void latex_node(vigen_strbuf *sb, const char *text, const node *n);

static void latex_wrapped(vigen_strbuf *sb, const char *text, const node *n, int min_rank)
{
    if (latex_rank(n) >= min_rank) { latex_node(sb, text, n); return; }
    vigen_strbuf_append(sb, "\\left(");
    latex_node(sb, text, n);
    vigen_strbuf_append(sb, "\\right)");
}

static void latex_node(vigen_strbuf *sb, const char *text, const node *n)
{
    static const char *const fn[] = { "\\sqrt", "\\exp", "\\log", "\\sin", "\\cos", "\\tan" };
    switch (n->kind) {
    case N_NUM: {
        /* the literal as written; an exponent becomes \times 10^{k} */
        const char *a = text + n->start, *z = text + n->end, *e = a;
        while (e < z && *e != 'e' && *e != 'E') e++;
        vigen_strbuf_appendn(sb, a, (size_t)(e - a));
        if (e < z) vigen_strbuf_printf(sb, "\\times 10^{%ld}", strtol(e + 1, NULL, 10));
        break;
    }
    case N_PI: vigen_strbuf_append(sb, "\\pi"); break;
    case N_T: vigen_strbuf_append(sb, "t"); break;
    case N_NEG:
        vigen_strbuf_append(sb, "-");
        latex_wrapped(sb, text, n->a, 2);
        break;
    case N_ADD: case N_SUB:
        latex_node(sb, text, n->a);
        vigen_strbuf_append(sb, n->kind == N_ADD ? " + " : " - ");
        if (n->b->kind == N_NEG) latex_wrapped(sb, text, n->b, 6);   /* a - (-b), not a - -b */
        else latex_wrapped(sb, text, n->b, 2);
        break;
    case N_MUL: {
        latex_wrapped(sb, text, n->a, 2);
        /* 2\pi, 3\sqrt{2}: juxtaposition after a number; \cdot otherwise */
        int juxt = n->a->kind == N_NUM && n->b->kind != N_NUM && latex_rank(n->b) == 5 && n->b->kind != N_DIV;
        vigen_strbuf_append(sb, juxt ? " " : " \\cdot ");
        latex_wrapped(sb, text, n->b, 4);
        break;
    }
    case N_DIV:
        vigen_strbuf_append(sb, "\\frac{");
        latex_node(sb, text, n->a);
        vigen_strbuf_append(sb, "}{");
        latex_node(sb, text, n->b);
        vigen_strbuf_append(sb, "}");
        break;
    case N_POW:
        /* a fraction or a function call as the base gets parentheses too */
        if (latex_rank(n->a) == 5 && (n->a->kind == N_NUM || n->a->kind == N_PI || n->a->kind == N_T))
            latex_node(sb, text, n->a);
        else {
            vigen_strbuf_append(sb, "\\left(");
            latex_node(sb, text, n->a);
            vigen_strbuf_append(sb, "\\right)");
        }
        vigen_strbuf_append(sb, "^{");
        latex_node(sb, text, n->b);
        vigen_strbuf_append(sb, "}");
        break;
    case N_SQRT:
        vigen_strbuf_append(sb, "\\sqrt{");
        latex_node(sb, text, n->a);
        vigen_strbuf_append(sb, "}");
        break;
    default:
        vigen_strbuf_append(sb, fn[n->kind - N_SQRT]);
        vigen_strbuf_append(sb, "\\left(");
        latex_node(sb, text, n->a);
        vigen_strbuf_append(sb, "\\right)");
        break;
    }
}

char *vigen_expr_latex(const vigen_expr *e)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "");
    latex_node(&sb, e->text, e->root);
    return sb.data;
}

int vigen_expr_eval_string(arb_t res, const char *text, slong prec, vigen_error *err)
{
    vigen_expr *e;
    int rc = vigen_expr_parse(&e, text, 0, err);
    if (rc != VIGEN_OK) {
        arb_indeterminate(res);
        return rc;
    }
    rc = vigen_expr_eval_arb(res, e, NULL, prec, err);
    vigen_expr_free(e);
    return rc;
}
