/* expr_internal.h — the expression tree shared by the expr_*.c files: node
 * kinds, the node structure, the function table with its per-function
 * hooks, and the real evaluator that the integrator, the parser and the
 * magnitude span reuse.  Nothing outside src/core/expr_*.c includes it. */
#ifndef VIGEN_EXPR_INTERNAL_H
#define VIGEN_EXPR_INTERNAL_H

#include <arb.h>
#include <acb.h>
#include <flint/fmpq.h>
#include "core/expr.h"

enum {
    N_NUM,     /* a number as written */
    N_CONST,   /* a named constant: fn indexes expr_constants */
    N_T,
    N_NEG, N_ADD, N_SUB, N_MUL, N_DIV, N_POW,
    N_FUNC     /* fn(a): fn indexes expr_functions */
};

/* Indices into expr_functions (EXPR_FN_SQRT, ...) and expr_constants (EXPR_CONST_PI). */
enum {
#define X(ID, ...) EXPR_FN_##ID,
#include "core/functions.def"
#undef X
    EXPR_FN_COUNT
};
enum {
#define C(ID, ...) EXPR_CONST_##ID,
#include "core/functions.def"
#undef C
    EXPR_CONST_COUNT
};

typedef struct node {
    int kind;
    int fn;              /* N_FUNC, N_CONST: index into the table */
    int has_t;           /* the subtree depends on t */
    int depth;           /* height of the subtree (a leaf has 1) */
    size_t start, end;   /* source span [start, end) in the text */
    struct node *a, *b;  /* operands (a only for unary nodes and functions) */
    /* N_NUM: value m * 10^e, and q = that value when q_exact */
    fmpz_t m, e;
    fmpq_t q;
    int q_exact;
    /* N_NUM written with a point or an exponent: unit = the exponent of its
     * last digit; rounded: read as the ball of half that unit (tableau
     * entries, vigen_expr_round_decimals) instead of exactly */
    int decimal, rounded;
    fmpz_t unit;
    /* N_POW: int_exp when the exponent is a constant exact integer k */
    int int_exp;
    fmpz_t k;
} node;

struct vigen_expr {
    char *text;
    node *root;
};

/* a + b sqrt(d), normalised: d = 1 and b = 0 for a rational, otherwise d > 1
 * squarefree and b != 0, so that the field of a value is read off d. */
typedef struct {
    fmpq_t a, b;
    fmpz_t d;
} expr_quad;

/* res = f(x) in real balls.  Returns NULL, or, when x is not certainly in the
 * domain, the message (res is then indeterminate) with *undecided set when a
 * narrower ball might decide the question. */
typedef const char *(*expr_arb_fn)(arb_t res, const arb_t x, slong prec, int *undecided);
/* res = f(x) in real balls without a domain check (antiderivatives). */
typedef void (*expr_arb_plain_fn)(arb_t res, const arb_t x, slong prec);
/* x = f(x) in Q or Q(sqrt d); 0 when the value leaves those fields. */
typedef int (*expr_quad_fn)(expr_quad *x);

typedef struct {
    vigen_expr_function pub;        /* name, description, eval_acb, in_ball_library */
    expr_arb_fn eval_arb;
    const char *latex_open, *latex_close;
    expr_arb_plain_fn antiderivative;   /* NULL: no closed-form integral */
    expr_quad_fn exact;                 /* NULL: leaves Q(sqrt d) */
} expr_function;

typedef struct {
    vigen_expr_constant pub;        /* name, description, eval_acb */
    void (*eval_arb)(arb_t res, slong prec);
    const char *latex;
} expr_constant;

extern const expr_function expr_functions[EXPR_FN_COUNT];
extern const expr_constant expr_constants[EXPR_CONST_COUNT];

/* The per-function hooks named in functions.def. */
#define X(ID, NAME, ARB, ACB, LATEX_OPEN, LATEX_CLOSE, ANTIDERIVATIVE, EXACT, BALL, DESCRIPTION) \
    const char *ARB(arb_t res, const arb_t x, slong prec, int *undecided);                       \
    void ACB(acb_t res, const acb_t x, int analytic, slong prec);
#include "core/functions.def"
#undef X
void expr_neg_cos(arb_t res, const arb_t x, slong prec);

/* The arithmetic of Q(sqrt d) (expr_quad.c).  A value starts as 0 (init)
 * and is freed by clear; the operations return 0, leaving the result
 * unspecified, when the value would leave Q and one Q(sqrt d) or outgrow the
 * size limits (small says whether it is within them).  sqrt is also the
 * exact rule of sqrt in functions.def; pow takes any integer exponent. */
void expr_quad_init(expr_quad *x);
void expr_quad_clear(expr_quad *x);
void expr_quad_swap(expr_quad *x, expr_quad *y);
int expr_quad_small(const expr_quad *x);
int expr_quad_add(expr_quad *res, const expr_quad *x, const expr_quad *y, int sign);
int expr_quad_mul(expr_quad *res, const expr_quad *x, const expr_quad *y);
int expr_quad_inv(expr_quad *x);
int expr_quad_pow(expr_quad *x, slong k);
int expr_quad_sqrt(expr_quad *x);

/* Real evaluation of a subtree (expr_eval.c).  err may be NULL: then no
 * message is written (internal evaluations at a fixed precision). */
typedef struct {
    const vigen_expr *e;
    vigen_error *err;
    arb_srcptr t;          /* may be NULL */
    slong prec;
} expr_arb_ctx;

int expr_eval_arb_node(arb_t res, const node *n, const expr_arb_ctx *c);

/* A constant subtree evaluated silently at prec; 0 unless finite. */
int expr_eval_constant(arb_t res, const node *n, slong prec);

#endif
