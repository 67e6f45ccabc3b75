/* expr_functions.c — the elementary functions and constants of exact
 * expressions: the table built from functions.def, each function's real
 * evaluator with its domain check and its complex evaluator with its branch
 * cut, and the name lists for messages and the Lua vocabulary. */
#include "core/expr_internal.h"

const expr_function expr_functions[EXPR_FN_COUNT] = {
#define X(ID, NAME, ARB, ACB, LATEX_OPEN, LATEX_CLOSE, ANTIDERIVATIVE, EXACT, BALL, DESCRIPTION) \
    { { NAME, DESCRIPTION, ACB, BALL }, ARB, LATEX_OPEN, LATEX_CLOSE, ANTIDERIVATIVE, EXACT },
#include "core/functions.def"
#undef X
};

const expr_constant expr_constants[EXPR_CONST_COUNT] = {
#define C(ID, NAME, ARB, ACB, LATEX, DESCRIPTION) { { NAME, DESCRIPTION, ACB }, ARB, LATEX },
#include "core/functions.def"
#undef C
};

/* Built at compile time, each name preceded by ", "; the lists skip the first. */
static const char function_list[] = ""
#define X(ID, NAME, ...) ", " NAME
#include "core/functions.def"
#undef X
    ;
static const char constant_list[] = ""
#define C(ID, NAME, ...) ", " NAME
#include "core/functions.def"
#undef C
    ;

int vigen_expr_function_count(void) { return EXPR_FN_COUNT; }
const vigen_expr_function *vigen_expr_function_at(int i) { return &expr_functions[i].pub; }
int vigen_expr_constant_count(void) { return EXPR_CONST_COUNT; }
const vigen_expr_constant *vigen_expr_constant_at(int i) { return &expr_constants[i].pub; }
const char *vigen_expr_function_names(void) { return function_list + 2; }
const char *vigen_expr_constant_names(void) { return constant_list + 2; }

/* ------------------------------------------------------------------------ */
/* Real evaluators: the domain question is decided on the ball or refused     */

const char *expr_sqrt_arb(arb_t res, const arb_t x, slong prec, int *undecided)
{
    if (!arb_is_nonnegative(x)) {
        *undecided = !arb_is_negative(x);
        return "sqrt of a value that is not certainly nonnegative";
    }
    arb_sqrt(res, x, prec);
    return NULL;
}

const char *expr_log_arb(arb_t res, const arb_t x, slong prec, int *undecided)
{
    if (!arb_is_positive(x)) {
        *undecided = !arb_is_nonpositive(x);
        return "log of a value that is not certainly positive";
    }
    arb_log(res, x, prec);
    return NULL;
}

/* arb_tan gives a non-finite ball on a ball that contains a pole. */
const char *expr_tan_arb(arb_t res, const arb_t x, slong prec, int *undecided)
{
    arb_tan(res, x, prec);
    if (arb_is_finite(res)) return NULL;
    *undecided = 1;
    return "tan at a pole, or too close to one";
}

/* Entire functions: no domain question. */
#define ENTIRE_ARB(NAME, F)                                                  \
    const char *NAME(arb_t res, const arb_t x, slong prec, int *undecided)  \
    {                                                                        \
        (void)undecided;                                                     \
        F(res, x, prec);                                                     \
        return NULL;                                                         \
    }
ENTIRE_ARB(expr_exp_arb, arb_exp)
ENTIRE_ARB(expr_sin_arb, arb_sin)
ENTIRE_ARB(expr_cos_arb, arb_cos)

/* The antiderivative of sin. */
void expr_neg_cos(arb_t res, const arb_t x, slong prec)
{
    arb_cos(res, x, prec);
    arb_neg(res, res);
}

/* ------------------------------------------------------------------------ */
/* Complex evaluators: the analytic variants refuse a ball on a branch cut    */

void expr_sqrt_acb(acb_t res, const acb_t x, int analytic, slong prec) { acb_sqrt_analytic(res, x, analytic, prec); }
void expr_log_acb(acb_t res, const acb_t x, int analytic, slong prec) { acb_log_analytic(res, x, analytic, prec); }

/* Meromorphic without branch cuts: a pole inside x gives an indeterminate ball anyway. */
#define NO_CUT_ACB(NAME, F)                                           \
    void NAME(acb_t res, const acb_t x, int analytic, slong prec)     \
    {                                                                 \
        (void)analytic;                                               \
        F(res, x, prec);                                              \
    }
NO_CUT_ACB(expr_exp_acb, acb_exp)
NO_CUT_ACB(expr_sin_acb, acb_sin)
NO_CUT_ACB(expr_cos_acb, acb_cos)
NO_CUT_ACB(expr_tan_acb, acb_tan)
