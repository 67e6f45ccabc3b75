/* expr_parse.c — text to expression tree: the nodes, a lexer and a
 * recursive-descent parser for the grammar in expr.h, with messages that
 * quote the text and name the column; the names it knows come from
 * functions.def.
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
#include "core/decimal.h"
#include "core/expr_internal.h"
#include "support/strbuf.h"

/* Nesting limit: keeps the recursive parser, evaluator and destructor far
 * away from the end of the C stack.  Real expressions nest a few levels. */
#define EXPR_MAX_DEPTH 1000

/* Exact exponents are stored as fmpq when |exponent| <= this (10^4096 needs
 * 1.7 KB); beyond that a number is rounded through an arb power of ten. */
#define EXPR_MAX_FMPQ_EXP 4096

/* Precision at which a constant exponent is evaluated to decide whether it is
 * an exact integer (an exact ball is the exact value, at any precision). */
#define EXPR_EXPONENT_PREC 1024

/* The names an expression may use, for the "unknown name" message. */
static const char known_names[] = ""
#define C(ID, NAME, ...) NAME ", "
#include "core/functions.def"
#undef C
    "t"
#define X(ID, NAME, ...) ", " NAME
#include "core/functions.def"
#undef X
    ;

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
    fmpz_init(n->unit);
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
    fmpz_clear(n->unit);
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

/* The known name (t, a constant, a function) that differs from the len bytes
 * at name only in case, or NULL. */
static const char *case_variant(const char *name, size_t len)
{
    const char *hit = NULL;
    for (int k = -1; k < EXPR_CONST_COUNT + EXPR_FN_COUNT; k++) {
        const char *known = k < 0 ? "t"
                          : k < EXPR_CONST_COUNT ? expr_constants[k].pub.name
                                                 : expr_functions[k - EXPR_CONST_COUNT].pub.name;
        if (strlen(known) == len && same_name_ignoring_case(known, name, len)) hit = known;
    }
    return hit;
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
            /* range-checked before use: 1e99999999999999999999 would overflow
             * arb's exponents (FLINT aborts) */
            long e = 0;
            while (is_digit(s[j])) {
                if (e <= VIGEN_DECIMAL_EXP_MAX) e = 10 * e + (s[j] - '0');
                j++;
            }
            if (e > VIGEN_DECIMAL_EXP_MAX) {
                char *what = vigen_strdup_printf("exponent out of range in '%.*s'", (int)(j - pos), s + pos);
                return syntax_error_owned(p, pos, what, vigen_strdup_printf("(a decimal exponent is at most %ld in "
                                                                            "size: write the number another way)",
                                                                            (long)VIGEN_DECIMAL_EXP_MAX));
            }
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
    n->decimal = memchr(s + start, '.', len) != NULL || memchr(s + start, 'e', len) != NULL ||
                 memchr(s + start, 'E', len) != NULL;
    fmpz_set(n->unit, n->e);
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
    expr_arb_ctx c = { NULL, NULL, NULL, EXPR_EXPONENT_PREC };   /* silent: no messages */
    arb_init(v);
    if (expr_eval_arb_node(v, y, &c) == VIGEN_OK && arb_is_int(v)
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
        for (int k = 0; k < EXPR_CONST_COUNT; k++) {
            if (!tok_is_name(p, &tok, expr_constants[k].pub.name)) continue;
            p->pos = tok.end;
            *out = node_new(N_CONST, tok.start, tok.end);
            (*out)->fn = k;
            return VIGEN_OK;
        }
        if (tok_is_name(p, &tok, "t")) {
            if (!p->allow_t)
                return syntax_error(p, tok.start, "the variable t is not allowed here (constants only)", NULL);
            p->pos = tok.end;
            *out = node_link(node_new(N_T, tok.start, tok.end), NULL, NULL);
            return VIGEN_OK;
        }
        for (int f = 0; f < EXPR_FN_COUNT; f++) {
            const char *fname = expr_functions[f].pub.name;
            if (!tok_is_name(p, &tok, fname)) continue;
            token open;
            p->pos = tok.end;
            rc = peek(p, &open);
            if (rc != VIGEN_OK) return rc;
            if (!tok_is(p, &open, '(')) {
                char *what = vigen_strdup_printf("expected '(' after the function name '%s'", fname);
                return syntax_error_owned(p, open.start, what, NULL);
            }
            p->pos = open.end;
            node *arg;
            rc = parse_expr(&arg, p);
            if (rc != VIGEN_OK) return rc;
            rc = expect_close(p, open.start);
            if (rc == VIGEN_OK) rc = make_node(out, p, N_FUNC, tok.start, p->pos, arg, NULL);
            else node_free(arg);
            if (rc == VIGEN_OK) (*out)->fn = f;
            return rc;
        }
        /* unknown name: a hint for near misses */
        size_t len = tok.end - tok.start;
        const char *name = p->text + tok.start;
        const char *hint = case_variant(name, len);
        char *what = vigen_strdup_printf("unknown name '%.*s'", (int)len, name);
        char *tail;
        if (hint)
            tail = vigen_strdup_printf("(known: %s; names are case-sensitive: did you mean '%s'?)", known_names, hint);
        else if (len == 1 && (name[0] == 'e' || name[0] == 'E'))
            tail = vigen_strdup_printf("(known: %s; write exp(1) for Euler's number)", known_names);
        else
            tail = vigen_strdup_printf("(known: %s)", known_names);
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
/* Parse and evaluate                                                         */

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
