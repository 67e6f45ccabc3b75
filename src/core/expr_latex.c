/* expr_latex.c — an expression tree as LaTeX (math mode): numbers as
 * written, fractions as \frac, the table's functions and constants in their
 * LaTeX form, parentheses only where the binding strength needs them. */
#include <stdlib.h>
#include "core/expr_internal.h"
#include "support/strbuf.h"

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
    switch (n->kind) {
    case N_NUM: {
        /* the literal as written; an exponent becomes \times 10^{k} */
        const char *a = text + n->start, *z = text + n->end, *e = a;
        while (e < z && *e != 'e' && *e != 'E') e++;
        vigen_strbuf_appendn(sb, a, (size_t)(e - a));
        if (e < z) vigen_strbuf_printf(sb, "\\times 10^{%ld}", strtol(e + 1, NULL, 10));
        break;
    }
    case N_CONST: vigen_strbuf_append(sb, expr_constants[n->fn].latex); break;
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
        if (latex_rank(n->a) == 5 && (n->a->kind == N_NUM || n->a->kind == N_CONST || n->a->kind == N_T))
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
    case N_FUNC:
        vigen_strbuf_append(sb, expr_functions[n->fn].latex_open);
        latex_node(sb, text, n->a);
        vigen_strbuf_append(sb, expr_functions[n->fn].latex_close);
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
