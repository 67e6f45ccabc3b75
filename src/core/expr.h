/* expr.h — exact real expressions: the one parser for nodes, basis functions
 * and tableau entries, and the table of elementary functions they may use.
 *
 * Grammar (whitespace ignored):
 *   expr    := term (('+' | '-') term)*
 *   term    := unary (('*' | '/') unary)*
 *   unary   := ('+' | '-') unary | power
 *   power   := primary ('^' unary)?            -- right associative: 2^-1, 2^3^2 = 2^9
 *   primary := number | 'pi' | 't' | func '(' expr ')' | '(' expr ')'
 *   number  := digits ['.' digits] [('e'|'E') ['+'|'-'] digits]  |  '.' digits [...]
 *   func    := sqrt | exp | log | sin | cos | tan     -- the rows of functions.def
 * Numbers are exact: "0.1" is 1/10, "2.5e-3" is 1/400 (tableau entries read
 * their decimals rounded instead: vigen_expr_round_decimals).  Identifiers other than
 * pi, t and the functions are errors.  The variable t is allowed only when the
 * caller says so (basis functions); nodes and tableau entries are constants.
 * Powers: an exponent that is an exact integer (after evaluation of a constant
 * subexpression) is computed exactly (x^-2 = 1/x^2); otherwise x^y = exp(y log x)
 * and requires x > 0.
 *
 * Evaluation is in ball arithmetic: every result ball contains the exact value.
 * A domain error (log of a non-positive number, division by a ball containing 0,
 * sqrt of a negative number) or a non-finite result is reported, never guessed.
 */
#ifndef VIGEN_EXPR_H
#define VIGEN_EXPR_H

#include <arb.h>
#include <acb.h>
#include <arb_poly.h>
#include <flint/fmpq.h>
#include "vigen/error.h"

typedef struct vigen_expr vigen_expr;

/* An elementary function of the grammar (a row of functions.def), as the Lua
 * ball library and messages see it. */
typedef struct {
    const char *name;          /* "sqrt" */
    const char *description;   /* one line, for documentation */
    /* res = f(x); with analytic set, indeterminate unless f is certainly
     * holomorphic on the ball x (branch cuts), for acb_calc_integrate */
    void (*eval_acb)(acb_t res, const acb_t x, int analytic, slong prec);
    int in_ball_library;       /* offered as ball.NAME and as a global in spec files */
} vigen_expr_function;

/* A named constant of the grammar ("pi"). */
typedef struct {
    const char *name;
    const char *description;
    void (*eval_acb)(acb_t res, slong prec);
} vigen_expr_constant;

int vigen_expr_function_count(void);
const vigen_expr_function *vigen_expr_function_at(int i);    /* 0 <= i < count */
int vigen_expr_constant_count(void);
const vigen_expr_constant *vigen_expr_constant_at(int i);
/* The names in table order, comma-separated: "sqrt, exp, log, sin, cos, tan"
 * and "pi".  Static strings. */
const char *vigen_expr_function_names(void);
const char *vigen_expr_constant_names(void);

/* Parses text.  allow_t: whether the variable t may appear.  On error returns
 * VIGEN_E_SYNTAX with a message that quotes the text and names the column, e.g.
 *   unknown name 'cosh' at column 1 in "cosh(t)" (known: pi, t, sqrt, exp, log, sin, cos, tan) */
int vigen_expr_parse(vigen_expr **out, const char *text, int allow_t, vigen_error *err);
void vigen_expr_free(vigen_expr *e);

int vigen_expr_depends_on_t(const vigen_expr *e);

/* Decimal literals: numbers written with a point or an exponent ("0.5",
 * "2e-3").  vigen_expr_round_decimals makes every later evaluation read each
 * of them as the ball of half a unit in its last digit ("0.5" is 0.5 +/-
 * 0.05), as a bare decimal tableau entry is read, and the exact conversions
 * (vigen_expr_to_fmpq, _to_quadratic) then decline the expression; it
 * returns the number of decimal literals.  vigen_expr_shortest_decimal: the
 * literal with the fewest significant digits, a fresh string, or NULL when
 * there is none; vigen_expr_longest_decimal_digits: the most significant
 * digits of a literal (0 without one). */
int vigen_expr_round_decimals(vigen_expr *e);
int vigen_expr_decimal_count(const vigen_expr *e);
char *vigen_expr_shortest_decimal(const vigen_expr *e);
slong vigen_expr_longest_decimal_digits(const vigen_expr *e);
const char *vigen_expr_text(const vigen_expr *e);   /* the text it was parsed from */

/* Real evaluation; t may be NULL when the expression has no t.  Returns VIGEN_OK,
 * or VIGEN_E_DOMAIN with a message (the result is then indeterminate).  A ball
 * that merely fails to decide a domain question at this precision (e.g. log of
 * [0 +/- 1e-30]) is also VIGEN_E_DOMAIN; callers retry at higher precision. */
int vigen_expr_eval_arb(arb_t res, const vigen_expr *e, const arb_t t, slong prec, vigen_error *err);

/* Complex evaluation for rigorous integration (acb_calc_integrate).  When
 * analytic is nonzero the result must be indeterminate (acb_indeterminate)
 * unless the expression is certainly holomorphic on the ball t: branch cuts are
 * handled with acb_sqrt_analytic, acb_log_analytic, and x^y for non-integer y as
 * exp(y log_analytic(x)).  Returns VIGEN_OK, or VIGEN_E_DOMAIN for an error that
 * no refinement can fix (none in the current grammar; reserved). */
int vigen_expr_eval_acb(acb_t res, const vigen_expr *e, const acb_t t, int analytic, slong prec);

/* If e is a polynomial in t whose coefficients are constant expressions (only
 * + - *, division by a constant, t^k for constant non-negative integer k),
 * writes it to res (coefficients as balls at prec) and returns 1; else 0. */
int vigen_expr_to_arb_poly(arb_poly_t res, const vigen_expr *e, slong prec);

/* If e is built from polynomials in t and sin, cos, exp of linear arguments
 * a t + b (a != 0), with sums and constant factors or divisors, writes
 * int_0^x e(t) dt, computed from the exact antiderivative, to res and returns
 * 1; else returns 0 (use rigorous quadrature). */
int vigen_expr_integral_closed_form(arb_t res, const vigen_expr *e, const arb_t x, slong prec);

/* log2 of the ratio of the largest to the smallest magnitude among the
 * certainly nonzero constant subexpressions of e (each evaluated at 64 bits):
 * in "1/2 + exp(-2000)" about 2890 bits.  Checking a condition on such an
 * entry needs at least that many bits to see the small part at all. */
double vigen_expr_magnitude_span_bits(const vigen_expr *e);

/* If the constant expression is built from numbers with + - * / and
 * integer powers (so that its value is rational), writes the value to res
 * and returns 1; else returns 0 (sqrt(4) counts as not rational). */
int vigen_expr_to_fmpq(fmpq_t res, const vigen_expr *e);

/* If the constant expression's value lies in one real quadratic field,
 * writes it as a + b sqrt(d) and returns 1: d > 1 squarefree and b != 0, or
 * d = 1 and b = 0 when the value is rational.  Allowed: numbers, + - * /,
 * integer powers (|k| <= 4096, as vigen_expr_to_fmpq) and sqrt of a
 * non-negative rational p/q in lowest terms (sqrt(p/q) = m sqrt(d)/q; refused
 * when p or q, its prime factors below 4096 divided out, leaves a cofactor
 * that is not a square and exceeds 64 bits, too large to factor at once).  Returns 0 otherwise: pi, t, other functions, nested radicals, and an
 * operation on two irrationals of different fields even when the result lies
 * in one (sqrt(2)*sqrt(3) = sqrt(6) and sqrt(6)/sqrt(2) = sqrt(3) give 0). */
int vigen_expr_to_quadratic(fmpq_t a, fmpq_t b, fmpz_t d, const vigen_expr *e);

/* The expression in LaTeX (math mode), e.g. "1/4 - sqrt(3)/6" gives
 * "\frac{1}{4} - \frac{\sqrt{3}}{6}"; numbers as written.  A fresh string. */
char *vigen_expr_latex(const vigen_expr *e);

/* Convenience: parse and evaluate a constant expression. */
int vigen_expr_eval_string(arb_t res, const char *text, slong prec, vigen_error *err);

#endif
