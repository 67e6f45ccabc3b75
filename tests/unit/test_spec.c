/* test_spec.c — loading and validating spec files, calling Lua basis
 * functions, and method files (vigen/method.h): a spec or a tableau file
 * recognised from the one run of the file.  Spec files are written to a temporary directory, so every
 * message can be checked to start with the file's path. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "method/spec.h"
#include "vigen/method.h"
#include "testlib.h"
#include "support/strbuf.h"

static char *tmpdir;
static char **written;          /* files to remove at the end */
static size_t n_written;

static int contains(const char *haystack, const char *needle)
{
    return haystack != NULL && strstr(haystack, needle) != NULL;
}

static int starts_with(const char *s, const char *prefix)
{
    return s != NULL && strncmp(s, prefix, strlen(prefix)) == 0;
}

/* Writes text to TMPDIR/name and returns the path (heap). */
static char *write_spec(const char *name, const char *text)
{
    char *path = vigen_strdup_printf("%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    if (f == NULL) { perror(path); exit(1); }
    fputs(text, f);
    fclose(f);
    written = realloc(written, (n_written + 1) * sizeof *written);
    written[n_written++] = vigen_strdup(path);
    return path;
}

/* Captured warnings. */
static vigen_strbuf warnings;
static void capture_warning(const char *message, void *ctx)
{
    (void)ctx;
    vigen_strbuf_append(&warnings, message);
    vigen_strbuf_append(&warnings, "\n");
}

/* Loads text as a spec; returns the status and leaves the message in err. */
static int load(vigen_spec **spec, const char *text, const vigen_sandbox_limits *limits, vigen_error *err,
                char **path_out)
{
    static int counter = 0;
    char *name = vigen_strdup_printf("spec%d.lua", ++counter);
    char *path = write_spec(name, text);
    free(name);
    vigen_error_clear(err);
    *spec = (vigen_spec *)1;   /* must be reset to NULL on failure */
    int code = vigen_spec_load(spec, path, limits, err);
    if (code != VIGEN_OK) CHECK(*spec == NULL);
    if (path_out) *path_out = path;
    else free(path);
    return code;
}

/* The load fails with code; the message starts with the path and contains each phrase. */
static void expect_failure(const char *text, int want, const char *phrase1, const char *phrase2)
{
    vigen_spec *spec;
    vigen_error err;
    vigen_error_init(&err);
    char *path;
    int code = load(&spec, text, NULL, &err, &path);
    CHECK_MSG(code == want, "expected %s, got %s: %s\n  for: %s", vigen_status_name(want), vigen_status_name(code),
              err.message ? err.message : "(no message)", text);
    CHECK_MSG(starts_with(err.message, path), "%s", err.message);
    CHECK_MSG(contains(err.message, phrase1), "lacks '%s': %s", phrase1, err.message);
    if (phrase2) CHECK_MSG(contains(err.message, phrase2), "lacks '%s': %s", phrase2, err.message);
    if (code == VIGEN_OK) vigen_spec_free(spec);
    free(path);
    vigen_error_clear(&err);
}

static void test_list_spec(void)
{
    vigen_spec *spec;
    vigen_error err;
    vigen_error_init(&err);
    char *path;
    int code = load(&spec,
                    "-- a list spec\n"
                    "local function psi3(t) return sin(pi*t) end\n"
                    "return {\n"
                    "  name = \"ex4\", description = \"Leok-Zhang example 4\", source = \"paper\",\n"
                    "  nodes = { \"0\", \"1/2\", 1 },\n"
                    "  basis = { \"1\", \"cos(pi*t)\", psi3 },\n"
                    "}\n", NULL, &err, &path);
    CHECK_MSG(code == VIGEN_OK, "%s", err.message);
    if (code == VIGEN_OK) {
        CHECK(strcmp(spec->path, path) == 0);
        CHECK(strcmp(spec->name, "ex4") == 0);
        CHECK(strcmp(spec->description, "Leok-Zhang example 4") == 0);
        CHECK(strcmp(spec->source, "paper") == 0);
        CHECK(spec->nodes_kind == VIGEN_SPEC_NODES_LIST && spec->s == 3 && spec->node_family == NULL);
        CHECK(spec->basis_kind == VIGEN_SPEC_BASIS_LIST && spec->basis_count == 3);
        CHECK(strcmp(vigen_expr_text(spec->node_exprs[1]), "1/2") == 0);
        /* the nodes evaluate to 0, 1/2, 1 */
        arb_t x, want;
        arb_init(x);
        arb_init(want);
        for (int i = 0; i < 3; i++) {
            CHECK(vigen_expr_eval_arb(x, spec->node_exprs[i], NULL, 64, &err) == VIGEN_OK);
            arb_set_si(want, i);
            arb_mul_2exp_si(want, want, -1);
            CHECK(arb_equal(x, want));
        }
        arb_clear(x);
        arb_clear(want);
        CHECK(spec->items[0].kind == VIGEN_SPEC_ITEM_EXPR && !vigen_expr_depends_on_t(spec->items[0].expr));
        CHECK(spec->items[1].kind == VIGEN_SPEC_ITEM_EXPR && vigen_expr_depends_on_t(spec->items[1].expr));
        CHECK(strcmp(spec->items[1].label, "cos(pi*t)") == 0);
        CHECK(spec->items[2].kind == VIGEN_SPEC_ITEM_LUA && spec->items[2].expr == NULL);
        CHECK(strcmp(spec->items[2].label, "<Lua function, basis[3]>") == 0);
        CHECK_MSG(strcmp(spec->nodes_text, "{\"0\", \"1/2\", \"1\"}") == 0, "%s", spec->nodes_text);
        CHECK_MSG(strcmp(spec->basis_text, "{\"1\", \"cos(pi*t)\", \"<Lua function>\"}") == 0, "%s", spec->basis_text);
        CHECK(spec->sandbox != NULL);
        vigen_spec_free(spec);
    }
    free(path);
    vigen_error_clear(&err);
}

static void test_family_specs(void)
{
    vigen_spec *spec;
    vigen_error err;
    vigen_error_init(&err);
    CHECK(load(&spec, "return { name = 'g3', basis = 'lagrange', nodes = gauss_legendre(3) }", NULL, &err, NULL)
          == VIGEN_OK);
    if (spec) {
        CHECK(spec->nodes_kind == VIGEN_SPEC_NODES_FAMILY && spec->s == 3);
        CHECK(strcmp(spec->node_family, "gauss_legendre") == 0 && spec->node_exprs == NULL);
        CHECK(spec->basis_kind == VIGEN_SPEC_BASIS_LAGRANGE && spec->basis_count == 3 && spec->items == NULL);
        CHECK(strcmp(spec->nodes_text, "gauss_legendre(3)") == 0);
        CHECK(strcmp(spec->basis_text, "\"lagrange\"") == 0);
        CHECK(spec->description == NULL && spec->source == NULL);
        vigen_spec_free(spec);
    }
    CHECK(load(&spec, "return { name = 't5', basis = trig(5), nodes = equispaced(5) }", NULL, &err, NULL)
          == VIGEN_OK);
    if (spec) {
        CHECK(spec->basis_kind == VIGEN_SPEC_BASIS_FAMILY && strcmp(spec->basis_family, "trig") == 0);
        CHECK(spec->basis_count == 5 && spec->s == 5);
        CHECK(strcmp(spec->basis_text, "trig(5)") == 0 && strcmp(spec->nodes_text, "equispaced(5)") == 0);
        vigen_spec_free(spec);
    }
    /* every basis family, with a node list */
    static const char *const families[] = { "monomials", "trig", "legendre", "chebyshev_t", NULL };
    for (int i = 0; families[i]; i++) {
        char *text = vigen_strdup_printf("return { name = 'x', basis = %s(2), nodes = {'0', '1'} }", families[i]);
        CHECK(load(&spec, text, NULL, &err, NULL) == VIGEN_OK);
        if (spec) {
            CHECK(strcmp(spec->basis_family, families[i]) == 0 && spec->basis_count == 2);
            vigen_spec_free(spec);
        }
        free(text);
    }
    /* lagrange on a node list */
    CHECK(load(&spec, "return { name = 'mid', basis = 'lagrange', nodes = { '1/2' } }", NULL, &err, NULL) == VIGEN_OK);
    if (spec) {
        CHECK(spec->basis_count == 1 && spec->s == 1);
        vigen_spec_free(spec);
    }
    vigen_error_clear(&err);
}

static void test_refusals(void)
{
    /* what the file returns */
    expect_failure("return 42", VIGEN_E_SPEC, "must return a table", "number");
    expect_failure("local x = 1", VIGEN_E_SPEC, "returned nothing", NULL);
    expect_failure("return {\n name = 'x'\n nodes = {} }", VIGEN_E_SYNTAX, ":3:", NULL);
    expect_failure("local n = 2\nerror('fails on purpose')", VIGEN_E_LUA, ":2: fails on purpose", NULL);
    expect_failure("return { name = 'x', basis = 'lagrange',\n nodes = gauss(3) }", VIGEN_E_LUA, ":2: unknown name 'gauss'",
                   "gauss_legendre");
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = gauss_legendre(2.5) }", VIGEN_E_LUA, ":1:",
                   "not the float 2.5");
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = gauss_legendre(3.0) }", VIGEN_E_LUA,
                   "Lua integer", "3.0");

    /* name, description, source */
    expect_failure("return { basis = 'lagrange', nodes = {'0'} }", VIGEN_E_SPEC, "name is missing", NULL);
    expect_failure("return { name = 3, basis = 'lagrange', nodes = {'0'} }", VIGEN_E_SPEC, "name must be a string",
                   "number");
    expect_failure("return { name = '', basis = 'lagrange', nodes = {'0'} }", VIGEN_E_SPEC, "name is empty", NULL);
    expect_failure("return { name = 'x', description = {}, basis = 'lagrange', nodes = {'0'} }", VIGEN_E_SPEC,
                   "description must be a string", "table");
    expect_failure("return { name = 'x', source = true, basis = 'lagrange', nodes = {'0'} }", VIGEN_E_SPEC,
                   "source must be a string", "boolean");

    /* nodes */
    expect_failure("return { name = 'x', basis = {'1', 't'}, nodes = {0, 1/3} }", VIGEN_E_SPEC,
                   ": nodes[2] is the Lua float 0.3333333333333333; write the exact string \"1/3\"", NULL);
    expect_failure("return { name = 'x', basis = {'1', 't'}, nodes = {0, 0.5} }", VIGEN_E_SPEC,
                   "nodes[2] is the Lua float 0.5", "\"1/2\"");
    expect_failure("return { name = 'x', basis = {'1'}, nodes = {2.0} }", VIGEN_E_SPEC, "nodes[1] is the Lua float 2.0",
                   "\"2\"");
    expect_failure("return { name = 'x', basis = {'1'}, nodes = {math.pi} }", VIGEN_E_SPEC,
                   "nodes[1] is the Lua float 3.141592653589793", "rounded");
    expect_failure("return { name = 'x', basis = 'lagrange' }", VIGEN_E_SPEC, "nodes is missing", "gauss_legendre");
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = {} }", VIGEN_E_SPEC, "nodes is empty", NULL);
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = {'0', x = '1'} }", VIGEN_E_SPEC,
                   "nodes has an entry with key 'x'", "plain list");
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = {'0', [5] = '1'} }", VIGEN_E_SPEC, "nodes", NULL);
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = {'0', true} }", VIGEN_E_SPEC,
                   "nodes[2] is a boolean", NULL);
    expect_failure("return { name = 'x', basis = {'1'}, nodes = {'t'} }", VIGEN_E_SYNTAX, "nodes[1]", NULL);
    expect_failure("return { name = 'x', basis = {'1', 't'}, nodes = {'0', '1/'} }", VIGEN_E_SYNTAX, "nodes[2]", NULL);
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = 'gauss_legendre' }", VIGEN_E_SPEC,
                   "needs the number of nodes", "gauss_legendre(3)");
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = 'gaus' }", VIGEN_E_SPEC,
                   "nodes: unknown node family 'gaus' (known: gauss_legendre, ", NULL);
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = '1/2' }", VIGEN_E_SPEC, "single string",
                   "{\"1/2\"}");
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = gauss_legendre }", VIGEN_E_SPEC,
                   "nodes is a function", "gauss_legendre(3)");
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = 3 }", VIGEN_E_SPEC, "nodes is a number", NULL);
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = trig(3) }", VIGEN_E_SPEC,
                   "trig(3) is a basis family, not a node family", NULL);
    expect_failure("return { name = 'x', basis = 'lagrange', nodes = {gauss_legendre(3)} }", VIGEN_E_SPEC,
                   "nodes[1] is gauss_legendre(3)", "nodes = gauss_legendre(3)");

    /* basis */
    expect_failure("return { name = 'x', nodes = {'0'} }", VIGEN_E_SPEC, "basis is missing", "lagrange");
    expect_failure("return { name = 'x', basis = gauss_legendre(2), nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   "basis: gauss_legendre(2) is a node family, not a basis family", NULL);
    expect_failure("return { name = 'x', basis = 'gauss_legendre', nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   "is a node family", NULL);
    expect_failure("return { name = 'x', basis = 'lagrang', nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   "unknown basis 'lagrang'", "\"lagrange\"");
    expect_failure("return { name = 'x', basis = 'trig', nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   "needs the number of functions", "trig(2)");
    expect_failure("return { name = 'x', basis = {}, nodes = {'0', '1'} }", VIGEN_E_SPEC, "basis is empty", NULL);
    expect_failure("return { name = 'x', basis = {'1', true}, nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   "basis[2] is a boolean", NULL);
    expect_failure("return { name = 'x', basis = {'1', {}}, nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   "basis[2] is a table", NULL);
    expect_failure("return { name = 'x', basis = {'1', 0.5}, nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   "basis[2] is the Lua float 0.5", "\"1/2\"");
    expect_failure("return { name = 'x', basis = {'1', 'cosh(t)'}, nodes = {'0', '1'} }", VIGEN_E_SYNTAX,
                   "basis[2]", "cosh");
    expect_failure("return { name = 'x', basis = {'1', trig(2)}, nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   "basis[2] is trig(2)", NULL);
    expect_failure("return { name = 'x', basis = function(t) return t end, nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   "basis is a function", NULL);
    expect_failure("return { name = 'x', basis = 7, nodes = {'0', '1'} }", VIGEN_E_SPEC, "basis must be", "number");

    /* counts */
    expect_failure("return { name = 'x', basis = {'1', 't', 't^2'}, nodes = {'0', '1'} }", VIGEN_E_SPEC,
                   ": basis has 3 functions but nodes has 2 entries; Theorem 3 needs one node per basis function", NULL);
    expect_failure("return { name = 'x', basis = trig(3), nodes = gauss_legendre(2) }", VIGEN_E_SPEC,
                   "basis has 3 functions but nodes has 2 entries", NULL);
    expect_failure("return { name = 'x', basis = {'1', 't'}, nodes = {'0'} }", VIGEN_E_SPEC,
                   "basis has 2 functions but nodes has 1 entry;", NULL);

    /* caps */
    expect_failure("while true do end", VIGEN_E_LIMIT, "instructions", NULL);

    /* an unreadable file */
    vigen_spec *spec = (vigen_spec *)1;
    vigen_error err;
    vigen_error_init(&err);
    CHECK(vigen_spec_load(&spec, "/nonexistent/spec.lua", NULL, &err) == VIGEN_E_IO && spec == NULL);
    CHECK(contains(err.message, "/nonexistent/spec.lua"));
    vigen_error_clear(&err);
}

static void test_unknown_fields(void)
{
    vigen_spec *spec;
    vigen_error err;
    vigen_error_init(&err);
    vigen_strbuf_init(&warnings);
    vigen_warning_set_handler(capture_warning, NULL);

    /* a typo is warned about, and the spec still loads */
    char *path;
    CHECK(load(&spec, "return { name = 'x', basis = 'lagrange', nodes = {'0'}, descripton = 'typo', [1] = 'y' }",
               NULL, &err, &path) == VIGEN_OK);
    vigen_spec_free(spec);
    CHECK_MSG(contains(warnings.data, "unknown field 'descripton' is ignored; did you mean 'description'?"), "%s",
              warnings.data);
    CHECK(contains(warnings.data, path) && contains(warnings.data, "entry [1] is ignored"));
    free(path);

    /* the closest field is suggested: 'node' is one edit from 'nodes', two from 'name' */
    vigen_strbuf_clear(&warnings);
    CHECK(load(&spec, "return { name = 'x', basis = 'lagrange', node = {'0'} }", NULL, &err, NULL) == VIGEN_E_SPEC);
    CHECK_MSG(contains(warnings.data, "did you mean 'nodes'"), "%s", warnings.data ? warnings.data : "(none)");
    vigen_error_clear(&err);

    /* a typo of a required field: the warning, then the error */
    vigen_strbuf_clear(&warnings);
    CHECK(load(&spec, "return { name = 'x', basys = 'lagrange', nodes = {'0'} }", NULL, &err, NULL) == VIGEN_E_SPEC);
    CHECK(contains(err.message, "basis is missing"));
    CHECK_MSG(contains(warnings.data, "'basys'") && contains(warnings.data, "did you mean 'basis'"), "%s",
              warnings.data ? warnings.data : "(none)");

    /* a clean spec warns about nothing */
    vigen_strbuf_clear(&warnings);
    CHECK(load(&spec, "return { name = 'x', basis = 'lagrange', nodes = {'0'} }", NULL, &err, NULL) == VIGEN_OK);
    vigen_spec_free(spec);
    CHECK(warnings.len == 0);

    vigen_warning_set_handler(NULL, NULL);
    vigen_strbuf_clear(&warnings);
    vigen_error_clear(&err);
}

static void acb_set_q(acb_t z, slong p, slong q, slong prec)
{
    fmpq_t r;
    fmpq_init(r);
    fmpq_set_si(r, p, (ulong)q);
    acb_zero(z);
    arb_set_fmpq(acb_realref(z), r, prec);
    fmpq_clear(r);
}

static int real_contains_q(const acb_t z, slong p, slong q)
{
    fmpq_t r;
    fmpq_init(r);
    fmpq_set_si(r, p, (ulong)q);
    int ok = arb_contains_fmpq(acb_realref(z), r) && arb_contains_zero(acb_imagref(z));
    fmpq_clear(r);
    return ok;
}

static void test_call_basis(void)
{
    slong prec = 128;
    vigen_spec *spec;
    vigen_error err;
    vigen_error_init(&err);
    char *path;
    vigen_sandbox_limits lim;
    vigen_sandbox_limits_default(&lim);
    lim.instruction_limit = 1000000;
    int code = load(&spec,
                    "return {\n"
                    "  name = 'calls',\n"
                    "  nodes = gauss_legendre(11),\n"
                    "  basis = {\n"
                    "    function(t) return cos(pi*t) end,\n"             /* 1 */
                    "    function(t) return t^2/3 end,\n"                 /* 2 */
                    "    function(t) return t/3 end,\n"                   /* 3 */
                    "    function(t)\n      return (1/3)*t\n    end,\n"   /* 4: line 9 */
                    "    function(t) return 'one' end,\n"                 /* 5 */
                    "    function(t) return 0.5 end,\n"                   /* 6 */
                    "    function(t) return 1 end,\n"                     /* 7 */
                    "    function(t) error('broken basis') end,\n"        /* 8: line 14 */
                    "    function(t) while true do end end,\n"            /* 9 */
                    "    function(t) local n = 0 for i = 1, 170000 do n = n + i end return t * n end,\n" /* 10 */
                    "    'cos(pi*t)',\n"                                  /* 11 */
                    "  },\n"
                    "}\n", &lim, &err, &path);
    CHECK_MSG(code == VIGEN_OK, "%s", err.message);
    if (code != VIGEN_OK) { free(path); return; }
    CHECK(spec->basis_count == 11);
    CHECK_MSG(strcmp(spec->basis_text, "{\"<Lua function>\", \"<Lua function>\", \"<Lua function>\", \"<Lua function>\", "
                                       "\"<Lua function>\", \"<Lua function>\", \"<Lua function>\", \"<Lua function>\", "
                                       "\"<Lua function>\", \"<Lua function>\", \"cos(pi*t)\"}") == 0,
              "%s", spec->basis_text);

    acb_t t, r;
    acb_init(t);
    acb_init(r);

    /* cos(pi t) at 1/3 contains 1/2, also in analytic mode on a real ball */
    acb_set_q(t, 1, 3, prec);
    CHECK(vigen_spec_call_basis(r, spec, 0, t, 0, prec, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 2) && mag_cmp_2exp_si(arb_radref(acb_realref(r)), -100) <= 0);
    mag_set_ui_2exp_si(arb_radref(acb_realref(t)), 1, -30);
    CHECK(vigen_spec_call_basis(r, spec, 0, t, 1, prec, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 2) && acb_is_finite(r));
    /* the expression item goes through the same call */
    CHECK(vigen_spec_call_basis(r, spec, 10, t, 1, prec, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 2) && acb_is_finite(r));

    /* t^2/3 at 1/2 is 1/12 (a ball of tiny radius around it), t/3 is 1/6 */
    acb_set_q(t, 1, 2, prec);
    CHECK(vigen_spec_call_basis(r, spec, 1, t, 0, prec, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 12) && arb_is_zero(acb_imagref(r)));
    CHECK(mag_cmp_2exp_si(arb_radref(acb_realref(r)), -(prec - 8)) <= 0);
    CHECK(vigen_spec_call_basis(r, spec, 2, t, 0, prec, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 6) && mag_cmp_2exp_si(arb_radref(acb_realref(r)), -(prec - 8)) <= 0);

    /* (1/3)*t: the float is refused with file:line, the entry and the hint */
    CHECK(vigen_spec_call_basis(r, spec, 3, t, 0, prec, &err) == VIGEN_E_LUA);
    char *where = vigen_strdup_printf("%s:9:", path);
    CHECK_MSG(starts_with(err.message, where) && contains(err.message, "exact(\"1/3\")") &&
              contains(err.message, "basis[4]"), "%s", err.message);
    free(where);
    CHECK(!acb_is_finite(r));   /* indeterminate on failure */

    /* wrong return values */
    CHECK(vigen_spec_call_basis(r, spec, 4, t, 0, prec, &err) == VIGEN_E_SPEC);
    CHECK_MSG(starts_with(err.message, path) && contains(err.message, "basis[5] returned a string"), "%s", err.message);
    CHECK(vigen_spec_call_basis(r, spec, 5, t, 0, prec, &err) == VIGEN_E_SPEC);
    CHECK_MSG(contains(err.message, "basis[6] returned the Lua float 0.5"), "%s", err.message);
    CHECK(vigen_spec_call_basis(r, spec, 6, t, 0, prec, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 1) && arb_is_exact(acb_realref(r)));

    /* Lua errors carry file:line; the cap is a cap */
    CHECK(vigen_spec_call_basis(r, spec, 7, t, 0, prec, &err) == VIGEN_E_LUA);
    where = vigen_strdup_printf("%s:14: broken basis", path);
    CHECK_MSG(starts_with(err.message, where) && contains(err.message, "basis[8]"), "%s", err.message);
    free(where);
    CHECK(vigen_spec_call_basis(r, spec, 8, t, 0, prec, &err) == VIGEN_E_LIMIT);
    CHECK_MSG(starts_with(err.message, path) && contains(err.message, "more than 1000000 Lua instructions"), "%s",
              err.message);

    /* the budget is reset at every call: ~0.7 of the cap, three times */
    for (int k = 0; k < 3; k++) {
        CHECK_MSG(vigen_spec_call_basis(r, spec, 9, t, 0, prec, &err) == VIGEN_OK, "%s", err.message);
        CHECK(real_contains_q(r, (slong)170000 * 170001 / 4, 1));
    }

    /* the sandbox's stack is left clean */
    CHECK(lua_gettop(vigen_sandbox_state(spec->sandbox)) == 0);

    /* list kinds only */
    CHECK(vigen_spec_call_basis(r, spec, 11, t, 0, prec, &err) != VIGEN_OK);
    CHECK(vigen_spec_call_basis(r, spec, -1, t, 0, prec, &err) != VIGEN_OK);

    acb_clear(t);
    acb_clear(r);
    vigen_spec_free(spec);
    free(path);
    vigen_error_clear(&err);
}

static void test_memory_cap(void)
{
    vigen_spec *spec;
    vigen_error err;
    vigen_error_init(&err);
    vigen_sandbox_limits lim;
    vigen_sandbox_limits_default(&lim);
    lim.memory_limit = (size_t)8 << 20;
    CHECK(load(&spec, "local t = {} for i = 1, 1e9 do t[i] = string.rep('x', 1000) .. i end", &lim, &err, NULL)
          == VIGEN_E_LIMIT);
    CHECK_MSG(contains(err.message, "more than 8 MiB of memory"), "%s", err.message);
    /* inside a basis function too */
    CHECK(load(&spec, "return { name = 'm', nodes = {'0'}, basis = { function(t) local s = 'x' "
                      "while true do s = s .. s end end } }", &lim, &err, NULL) == VIGEN_OK);
    acb_t t, r;
    acb_init(t);
    acb_init(r);
    if (spec) {
        CHECK(vigen_spec_call_basis(r, spec, 0, t, 0, 64, &err) == VIGEN_E_LIMIT);
        CHECK_MSG(contains(err.message, "memory"), "%s", err.message);
        vigen_spec_free(spec);
    }
    acb_clear(t);
    acb_clear(r);
    vigen_error_clear(&err);
}

/* The one-stage Gauss method (the implicit midpoint rule): c = a = 1/2, b = 1. */
static void check_midpoint(vigen_method *m, slong digits, vigen_error *err)
{
    vigen_tableau t;
    CHECK_MSG(vigen_method_tableau(&t, m, digits, err) == VIGEN_OK, "%s", err->message);
    if (err->code != VIGEN_OK) return;
    arb_t half;
    arb_init(half);
    arb_set_d(half, 0.5);
    CHECK(t.s == 1);
    CHECK(arb_contains(t.c, half) && arb_contains(arb_mat_entry(t.A, 0, 0), half));
    CHECK(arb_contains_si(t.b, 1));
    CHECK(t.prec > 0 && arb_rel_accuracy_bits(t.c) > 3 * digits);
    arb_clear(half);
    vigen_tableau_clear(&t);
}

static void test_method_files(void)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_method *m = NULL;

    char *spec = write_spec("m_spec.lua", "return { name = 'midpoint', nodes = gauss_legendre(1), basis = 'lagrange' }");
    CHECK_MSG(vigen_method_load(&m, spec, NULL, &err) == VIGEN_OK, "%s", err.message);
    if (m) {
        CHECK(vigen_method_is_generated(m) == 1);
        check_midpoint(m, 20, &err);    /* asked twice, at two precisions, from the one run */
        check_midpoint(m, 60, &err);
        vigen_tableau t;    /* a spec has no tableau "as stated" */
        CHECK(vigen_method_tableau(&t, m, 0, &err) == VIGEN_E_USAGE);
        vigen_error_clear(&err);
        vigen_method_free(m);
        m = NULL;
    }

    /* a tableau file carries nodes and basis as descriptions: still a tableau */
    char *tab = write_spec("m_tableau.lua", "return { name = 'midpoint', s = 1, c = {'1/2'}, A = {{'1/2'}}, b = {1}, "
                                           "nodes = 'gauss_legendre(1)', basis = '\"lagrange\"' }");
    CHECK_MSG(vigen_method_load(&m, tab, NULL, &err) == VIGEN_OK, "%s", err.message);
    if (m) {
        CHECK(vigen_method_is_generated(m) == 0);
        check_midpoint(m, 20, &err);
        check_midpoint(m, 60, &err);
        vigen_tableau t;    /* as stated: the texts of the file, nothing evaluated */
        CHECK(vigen_method_tableau(&t, m, 0, &err) == VIGEN_OK);
        if (err.code == VIGEN_OK) {
            CHECK(t.prec == 0 && t.s == 1 && strcmp(t.A_text[0], "1/2") == 0 && strcmp(t.b_text[0], "1") == 0);
            CHECK(strcmp(t.nodes, "gauss_legendre(1)") == 0 && !t.has_At);
            vigen_tableau_clear(&t);
        }
        vigen_method_free(m);
        m = NULL;
    }

    /* a spec's own messages come through unchanged */
    char *partial = write_spec("m_partial.lua", "return { name = 'x', basis = 'lagrange' }");
    CHECK(vigen_method_load(&m, partial, NULL, &err) == VIGEN_E_SPEC && m == NULL);
    CHECK(starts_with(err.message, partial) && contains(err.message, "nodes is missing"));

    /* of no kind: one message naming the file and what each kind needs */
    char *none = write_spec("m_none.lua", "return { name = 'x' }");
    CHECK(vigen_method_load(&m, none, NULL, &err) == VIGEN_E_SPEC && m == NULL);
    CHECK_MSG(starts_with(err.message, none) && contains(err.message, "nodes and basis") &&
              contains(err.message, "s, c, A and b"), "%s", err.message);
    char *scalar = write_spec("m_scalar.lua", "return 'gauss'");
    CHECK(vigen_method_load(&m, scalar, NULL, &err) == VIGEN_E_SPEC && m == NULL);
    CHECK_MSG(starts_with(err.message, scalar) && contains(err.message, "returns a string"), "%s", err.message);

    /* the one-call loader: the midpoint rule from either kind of file */
    const char *files[] = { spec, tab };
    for (int i = 0; i < 2; i++) {
        vigen_tableau t;
        CHECK_MSG(vigen_source_load(&t, files[i], 20, &err) == VIGEN_OK, "%s", err.message);
        if (err.code != VIGEN_OK) continue;
        arb_t half;
        arb_init(half);
        arb_set_d(half, 0.5);
        CHECK(t.s == 1 && arb_contains(t.c, half) && arb_contains_si(t.b, 1));
        arb_clear(half);
        vigen_tableau_clear(&t);
    }
    free(spec);
    free(tab);
    free(partial);
    free(none);
    free(scalar);
    vigen_error_clear(&err);
}

int main(void)
{
    char templ[] = "/tmp/vigen-test-spec-XXXXXX";
    const char *base = getenv("TMPDIR");
    char *dir_template = base ? vigen_strdup_printf("%s/vigen-test-spec-XXXXXX", base) : vigen_strdup(templ);
    tmpdir = mkdtemp(dir_template);
    if (tmpdir == NULL) { perror("mkdtemp"); return 1; }

    test_list_spec();
    test_family_specs();
    test_refusals();
    test_unknown_fields();
    test_call_basis();
    test_memory_cap();
    test_method_files();

    /* remove the temporary files */
    for (size_t i = 0; i < n_written; i++) {
        unlink(written[i]);
        free(written[i]);
    }
    free(written);
    rmdir(tmpdir);
    free(dir_template);
    TEST_MAIN_END();
}
