/* test_check_extension.c — a new check is one row of vigen/check_fields.def
 * and one function.  This test is built with the checker and its reports
 * (src/check, src/report) compiled again with one more row
 * (test_check_extension.def, through VIGEN_CHECK_FIELDS_EXTRA; see
 * tests/CMakeLists.txt) and the row's function below, and nothing else: the
 * check runs on every round after the others, `vigen help checks` lists it,
 * the report has its member (initialised, reset each round, cleared), the
 * JSON object its key and the text report its line at its place, in the
 * check's words when it gives them and the value's otherwise.
 *
 * The check: a PRK method whose parts satisfy a_ij + a_(s+1-i)(s+1-j) = b_j
 * is symmetric (Hairer, Lubich, Wanner, Geometric Numerical Integration,
 * Thm V.2.3, with Sect. V.2.1 for the partitioned case).  Known truths: the
 * Gauss methods (c_(s+1-i) = 1 - c_i, HLW V.2) and Lobatto IIIA-IIIB satisfy
 * it; symplectic Euler is not symmetric (its adjoint is the other variant,
 * HLW V.1), so no tableau of it can satisfy it.
 */
#include "test_check_support.h"
#include "vigen/method.h"
#include "check/check_internal.h"

/* The function of the row: every condition decided through chk_decide2 (with
 * the simplifying assumptions' statistics of holds), the first failure in
 * the check's own words. */
int chk_symmetric(chk_round *r, vigen_error *err)
{
    (void)err;
    ctx_t *cx = r->cx;
    vigen_check_report *rep = r->rep;
    slong s = cx->s, fail = 0, undecided = 0;
    arb_t sum, d;
    arb_init(sum);
    arb_init(d);
    cx->section = VIGEN_CHECK_SECT_SIMPLIFYING;
    for (int part = 0; part < (cx->has_At ? 2 : 1); part++) {
        int M = part ? M_AT : M_A, W = part ? M_BT : M_B;
        for (slong i = 0; i < s; i++)
            for (slong j = 0; j < s; j++) {
                /* one entry per term, no constant: a multiple of 1/D */
                chk_ctx_shape(cx, 1, 1, 1000 + part, i, j);
                arb_srcptr w = chk_get(cx, W, j, 0, NULL);
                arb_add(sum, chk_get(cx, M, i, j, NULL), chk_get(cx, M, s - 1 - i, s - 1 - j, NULL), cx->prec);
                arb_sub(d, sum, w, cx->prec);
                int v = chk_decide2(cx, d, cx->ex->part[part], sum, w);
                if (v == FAILS && fail++ == 0)
                    rep->symmetric.text = vigen_strdup_printf(
                        "no (%s[%ld][%ld] + %s[%ld][%ld] != %s[%ld])", chk_matrix_names[M], (long)(i + 1),
                        (long)(j + 1), chk_matrix_names[M], (long)(s - i), (long)(s - j), chk_matrix_names[W],
                        (long)(j + 1));
                undecided += v == UNDECIDED;
            }
    }
    rep->symmetric.value = chk_tri_of(fail, undecided);
    rep->symmetric.set = 1;
    arb_clear(sum);
    arb_clear(d);
    return VIGEN_OK;
}

static int check_rel(vigen_check_report *rep, const char *rel)
{
    char path[1024];
    snprintf(path, sizeof(path), "%s/%s", VIGEN_SOURCE_DIR, rel);
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.load = vigen_source_load;
    opt.path = path;
    vigen_error err;
    vigen_error_init(&err);
    vigen_check_report_init(rep);
    int rc = vigen_check_file(rep, &opt, &err);
    CHECK_MSG(rc == VIGEN_OK, "%s: %s", rel, err.message ? err.message : "");
    vigen_error_clear(&err);
    return rc;
}

/* `vigen help checks`: the new check last, with its description */
static void test_listed(void)
{
    char *list = vigen_check_list_text();
    const char *line = strstr(list, "\n  symmetric ");
    CHECK_MSG(line != NULL, "%s", list);
    if (line) {
        CHECK(strstr(line, "a_ij + a_(s+1-i)(s+1-j) = b_j in both parts") != NULL);
        CHECK(strchr(line + 1, '\n')[1] == '\0');
    }
    CHECK(strstr(list, "\n  figures ") != NULL && strstr(list, "\n  figures ") < line);
    free(list);
}

/* The reports of one checked file: the member holds want, the JSON object
 * ends with the new key after the table's last row, the text has the line
 * (the check's words, or the value's) before the verdict. */
static void check_file(const char *rel, int want, const char *json_value, const char *text_line)
{
    vigen_check_report rep;
    if (check_rel(&rep, rel) != VIGEN_OK) {
        vigen_check_report_clear(&rep);
        return;
    }
    CHECK_MSG(rep.symmetric.set && rep.symmetric.value == want, "%s: set %d value %d", rel, rep.symmetric.set,
              rep.symmetric.value);
    CHECK(rep.rounds >= 1);
    char *js = render(&rep, 1), *text = render(&rep, 0);
    char tail[128];
    snprintf(tail, sizeof(tail), ",\n \"symmetric\": %s}\n", json_value);
    size_t n = strlen(js), m = strlen(tail);
    CHECK_MSG(n > m && strcmp(js + n - m, tail) == 0, "%s: JSON ends %s", rel, n > 40 ? js + n - 40 : js);
    CHECK(strstr(js, "\"exit\": ") != NULL && strstr(js, "\"exit\": ") < js + n - m);
    const char *line = strstr(text, text_line), *trees = strstr(text, "\ntrees: "), *result = strstr(text, "\nresult ");
    CHECK_MSG(line && trees && result && trees < line && line < result, "%s:\n%s", rel, text);
    free(js);
    free(text);
    vigen_check_report_clear(&rep);
}

/* a report the check has not written: JSON null, no text line */
static void test_unset(void)
{
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    CHECK(!rep.symmetric.set && rep.symmetric.text == NULL);
    char *js = render(&rep, 1), *text = render(&rep, 0);
    CHECK(strstr(js, ",\n \"symmetric\": null}\n") != NULL);
    CHECK(strstr(text, "symmetric ") == NULL);
    free(js);
    free(text);
    vigen_check_report_clear(&rep);
}

int main(void)
{
    test_listed();
    check_file("tableaux/published/gauss_2.lua", VIGEN_CHECK_YES, "true", "\nsymmetric     yes\n");
    check_file("tableaux/published/lobatto_iiia_iiib_3.lua", VIGEN_CHECK_YES, "true", "\nsymmetric     yes\n");
    check_file("tableaux/published/symplectic_euler_p_first.lua", VIGEN_CHECK_NO, "false", "\nsymmetric     no (");
    test_unset();
    TEST_MAIN_END();
}
