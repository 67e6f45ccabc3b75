/* notes.c — what the entries' literals ask: the starting precision that sees
 * every digit of them, and the notes on short decimals among long ones that
 * look like exact values typed as decimals.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/decimal.h"
#include "core/expr.h"
#include "check/check_internal.h"
#include "support/strbuf.h"

/* Decimal digits needed to see every literal of an exact expression: the
 * digits of its longest number (all digits of the mantissa, leading zeros
 * included, plus |exponent|: "1e-45" needs 46), plus, summed over the powers
 * B^k with a whole-number literal exponent k, |k| log10 B (at least |k| 0.3;
 * B the number before '^'; a parenthesised base counts |k| digits when |k| >= 10,
 * nothing for small powers such as x^2). */
static double literal_digits(const char *s)
{
    double numbers = 0, powers = 0;
    double base = -1;            /* the number just before the current position, or -1 */
    size_t i = 0, n = strlen(s);
    while (i < n) {
        char ch = s[i];
        if ((ch >= '0' && ch <= '9') || (ch == '.' && s[i + 1] >= '0' && s[i + 1] <= '9')) {
            size_t j = i;
            double nd = 0;
            while ((s[j] >= '0' && s[j] <= '9') || s[j] == '.') nd += s[j++] != '.';
            double ex = 0;
            if ((s[j] == 'e' || s[j] == 'E') &&
                ((s[j + 1] >= '0' && s[j + 1] <= '9') ||
                 ((s[j + 1] == '+' || s[j + 1] == '-') && s[j + 2] >= '0' && s[j + 2] <= '9'))) {
                j++;
                if (s[j] == '+' || s[j] == '-') j++;
                while (s[j] >= '0' && s[j] <= '9') {
                    if (ex < 1e9) ex = 10 * ex + (s[j] - '0');
                    j++;
                }
            }
            if (nd + ex > numbers) numbers = nd + ex;
            char *buf = malloc(j - i + 1);
            memcpy(buf, s + i, j - i);
            buf[j - i] = '\0';
            base = fabs(strtod(buf, NULL));
            free(buf);
            i = j;
            continue;
        }
        if (ch == '^') {
            double b = base;
            size_t j = i + 1;
            int paren = 0;
            while (s[j] == ' ' || s[j] == '(' || s[j] == '+' || s[j] == '-') paren += s[j++] == '(';
            if (s[j] >= '0' && s[j] <= '9') {
                size_t k0 = j;
                double k = 0;
                while (s[j] >= '0' && s[j] <= '9') {
                    if (k < 1e9) k = 10 * k + (s[j] - '0');
                    j++;
                }
                while (s[j] == ' ') j++;
                /* a whole number, not the start of 1/3, 2.5, 1e3 or 2^3 */
                int whole = j > k0 && s[j] != '.' && s[j] != '/' && s[j] != 'e' && s[j] != 'E' && s[j] != '^' &&
                            !(paren && s[j] != ')');
                if (whole) {
                    if (b < 0) powers += k >= 10 ? k : 0;
                    else if (b != 0 && b != 1) powers += k * FLINT_MAX(fabs(log10(b)), 0.30103);
                }
            }
            base = -1;
            i++;
            continue;
        }
        if (ch != ' ' && ch != '\t') base = -1;
        i++;
    }
    return numbers + powers;
}

/* Digits needed by the entries: the longest rounded decimal, and the literals
 * of every exact expression. */
static double entries_digits(const vigen_tableau *t)
{
    slong s = t->s;
    double d = 0;
    char **lists[6] = {t->c_text, t->b_text, t->ct_text, t->bt_text, t->A_text, t->At_text};
    slong lens[6] = {s, s, s, s, s * s, s * s};
    for (int l = 0; l < 6; l++) {
        if (lists[l] == NULL) continue;
        for (slong k = 0; k < lens[l]; k++) {
            const char *x = lists[l][k];
            if (x == NULL) continue;
            double n = vigen_decimal_is_rounded(x) ? (double)vigen_decimal_significant_digits(x) : literal_digits(x);
            if (!vigen_decimal_is_rounded(x)) {
                /* an exact part far smaller than the rest (1/2 + exp(-2000)) must
                 * be visible at the starting precision, literal or not */
                vigen_expr *e = NULL;
                vigen_error err;
                vigen_error_init(&err);
                if (vigen_expr_parse(&e, x, 0, &err) == VIGEN_OK) {
                    double span = vigen_expr_magnitude_span_bits(e) * 0.30102999566398120;
                    if (span > n) n = span;
                }
                vigen_expr_free(e);
                vigen_error_clear(&err);
            }
            if (n > d) d = n;
        }
    }
    return d;
}

/* The text without surrounding blanks, a fresh string. */
static char *trimmed(const char *x)
{
    while (*x == ' ' || *x == '\t') x++;
    size_t len = strlen(x);
    while (len > 0 && (x[len - 1] == ' ' || x[len - 1] == '\t')) len--;
    char *r = malloc(len + 1);
    if (r == NULL) abort();
    memcpy(r, x, len);
    r[len] = '\0';
    return r;
}

/* The decimals of an entry, bare or inside an expression: returns the most
 * significant digits of one of them (0: none), and with shortest the one
 * with the fewest (a fresh string). */
static slong entry_decimals(const char *x, char **shortest)
{
    if (shortest) *shortest = NULL;
    if (x == NULL) return 0;
    if (vigen_decimal_is_rounded(x)) {
        if (shortest) *shortest = trimmed(x);
        return vigen_decimal_significant_digits(x);
    }
    vigen_expr *e = NULL;
    vigen_error err;
    vigen_error_init(&err);
    slong most = 0;
    if (vigen_expr_parse(&e, x, 0, &err) == VIGEN_OK) {
        most = vigen_expr_longest_decimal_digits(e);
        if (most > 0 && shortest) *shortest = vigen_expr_shortest_decimal(e);
    }
    vigen_expr_free(e);
    vigen_error_clear(&err);
    return most;
}

/* Short decimals that look exact: a rounded decimal (bare, or inside an
 * expression: "0.5*sqrt(3)") with at most
 * CHK_NOTE_SHORT_DIGITS significant digits in a file whose longest
 * decimal has at least CHK_NOTE_LONG_DIGITS.  Three digits is where
 * the rule for rounded data stops deciding on an entry alone (5 10^-3 of
 * itself at most, above 2^-10); ten digits says the file meant to be precise,
 * so a "0.5" among such entries is most likely the exact 1/2 typed as a
 * decimal.  Zeros written with an exponent ("0e-50", a certified tiny value
 * of a generated file) are meant as balls and not named. */
void chk_collect_notes(vigen_check_report *rep, const vigen_tableau *t)
{
    chk_notes_clear(rep);
    if (!chk_has_texts(t)) return;
    slong s = t->s;
    int has_At = t->has_At, has_bt = t->has_At && t->has_bt, has_ct = t->has_At && t->has_ct;
    /* in the order of the file */
    char **lists[6] = {t->c_text, t->A_text, t->b_text, has_At ? t->At_text : NULL, has_ct ? t->ct_text : NULL,
                       has_bt ? t->bt_text : NULL};
    const char *names[6] = {"c", "A", "b", "At", "ct", "bt"};
    slong lens[6] = {s, s * s, s, s * s, s, s};
    int matrix[6] = {0, 1, 0, 1, 0, 0};
    slong longest = 0;
    for (int l = 0; l < 6; l++)
        for (slong k = 0; lists[l] && k < lens[l]; k++) {
            slong d = entry_decimals(lists[l][k], NULL);
            if (d > longest) longest = d;
        }
    if (longest < CHK_NOTE_LONG_DIGITS) return;
    slong alloc = 0;
    for (int l = 0; l < 6; l++)
        for (slong k = 0; lists[l] && k < lens[l]; k++) {
            const char *x = lists[l][k];
            char *lit = NULL;
            if (x == NULL || entry_decimals(x, &lit) == 0 || lit == NULL) {
                free(lit);
                continue;
            }
            slong d = vigen_decimal_significant_digits(lit);
            char *fraction = d <= CHK_NOTE_SHORT_DIGITS ? vigen_decimal_exact_fraction(lit) : NULL;
            char *radius = fraction ? vigen_decimal_half_unit(lit) : NULL;
            if (fraction == NULL || radius == NULL ||
                (strcmp(fraction, "0") == 0 && (strchr(lit, 'e') != NULL || strchr(lit, 'E') != NULL))) {
                free(fraction);
                free(radius);
                free(lit);
                continue;
            }
            if (rep->nnotes == alloc) {
                alloc = alloc ? 2 * alloc : 8;
                rep->notes = realloc(rep->notes, sizeof(vigen_check_note) * (size_t)alloc);
            }
            vigen_check_note *n = rep->notes + rep->nnotes++;
            n->entry = matrix[l] ? vigen_strdup_printf("%s[%ld][%ld]", names[l], (long)(k / s + 1), (long)(k % s + 1))
                                 : vigen_strdup_printf("%s[%ld]", names[l], (long)(k + 1));
            n->text = lit;
            n->expression = vigen_decimal_is_rounded(x) ? NULL : trimmed(x);
            n->digits = d;
            n->radius = radius;
            n->fraction = fraction;
            if (n->expression)
                n->message = vigen_strdup_printf("%s = \"%s\": %s is read as %s +/- %s (%ld significant digit%s); if "
                                                 "it is exact, write %s", n->entry, n->expression, lit, lit, radius,
                                                 (long)d, d == 1 ? "" : "s", fraction);
            else
                n->message = vigen_strdup_printf("%s = \"%s\" is read as %s +/- %s (%ld significant digit%s); if it "
                                                 "is exact, write \"%s\"", n->entry, lit, lit, radius, (long)d,
                                                 d == 1 ? "" : "s", fraction);
        }
}

slong chk_adequate_prec(const vigen_tableau *t)
{
    double d = entries_digits(t);
    if (d > 1e7) d = 1e7;
    slong p = (slong)ceil(d * 3.3219280948873623) + 64;
    if (!chk_has_texts(t) && t->prec > p) p = t->prec;
    return p < 128 ? 128 : p;
}


/* Two entry texts with the same exact value (or the same text). */
static int same_entry(const char *x, const char *y)
{
    if (x == NULL || y == NULL) return 0;
    if (strcmp(x, y) == 0) return 1;
    arb_t a, b;
    arb_init(a);
    arb_init(b);
    vigen_error err;
    vigen_error_init(&err);
    int same = vigen_tableau_entry_eval(a, x, 128, &err) == VIGEN_OK &&
               vigen_tableau_entry_eval(b, y, 128, &err) == VIGEN_OK && arb_is_exact(a) && arb_equal(a, b);
    vigen_error_clear(&err);
    arb_clear(a);
    arb_clear(b);
    return same;
}

static int zero_entry(const char *x)
{
    arb_t a;
    arb_init(a);
    vigen_error err;
    vigen_error_init(&err);
    int zero = x != NULL && vigen_tableau_entry_eval(a, x, 128, &err) == VIGEN_OK && arb_is_zero(a);
    vigen_error_clear(&err);
    arb_clear(a);
    return zero;
}

/* A reducible tableau computes with fewer stages than it has, which makes
 * conditions fail or degenerate for reasons the tableau's author should see
 * named: two stages with equal rows of A and At have equal stage values (for
 * time-independent H; their c only place them in time), and a stage of
 * weight 0 in both parts that no stage uses does nothing. */
void chk_collect_reducible(vigen_check_report *rep, const vigen_tableau *t)
{
    free(rep->reducible);
    rep->reducible = NULL;
    if (!chk_has_texts(t)) return;
    slong s = t->s;
    char **At = t->has_At ? t->At_text : t->A_text;
    char **bt = t->has_At && t->has_bt ? t->bt_text : t->b_text;
    for (slong i = 0; i < s; i++)
        for (slong j = i + 1; j < s; j++) {
            int rows = 1;
            for (slong k = 0; k < s && rows; k++)
                rows = same_entry(t->A_text[i * s + k], t->A_text[j * s + k]) &&
                       same_entry(At[i * s + k], At[j * s + k]);
            if (!rows) continue;
            int same_c = same_entry(t->c_text[i], t->c_text[j]);
            rep->reducible = vigen_strdup_printf(
                "stages %ld and %ld have equal rows of A%s, so equal stage values: they are one stage, and the "
                "method is a %ld-stage one with weight b[%ld] + b[%ld]%s; merge them (or check the rows for "
                "a typo)", (long)(i + 1), (long)(j + 1), t->has_At ? " and At" : "", (long)(s - 1), (long)(i + 1),
                (long)(j + 1),
                same_c ? "" : " (their c differ, which places one stage at two times: the row sums are the "
                              "times of the stage values)");
            return;
        }
    for (slong j = 0; j < s; j++) {
        int idle = zero_entry(t->b_text[j]) && zero_entry(bt[j]);
        for (slong i = 0; i < s && idle; i++) idle = zero_entry(t->A_text[i * s + j]) && zero_entry(At[i * s + j]);
        if (!idle) continue;
        rep->reducible = vigen_strdup_printf("stage %ld has weight 0 and no stage uses it (column %ld of A%s is 0): "
                                             "it does nothing; remove it (the method is a %ld-stage one)",
                                             (long)(j + 1), (long)(j + 1), t->has_At ? " and At" : "", (long)(s - 1));
        return;
    }
}
