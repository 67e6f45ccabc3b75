/* test_check_extension.c — a new check is one row of vigen/check_fields.def
 * and one function.  This test is built with the checker and its reports
 * (src/check, src/report) compiled again with one more row
 * (test_check_extension.def, through VIGEN_CHECK_FIELDS_EXTRA; see
 * tests/CMakeLists.txt) and the row's function below, and nothing else: the
 * check runs on every round after the others, `vigen help checks` lists it,
 * the report has its member (initialised, reset each round, cleared), the
 * JSON object its key and the text report its line at its place, in the
 * check's words when it gives them and the value's otherwise.  A second
 * row reports a figure, a ball: the largest residual of the same conditions.
 *
 * The check: a PRK method whose parts satisfy a_ij + a_(s+1-i)(s+1-j) = b_j
 * is symmetric (Hairer, Lubich, Wanner, Geometric Numerical Integration,
 * Thm V.2.3, with Sect. V.2.1 for the partitioned case).  Known truths: the
 * Gauss methods (c_(s+1-i) = 1 - c_i, HLW V.2) and Lobatto IIIA-IIIB satisfy
 * it; symplectic Euler is not symmetric (its adjoint is the other variant,
 * HLW V.1), so no tableau of it can satisfy it.
 */
#include <math.h>
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

/* The second row's function: a figure, the largest residual of the
 * conditions of chk_symmetric (no verdict, nothing decided). */
int chk_symmetry_defect(chk_round *r, vigen_error *err)
{
    (void)err;
    ctx_t *cx = r->cx;
    arb_ptr defect = r->rep->symmetry_defect.value;
    slong s = cx->s;
    arb_t d;
    arb_init(d);
    arb_zero(defect);
    for (int part = 0; part < (cx->has_At ? 2 : 1); part++) {
        int M = part ? M_AT : M_A, W = part ? M_BT : M_B;
        for (slong i = 0; i < s; i++)
            for (slong j = 0; j < s; j++) {
                arb_add(d, chk_get(cx, M, i, j, NULL), chk_get(cx, M, s - 1 - i, s - 1 - j, NULL), cx->prec);
                arb_sub(d, d, chk_get(cx, W, j, 0, NULL), cx->prec);
                arb_abs(d, d);
                arb_max(defect, defect, d, cx->prec);
            }
    }
    r->rep->symmetry_defect.set = 1;
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

/* `vigen help checks`: the new checks last, with their descriptions */
static void test_listed(void)
{
    char *list = vigen_check_list_text();
    const char *line = strstr(list, "\n  symmetric "), *second = strstr(list, "\n  symmetry_defect ");
    CHECK_MSG(line != NULL && second != NULL, "%s", list);
    if (line && second) {
        CHECK(strstr(line, "a_ij + a_(s+1-i)(s+1-j) = b_j in both parts") < second);
        CHECK(strchr(line + 1, '\n') == second && strchr(second + 1, '\n')[1] == '\0');
    }
    CHECK(strstr(list, "\n  figures ") != NULL && strstr(list, "\n  figures ") < line);
    free(list);
}

/* The reports of one checked file: the member holds want, after at least
 * rounds evaluations (the members are reset before each); the defect is the
 * number defect (a decimal) or within 10^-30 of 0 (defect NULL); the JSON
 * object ends with the new keys after the table's last row; the text has
 * the lines (the check's words, or the value's) between the tree notation
 * and the verdict. */
static void check_file(const char *rel, slong rounds, int want, const char *json_value, const char *text_line,
                       const char *defect)
{
    vigen_check_report rep;
    if (check_rel(&rep, rel) != VIGEN_OK) {
        vigen_check_report_clear(&rep);
        return;
    }
    CHECK_MSG(rep.symmetric.set && rep.symmetric.value == want, "%s: set %d value %d", rel, rep.symmetric.set,
              rep.symmetric.value);
    CHECK_MSG(rep.rounds >= rounds, "%s: %ld evaluations", rel, (long)rep.rounds);
    CHECK(rep.symmetry_defect.set && rep.symmetry_defect.text == NULL);
    arb_t bound;
    arb_init(bound);
    arb_set_str(bound, defect ? defect : "1e-30", 256);
    if (defect)
        CHECK(arb_overlaps(rep.symmetry_defect.value, bound) && arb_rel_accuracy_bits(rep.symmetry_defect.value) > 60);
    else CHECK(arb_lt(rep.symmetry_defect.value, bound));
    arb_clear(bound);
    char *js = render(&rep, 1), *text = render(&rep, 0);
    char tail[128];
    snprintf(tail, sizeof(tail), ",\n \"symmetric\": %s, \"symmetry_defect\": ", json_value);
    const char *at = strstr(js, tail), *exit_at = strstr(js, "\"exit\": ");
    CHECK_MSG(at && exit_at && exit_at < at, "%s: JSON %s", rel, js);
    if (at) {
        char *end;
        double d = strtod(at + strlen(tail), &end);
        CHECK_MSG(strcmp(end, "}\n") == 0 && (defect ? d == strtod(defect, NULL) : fabs(d) < 1e-30),
                  "%s: JSON ends %s", rel, at);
    }
    const char *line = strstr(text, text_line), *trees = strstr(text, "\ntrees: "), *result = strstr(text, "\nresult ");
    const char *line2 = strstr(text, "\nsym. defect  ");
    CHECK_MSG(line && line2 && trees && result && trees < line && line < line2 && line2 < result, "%s:\n%s", rel, text);
    /* a ball in words: its certain digits, six of an exact 1 */
    if (line2 && defect && strcmp(defect, "1") == 0)
        CHECK_MSG(strncmp(line2, "\nsym. defect   1.00000\n", 23) == 0, "%.40s", line2);
    free(js);
    free(text);
    vigen_check_report_clear(&rep);
}

/* a report the check has not written: JSON null, no text line */
static void test_unset(void)
{
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    CHECK(!rep.symmetric.set && rep.symmetric.text == NULL && !rep.symmetry_defect.set);
    char *js = render(&rep, 1), *text = render(&rep, 0);
    CHECK(strstr(js, ",\n \"symmetric\": null, \"symmetry_defect\": null}\n") != NULL);
    CHECK(strstr(text, "symmetric ") == NULL && strstr(text, "sym. defect") == NULL);
    free(js);
    free(text);
    vigen_check_report_clear(&rep);
}

int main(void)
{
    test_listed();
    check_file("tableaux/published/gauss_2.lua", 1, VIGEN_CHECK_YES, "true", "\nsymmetric     yes\n", NULL);
    check_file("tableaux/published/lobatto_iiia_iiib_3.lua", 1, VIGEN_CHECK_YES, "true", "\nsymmetric     yes\n",
               NULL);
    /* A = (0), At = (1), b = bt = (1) (HLW VI.3): 0 + 0 - 1 and 1 + 1 - 1 */
    check_file("tableaux/published/symplectic_euler_p_first.lua", 1, VIGEN_CHECK_NO, "false",
               "\nsymmetric     no (A[1][1] + A[1][1] != b[1])\n", "1");
    /* Gauss 2 with a_11 = 1/4 + 10^-45: the pairs (1, 1) and (2, 2) are off
     * by 10^-45, seen after a refinement; (1, 2) and (2, 1) still hold */
    check_file("tests/data/check/gauss2_1e-45.lua", 2, VIGEN_CHECK_NO, "false",
               "\nsymmetric     no (A[1][1] + A[2][2] != b[1])\n", "1e-45");
    test_unset();
    TEST_MAIN_END();
}
