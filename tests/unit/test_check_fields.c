/* test_check_fields.c — the report table (vigen/check_fields.def) and
 * the code that expands it: the checks come first and `vigen help checks`
 * lists them in their order; every figure is a JSON key of its own; a row
 * has text lines exactly when it names a place and a function for them, at
 * a place of its own; the JSON object of a checked file has the members the
 * rows say, in their order, each once at the top level, and the text report
 * prints the figures in the order of their places.  Also vigen_check_file:
 * FILE and FILE2 loaded and checked, an unreadable file an error with
 * nothing checked.  (A check added by one row: test_check_extension.c.)
 *
 * The expectations are the table's own statements (keys, conditions,
 * places) and the report's documented lines ("row sums", "symplectic", ...),
 * checked against what the printers write.
 */
#include "test_check_support.h"
#include "vigen/method.h"
#include "report/check_fields.h"

/* the figures of the JSON object: X_FIGURE and X_RESULT rows (the latter
 * with the text function the printer makes for them) */
#define X_CHECK(name, fn, description)
static const struct {
    const char *key, *type, *text_fn;
    int text_at;
} rows[] = {
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn) {#key, #type, #text_fn, text_at},
#define X_RESULT(name, fn, description, type, sep, text_at, label) {#name, #type, text_at ? "text_result" : "NULL", text_at},
#include "vigen/check_fields.def"
#undef X_FIGURE
#undef X_RESULT
};
enum { NROWS = sizeof(rows) / sizeof(rows[0]) };

static void test_rows(void)
{
    CHECK(NROWS > 40);
    for (int i = 0; i < NROWS; i++) {
        int text = strcmp(rows[i].text_fn, "NULL") != 0;
        CHECK_MSG(text == (rows[i].text_at > 0), "row %s: text_at %d, text_fn %s", rows[i].key, rows[i].text_at,
                  rows[i].text_fn);
        CHECK_MSG(!text || strncmp(rows[i].text_fn, "text_", 5) == 0, "row %s: text_fn %s", rows[i].key,
                  rows[i].text_fn);
        for (int j = 0; j < i; j++) {
            CHECK_MSG(strcmp(rows[i].key, rows[j].key) != 0, "key %s twice", rows[i].key);
            CHECK_MSG(!text || rows[i].text_at != rows[j].text_at, "rows %s and %s print at %d", rows[i].key,
                      rows[j].key, rows[i].text_at);
        }
    }
}

/* The checks: every X_CHECK row before the figures (the checks that write
 * members by hand run first), names of their own, and `vigen help checks`
 * lists exactly the checks of the table, in its order. */
static void test_checks(void)
{
    enum { CHECK_ROW, FIGURE_ROW, RESULT_ROW };
    static const struct {
        int kind;
        const char *name, *description;
    } all[] = {
#undef X_CHECK
#define X_CHECK(name, fn, description) {CHECK_ROW, #name, description},
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn) {FIGURE_ROW, #key, NULL},
#define X_RESULT(name, fn, description, type, sep, text_at, label) {RESULT_ROW, #name, description},
#include "vigen/check_fields.def"
#undef X_CHECK
#undef X_FIGURE
#undef X_RESULT
#define X_CHECK(name, fn, description)
    };
    enum { NALL = sizeof(all) / sizeof(all[0]) };
    char *list = vigen_check_list_text();
    const char *at = strchr(list, '\n');
    int checks = 0, seen_figure = 0;
    for (int i = 0; i < NALL; i++) {
        if (all[i].kind == FIGURE_ROW) {
            seen_figure = 1;
            continue;
        }
        checks++;
        CHECK_MSG(all[i].kind != CHECK_ROW || !seen_figure, "X_CHECK row %s after a figure", all[i].name);
        for (int j = 0; j < i; j++)
            CHECK_MSG(all[j].kind == FIGURE_ROW || strcmp(all[i].name, all[j].name) != 0, "check %s twice",
                      all[i].name);
        /* its line: "  name  description" */
        CHECK_MSG(at && strncmp(at + 1, "  ", 2) == 0 && strncmp(at + 3, all[i].name, strlen(all[i].name)) == 0 &&
                      at[3 + strlen(all[i].name)] == ' ',
                  "check %s not listed in its place", all[i].name);
        const char *end = at ? strchr(at + 1, '\n') : NULL;
        size_t dl = strlen(all[i].description);
        CHECK_MSG(end && (size_t)(end - at) > dl && strncmp(end - dl, all[i].description, dl) == 0,
                  "check %s: its description", all[i].name);
        at = end;
    }
    CHECK(checks >= 10 && at && at[1] == '\0');
    free(list);
}

/* Loads and checks rel (and against_rel, or NULL) from the source tree. */
static int check_rel(vigen_check_report *rep, const char *rel, const char *against_rel, vigen_error *err)
{
    char path[1024], against[1024];
    snprintf(path, sizeof(path), "%s/%s", VIGEN_SOURCE_DIR, rel);
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.load = vigen_source_load;
    opt.path = path;
    if (against_rel) {
        snprintf(against, sizeof(against), "%s/%s", VIGEN_SOURCE_DIR, against_rel);
        opt.against = against;
    }
    vigen_check_report_init(rep);
    return vigen_check_file(rep, &opt, err);
}

/* The top-level members of the JSON object js, in order: the keys of the
 * table's rows whose condition holds, each once, at depth 1. */
static void check_members(const vigen_check_report *rep, const char *js)
{
    int want[NROWS], n = 0;
#define X_FIGURE(key, type, value, sep, when, text_at, text_fn) want[n++] = (when) != 0;
#define X_RESULT(name, fn, description, type, sep, text_at, label) want[n++] = 1;
#include "vigen/check_fields.def"
#undef X_FIGURE
#undef X_RESULT
    /* the keys at depth 1: a string after '{' or ',' at depth 1, followed by ':' */
    int depth = 0, next = 0;
    for (const char *p = js; *p; p++) {
        if (*p == '"') {
            const char *q = p + 1;
            while (*q && *q != '"') q += q[0] == '\\' && q[1] ? 2 : 1;
            const char *after = q + (*q == '"');
            while (*after == ' ') after++;
            if (depth == 1 && *after == ':') {
                while (next < NROWS && !want[next]) next++;
                CHECK_MSG(next < NROWS && strlen(rows[next].key) == (size_t)(q - p - 1) &&
                              strncmp(p + 1, rows[next].key, (size_t)(q - p - 1)) == 0,
                          "member %.*s where the table has %s", (int)(q - p - 1), p + 1,
                          next < NROWS ? rows[next].key : "nothing");
                next++;
            }
            p = *q ? q : q - 1;
        } else if (*p == '{' || *p == '[') depth++;
        else if (*p == '}' || *p == ']') depth--;
    }
    while (next < NROWS && !want[next]) next++;
    CHECK_MSG(next == NROWS, "member %s missing", next < NROWS ? rows[next].key : "");
    CHECK(depth == 0);
}

/* The text report's figures, in the order of their places (the first words
 * of the lines each prints). */
static void check_text_order(const char *text, int against)
{
    static const char *const heads[] = {"\n  entries: ", "\nrow sums ", "\nsymplectic ", "\norder ",
                                        "\nsimplifying assumptions\n", "\nerror constants ", "\nstability ",
                                        "\ncost ", "\nagainst ", "\nproblems", "\ntrees: ", "\nresult "};
    const char *at = text;
    for (size_t k = 0; k < sizeof(heads) / sizeof(heads[0]); k++) {
        if (!against && strcmp(heads[k], "\nagainst ") == 0) {
            CHECK(strstr(text, heads[k]) == NULL);
            continue;
        }
        const char *p = strstr(at, heads[k]);
        CHECK_MSG(p != NULL, "'%s' missing or out of order", heads[k] + 1);
        if (p) at = p + 1;
    }
}

static void test_reports(void)
{
    static const char *const cases[][2] = {
        {"tableaux/published/gauss_2.lua", NULL},                         /* Q(sqrt 3): proved */
        {"tableaux/published/lobatto_iiia_iiib_3.lua", NULL},             /* rational */
        {"tableaux/published/forest_ruth_4.lua", "tests/data/published_prk/forest_ruth_4.lua"},
        {"tests/data/check/gauss2_6digits.lua", "tableaux/published/gauss_2.lua"},   /* rounded */
        {"tests/data/check/gauss3_40_perturbed.lua", NULL},               /* problems, claims */
    };
    for (size_t k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
        vigen_check_report rep;
        vigen_error err;
        vigen_error_init(&err);
        CHECK_MSG(check_rel(&rep, cases[k][0], cases[k][1], &err) == VIGEN_OK, "%s: %s", cases[k][0],
                  err.message ? err.message : "");
        CHECK(rep.against_checked == (cases[k][1] != NULL));
        char *js = render(&rep, 1), *text = render(&rep, 0);
        check_members(&rep, js);
        check_text_order(text, cases[k][1] != NULL);
        free(js);
        free(text);
        vigen_check_report_clear(&rep);
        vigen_error_clear(&err);
    }
}

static void test_unreadable(void)
{
    vigen_check_report rep;
    vigen_error err;
    vigen_error_init(&err);
    int rc = check_rel(&rep, "tests/data/check/does_not_exist.lua", NULL, &err);
    CHECK(rc != VIGEN_OK && err.code == rc && vigen_status_exit_code(rc) == 2);
    CHECK(rep.s == 0 && rep.nfailures == 0);
    vigen_check_report_clear(&rep);
    vigen_error_clear(&err);
    /* FILE2 unreadable: the same, after FILE was read */
    vigen_error_init(&err);
    rc = check_rel(&rep, "tableaux/published/gauss_2.lua", "tests/data/check/does_not_exist.lua", &err);
    CHECK(rc != VIGEN_OK && vigen_status_exit_code(rc) == 2 && rep.s == 0);
    vigen_check_report_clear(&rep);
    vigen_error_clear(&err);
}

/* The generalized orders of a named-flow file are computed by default and
 * skipped when the caller asks for the classical figures only; the
 * classical order (SABA_2: 2, generalized (4, 2); Laskar and Robutel 2001)
 * is the same. */
static void test_generalized_option(void)
{
    char path[1024];
    snprintf(path, sizeof(path), "%s/tableaux/published/saba_2.lua", VIGEN_SOURCE_DIR);
    for (int g = 0; g <= 1; g++) {
        vigen_check_options opt;
        vigen_check_options_init(&opt);
        CHECK(opt.generalized == 1);
        opt.load = vigen_source_load;
        opt.path = path;
        opt.generalized = g;
        vigen_check_report rep;
        vigen_error err;
        vigen_error_init(&err);
        vigen_check_report_init(&rep);
        CHECK(vigen_check_file(&rep, &opt, &err) == VIGEN_OK);
        int computed = rep.generalized != NULL && rep.generalized->computed;
        CHECK_MSG(computed == g, "generalized = %d: computed %d", g, computed);
        int at_least = 0, undecided = 0;
        CHECK(vigen_check_certified_order(&rep, VIGEN_CHECK_GENERAL, &at_least, &undecided) == 2);
        vigen_check_report_clear(&rep);
        vigen_error_clear(&err);
    }
}

int main(void)
{
    test_generalized_option();
    test_rows();
    test_checks();
    test_reports();
    test_unreadable();
    TEST_MAIN_END();
}
