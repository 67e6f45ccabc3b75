/* expr_decimals.c — the decimal literals of an expression ("0.5" in
 * "0.5*sqrt(3)"): counting them, and reading them as rounded values, the
 * rule for tableau entries (a decimal there was rounded from the method's
 * exact coefficient, bare or inside an expression). */
#include <stdlib.h>
#include <string.h>
#include "core/decimal.h"
#include "core/expr_internal.h"

/* Marks the decimals of the subtree rounded; returns how many there are.  A
 * power whose exponent holds one is no longer an exact integer power. */
static int round_node(node *n)
{
    if (n == NULL) return 0;
    int k = 0;
    if (n->kind == N_NUM && n->decimal) {
        n->rounded = 1;
        k = 1;
    }
    k += round_node(n->a);
    int in_exponent = round_node(n->b);
    if (n->kind == N_POW && in_exponent > 0) n->int_exp = 0;
    return k + in_exponent;
}

int vigen_expr_round_decimals(vigen_expr *e) { return e ? round_node(e->root) : 0; }

static int count_node(const node *n)
{
    if (n == NULL) return 0;
    return (n->kind == N_NUM && n->decimal) + count_node(n->a) + count_node(n->b);
}

int vigen_expr_decimal_count(const vigen_expr *e) { return e ? count_node(e->root) : 0; }

/* The decimal literals of the subtree with the fewest and the most
 * significant digits (the first of each in the text). */
static void extreme_nodes(const node *n, const char *text, const node **few, slong *few_digits, slong *most_digits)
{
    if (n == NULL) return;
    if (n->kind == N_NUM && n->decimal) {
        size_t len = n->end - n->start;
        char *lit = malloc(len + 1);
        if (lit != NULL) {
            memcpy(lit, text + n->start, len);
            lit[len] = '\0';
            slong d = vigen_decimal_significant_digits(lit);
            if (*few == NULL || d < *few_digits) {
                *few = n;
                *few_digits = d;
            }
            if (d > *most_digits) *most_digits = d;
            free(lit);
        }
    }
    extreme_nodes(n->a, text, few, few_digits, most_digits);
    extreme_nodes(n->b, text, few, few_digits, most_digits);
}

slong vigen_expr_longest_decimal_digits(const vigen_expr *e)
{
    const node *few = NULL;
    slong f = 0, most = 0;
    if (e != NULL) extreme_nodes(e->root, e->text, &few, &f, &most);
    return most;
}

char *vigen_expr_shortest_decimal(const vigen_expr *e)
{
    if (e == NULL) return NULL;
    const node *best = NULL;
    slong digits = 0, most = 0;
    extreme_nodes(e->root, e->text, &best, &digits, &most);
    if (best == NULL) return NULL;
    size_t len = best->end - best->start;
    char *lit = malloc(len + 1);
    if (lit == NULL) return NULL;
    memcpy(lit, e->text + best->start, len);
    lit[len] = '\0';
    return lit;
}
