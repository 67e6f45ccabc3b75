/* vocabulary_text.c — what method files may contain, written out from the
 * tables themselves (methods.def, nodes.def, basis.def, functions.def), so
 * that `vigen help spec` and the documentation it backs never list a kind,
 * family or function the code does not have, nor miss one it has. */
#include <stdlib.h>
#include <string.h>

#include "core/expr.h"
#include "vigen/method.h"
#include "support/strbuf.h"

typedef struct { const char *name, *description; } row;

static const row method_rows[] = {
#define X(id, name, detect, read, tableau, release, generated, fields, description) { name, description },
#include "method/methods.def"
#undef X
};

static const row node_rows[] = {
#define X(name, min_s, fn, description) { #name "(s)", description },
#include "method/nodes.def"
#undef X
};

static const row basis_rows[] = {
#define X(name, fn, description) { #name "(s)", description },
#include "method/basis.def"
#undef X
};

/* The text fits a terminal of this many columns. */
#define TEXT_COLUMNS 80

/* Columns of n bytes of UTF-8 text (every character one column). */
static size_t columns(const char *s, size_t n)
{
    size_t c = 0;
    for (size_t i = 0; i < n; i++) c += ((unsigned char)s[i] & 0xC0) != 0x80;
    return c;
}

/* "  name  description", the names in one column and each description
 * broken at spaces before TEXT_COLUMNS, its further lines under its first. */
static void put_rows(vigen_strbuf *sb, const row *rows, size_t n)
{
    size_t width = 0;
    for (size_t i = 0; i < n; i++)
        if (strlen(rows[i].name) > width) width = strlen(rows[i].name);
    size_t indent = width + 4;
    for (size_t i = 0; i < n; i++) {
        vigen_strbuf_printf(sb, "  %-*s  ", (int)width, rows[i].name);
        size_t col = indent;
        for (const char *p = rows[i].description; *p;) {
            const char *gap = p;
            while (*p == ' ') p++;
            if (*p == '\0') break;
            const char *word = p;
            while (*p && *p != ' ') p++;
            size_t g = (size_t)(word - gap), w = columns(word, (size_t)(p - word));
            if (col > indent && col + g + w > TEXT_COLUMNS) {
                vigen_strbuf_printf(sb, "\n%*s", (int)indent, "");
                col = indent;
                g = 0;
            }
            vigen_strbuf_printf(sb, "%*s%.*s", (int)g, "", (int)(p - word), word);
            col += g + w;
        }
        vigen_strbuf_append(sb, "\n");
    }
}

char *vigen_method_vocabulary_text(void)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "Kinds of method file (FILE of show, check and emit; SPEC of generate):\n");
    put_rows(&sb, method_rows, sizeof method_rows / sizeof method_rows[0]);
    vigen_strbuf_append(&sb, "\nNode families (nodes = NAME(s); nodes t on [0, 1], certified, increasing):\n");
    put_rows(&sb, node_rows, sizeof node_rows / sizeof node_rows[0]);
    vigen_strbuf_append(&sb, "\nBasis families (basis = NAME(s); or \"lagrange\", or a list of expressions in t\n"
                             "and Lua functions of a ball t):\n");
    put_rows(&sb, basis_rows, sizeof basis_rows / sizeof basis_rows[0]);

    int nf = vigen_expr_function_count(), nc = vigen_expr_constant_count();
    row *fr = calloc((size_t)(nf + nc), sizeof *fr);
    char **names = calloc((size_t)(nf + nc), sizeof *names);
    if (fr == NULL || names == NULL) abort();
    for (int i = 0; i < nf; i++) {
        const vigen_expr_function *f = vigen_expr_function_at(i);
        names[i] = vigen_strdup_printf("%s(x)%s", f->name, f->in_ball_library ? "" : " *");
        fr[i].name = names[i];
        fr[i].description = f->description;
    }
    for (int i = 0; i < nc; i++) {
        const vigen_expr_constant *c = vigen_expr_constant_at(i);
        fr[nf + i].name = names[nf + i] = vigen_strdup(c->name);
        fr[nf + i].description = c->description;
    }
    vigen_strbuf_append(&sb, "\nFunctions and constants of exact expressions (\"1/2 - sqrt(3)/6\"), also offered\n"
                             "to Lua basis functions as ball functions (sqrt(t), ball.pi, exact(\"1/3\")):\n");
    put_rows(&sb, fr, (size_t)(nf + nc));
    int any_not_ball = 0;
    for (int i = 0; i < nf; i++) any_not_ball |= !vigen_expr_function_at(i)->in_ball_library;
    if (any_not_ball) vigen_strbuf_append(&sb, "  (* in expressions only, not a ball function)\n");
    vigen_strbuf_append(&sb, "  with + - * / ^, parentheses, integers, rationals and decimals\n"
                             "  (exact: 0.1 is 1/10)\n");
    for (int i = 0; i < nf + nc; i++) free(names[i]);
    free(names);
    free(fr);
    char *text = sb.data ? sb.data : vigen_strdup("");
    return text;
}
