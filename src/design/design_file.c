/* design_file.c — reading a design file (vigen/design.h): run once in the
 * sandbox, every read raw, every field validated with a message naming the
 * file and the field. */
#include <stdlib.h>
#include <string.h>
#include <lua.h>
#include <flint/fmpq.h>
#include "vigen/check.h"
#include "vigen/design.h"
#include "vigen/limits.h"
#include "lua/sandbox.h"
#include "method/tableau_file.h"
#include "support/strbuf.h"
#include "support/nul.h"
#include "design/design_criterion.h"

/* minimize: each start is a descent with a checker run per trial point */
#define DEFAULT_MINIMIZE_STARTS 8L
#define MAX_STARTS 1000000L
#define MAX_SCREEN 100000L
#define MAX_HOMOTOPY 10000000L
/* Compositions of at most this many stages (the unknowns of a family). */
#define MAX_DESIGN_STAGES 64

static void push_raw(lua_State *L, const char *key)
{
    lua_pushstring(L, key);
    lua_rawget(L, -2);
}

/* A string field into *out (NULL when absent and not required). */
static int read_string(char **out, lua_State *L, const char *key, int required, const char *path, vigen_error *err)
{
    *out = NULL;
    push_raw(L, key);
    int rc = VIGEN_OK;
    if (lua_isnil(L, -1)) {
        if (required) rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: missing (a string)", path, key);
    } else if (lua_type(L, -1) != LUA_TSTRING) {
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: must be a string", path, key);
    } else {
        size_t len = 0;
        const char *s = lua_tolstring(L, -1, &len);
        if ((rc = vigen_refuse_nul(s, len, path, key, err)) == VIGEN_OK) {
            if (len == 0) rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: must not be empty", path, key);
            else *out = vigen_strdup(s);
        }
    }
    lua_pop(L, 1);
    return rc;
}

/* A whole-number field in [lo, hi] (def when absent and not required). */
static int read_whole(long *out, lua_State *L, const char *key, int required, long def, long lo, long hi,
                      const char *path, vigen_error *err)
{
    *out = def;
    push_raw(L, key);
    int rc = VIGEN_OK;
    if (lua_isnil(L, -1)) {
        if (required) rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: missing (a whole number from %ld to %ld)", path,
                                           key, lo, hi);
    } else if (!lua_isinteger(L, -1) || lua_tointeger(L, -1) < lo || lua_tointeger(L, -1) > hi) {
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: must be a whole number from %ld to %ld", path, key, lo, hi);
    } else {
        *out = (long)lua_tointeger(L, -1);
    }
    lua_pop(L, 1);
    return rc;
}

void vigen_design_spec_clear(vigen_design_spec *d)
{
    free(d->path);
    free(d->name);
    free(d->family);
    free(d->base);
    free(d->minimize);
    free(d->stationary);
    free(d->flow_a);
    free(d->flow_b);
    for (slong i = 0; i < d->nnearest; i++) free(d->nearest[i]);
    free(d->nearest);
    for (long i = 0; i < d->nfix; i++) {
        free(d->fix_name[i]);
        free(d->fix_value[i]);
    }
    free(d->fix_name);
    free(d->fix_value);
    free(d->fix_unknown);
    free(d->equal_unknown);
    memset(d, 0, sizeof *d);
}

/* rkn: Nystrom conditions; processed: the kernel's family ("splitting" or
 * "rkn"), symmetric, effective order 4 (the conditions of higher effective
 * orders are not linear in the Lie coefficients: docs/design.md). */
static int read_kernel(vigen_design_spec *d, lua_State *L, const char *path, vigen_error *err)
{
    d->nystrom = strcmp(d->family, "rkn") == 0;
    d->processed = strcmp(d->family, "processed") == 0;
    char *kernel = NULL;
    int rc = read_string(&kernel, L, "kernel", d->processed, path, err);
    if (rc == VIGEN_OK && kernel && !d->processed)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: kernel: only a processed design has a kernel", path);
    else if (rc == VIGEN_OK && kernel && strcmp(kernel, "splitting") != 0 && strcmp(kernel, "rkn") != 0)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: kernel: must be \"splitting\" (separable H) or \"rkn\" "
                             "(Nystrom H); a processed composition of a symmetric base gains nothing at effective "
                             "order 4", path);
    if (rc == VIGEN_OK && kernel) d->nystrom = strcmp(kernel, "rkn") == 0;
    free(kernel);
    return rc;
}

/* What `minimize` may name: the checker's constant of one family, or the
 * effective error (that constant times the forces per step to the power
 * of the order: the error at equal work). */
static const struct {
    const char *name;
    int family, effective;
} criteria[] = {
    {"error_constant", VIGEN_CHECK_EC_GENERAL, 0},
    {"error_constant_separable", VIGEN_CHECK_EC_SEPARABLE, 0},
    {"error_constant_nystrom", VIGEN_CHECK_EC_NYSTROM, 0},
    {"effective_error", VIGEN_CHECK_EC_GENERAL, 1},
    {"effective_error_separable", VIGEN_CHECK_EC_SEPARABLE, 1},
    {"effective_error_nystrom", VIGEN_CHECK_EC_NYSTROM, 1},
};

static int read_criterion(vigen_design_spec *d)
{
    for (size_t i = 0; i < sizeof criteria / sizeof *criteria; i++)
        if (strcmp(d->minimize, criteria[i].name) == 0) {
            d->minimize_family = criteria[i].family;
            d->minimize_effective = criteria[i].effective;
            return 1;
        }
    return 0;
}

/* processed: what design handles (after every field is read) */
static int check_processed(const vigen_design_spec *d, const char *path, vigen_error *err)
{
    if (!d->processed) return VIGEN_OK;
    if (!d->symmetric)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: symmetric: a processed kernel must be symmetric (symmetric = "
                               "true)", path);
    if (d->order != 4)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: order: the effective order of a processed kernel must be 4 "
                               "(design handles effective order 4)", path);
    if (d->stationary || d->nnearest > 0)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: a processed design asks solutions = \"all\" or minimize "
                               "(the criterion would need the corrector's conditions too)", path,
                               d->stationary ? "stationary" : "nearest");
    return VIGEN_OK;
}

/* The unknown named (a<i>, b<i> of a splitting: the i-th distinct drift or
 * kick; gamma<i> of a composition), or -1. */
static long fix_unknown(const vigen_design_spec *d, const char *name)
{
    int splitting = strcmp(d->family, "composition") != 0;
    const char *digits = splitting ? name + 1 : name + 5;
    if (splitting ? (name[0] != 'a' && name[0] != 'b') : strncmp(name, "gamma", 5) != 0) return -1;
    if (*digits < '1' || *digits > '9' || strspn(digits, "0123456789") != strlen(digits) || strlen(digits) > 3)
        return -1;
    long i = atol(digits) - 1;
    long kicks = d->stages, drifts = d->symmetric ? (kicks + 2) / 2 : kicks + 1;
    long nk = d->symmetric ? (kicks + 1) / 2 : kicks, ng = d->symmetric ? (kicks + 1) / 2 : kicks;
    if (!splitting) return i < ng ? i : -1;
    if (name[0] == 'a') return i < drifts ? i : -1;
    return i < nk ? drifts + i : -1;
}

/* equal = { {NAME, NAME}, ... }: pairs of unknowns tied, each pair one
 * linear condition (Suzuki's fractal composition ties gamma1 = gamma2). */
static int read_equal(vigen_design_spec *d, lua_State *L, const char *path, vigen_error *err)
{
    push_raw(L, "equal");
    int rc = VIGEN_OK;
    if (!lua_isnil(L, -1) && !lua_istable(L, -1))
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: equal: must be a list of pairs { {\"gamma1\", \"gamma2\"} }",
                             path);
    for (lua_Integer i = 1; rc == VIGEN_OK && lua_istable(L, -1) && i <= (lua_Integer)lua_rawlen(L, -1); i++) {
        lua_rawgeti(L, -1, i);
        long j[2] = {-1, -1};
        int pair = lua_istable(L, -1) && lua_rawlen(L, -1) == 2;
        for (int e = 0; pair && e < 2; e++) {
            lua_rawgeti(L, -1, e + 1);
            if (lua_type(L, -1) == LUA_TSTRING) j[e] = fix_unknown(d, lua_tostring(L, -1));
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
        if (!pair || j[0] < 0 || j[1] < 0 || j[0] == j[1])
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: equal: entry %ld must be a pair of two different unknowns "
                                 "of this family (%s)", path, (long)i, strcmp(d->family, "composition") != 0
                                 ? "a1, a2, ... the drifts, b1, b2, ... the kicks" : "gamma1, gamma2, ...");
        else {
            d->equal_unknown = realloc(d->equal_unknown, (size_t)(2 * d->nequal + 2) * sizeof(long));
            d->equal_unknown[2 * d->nequal] = j[0];
            d->equal_unknown[2 * d->nequal + 1] = j[1];
            d->nequal++;
        }
    }
    lua_pop(L, 1);
    return rc;
}

/* fix = { NAME = "p/q", ... }: unknowns held at exact rationals (keys in
 * sorted order, so that the conditions are the same from run to run). */
static int read_fix(vigen_design_spec *d, lua_State *L, const char *path, vigen_error *err)
{
    push_raw(L, "fix");
    int rc = VIGEN_OK;
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        return VIGEN_OK;
    }
    if (!lua_istable(L, -1)) rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: fix: must be a table { b1 = \"-3/73\", "
                                                  "... }", path);
    for (lua_pushnil(L); rc == VIGEN_OK && lua_next(L, -2); lua_pop(L, 1)) {
        const char *key = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : NULL;
        long j = key ? fix_unknown(d, key) : -1;
        fmpq_t v;
        fmpq_init(v);
        const char *val = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : NULL;
        int ok = val && *val && strspn(val, "-0123456789/") == strlen(val) && fmpq_set_str(v, val, 10) == 0 &&
                 !fmpz_is_zero(fmpq_denref(v));
        fmpq_clear(v);
        if (j < 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: fix: %s%s%s is not an unknown of this family (%s)", path,
                                 key ? "'" : "", key ? key : "a key that is not a name", key ? "'" : "",
                                 strcmp(d->family, "composition") != 0 ? "a1, a2, ... the drifts, b1, b2, ... the "
                                 "kicks, the first half when symmetric" : "gamma1, gamma2, ...");
        else if (!ok)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: fix: %s: must be an exact rational as a string, such as "
                                 "\"-3/73\"", path, key);
        else {
            d->fix_name = realloc(d->fix_name, (size_t)(d->nfix + 1) * sizeof(char *));
            d->fix_value = realloc(d->fix_value, (size_t)(d->nfix + 1) * sizeof(char *));
            d->fix_unknown = realloc(d->fix_unknown, (size_t)(d->nfix + 1) * sizeof(long));
            long at = d->nfix++;
            while (at > 0 && d->fix_unknown[at - 1] > j) {
                d->fix_name[at] = d->fix_name[at - 1];
                d->fix_value[at] = d->fix_value[at - 1];
                d->fix_unknown[at] = d->fix_unknown[at - 1];
                at--;
            }
            d->fix_name[at] = vigen_strdup(key);
            d->fix_value[at] = vigen_strdup(val);
            d->fix_unknown[at] = j;
        }
    }
    if (rc != VIGEN_OK) lua_pop(L, 1);   /* the key lua_next left */
    lua_pop(L, 1);
    return rc;
}

/* A flow name: letters, digits and '_' (it is written into the method file). */
static int flow_name_ok(const char *s)
{
    if (*s == 0) return 0;
    for (; *s; s++)
        if (!(*s == '_' || (*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9')))
            return 0;
    return 1;
}

/* flows = {A, B}, perturbation = B, generalized_order = {r1, ..., rk}: a
 * splitting of two named flows for H = A + eps B, its conditions the Lyndon
 * words with j letters B of length <= r_j (docs/design.md).  Read after
 * order, which may then be absent; with both, r_j is at least order. */
static int read_flows(vigen_design_spec *d, lua_State *L, int order_given, const char *path, vigen_error *err)
{
    int rc = VIGEN_OK;
    push_raw(L, "flows");
    int has_flows = !lua_isnil(L, -1);
    const char *name[2] = {NULL, NULL};
    if (has_flows) {
        int ok = lua_istable(L, -1) && lua_rawlen(L, -1) == 2;
        for (int i = 0; ok && i < 2; i++) {
            lua_rawgeti(L, -1, i + 1);
            name[i] = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : NULL;
            if (name[i] && flow_name_ok(name[i])) d->flow_a = d->flow_a ? d->flow_a : vigen_strdup(name[i]);
            else ok = 0;
            if (ok && i == 1) {
                d->flow_b = vigen_strdup(name[i]);
                ok = strcmp(d->flow_a, d->flow_b) != 0;
            }
            lua_pop(L, 1);
        }
        if (!ok)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: flows: must be a list of two different flow names (letters, "
                                 "digits and '_'), e.g. flows = { \"kepler\", \"interaction\" }", path);
        else if (strcmp(d->family, "splitting") != 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: flows: only a design = \"splitting\" splits named flows",
                                 path);
    }
    lua_pop(L, 1);
    char *pert = NULL;
    if (rc == VIGEN_OK) rc = read_string(&pert, L, "perturbation", has_flows, path, err);
    if (rc == VIGEN_OK && pert && !has_flows)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: perturbation: names one of the flows; give flows = { A, B }",
                             path);
    else if (rc == VIGEN_OK && pert && strcmp(pert, d->flow_a) != 0 && strcmp(pert, d->flow_b) != 0)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: perturbation: '%s' is not one of the flows (%s, %s)", path, pert,
                             d->flow_a, d->flow_b);
    else if (rc == VIGEN_OK && pert && strcmp(pert, d->flow_a) == 0) {
        /* B, the kick letter of the family, is the perturbation */
        char *t = d->flow_a;
        d->flow_a = d->flow_b;
        d->flow_b = t;
        d->flows_first_b = 1;
    }
    free(pert);
    push_raw(L, "generalized_order");
    if (rc == VIGEN_OK && !lua_isnil(L, -1)) {
        lua_Integer n = lua_istable(L, -1) ? (lua_Integer)lua_rawlen(L, -1) : 0;
        int ok = n >= 1 && n <= VIGEN_DESIGN_MAX_GENERALIZED;
        for (lua_Integer i = 1; ok && i <= n; i++) {
            lua_rawgeti(L, -1, i);
            ok = lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 &&
                 lua_tointeger(L, -1) <= VIGEN_DESIGN_MAX_ORDER;
            if (ok) d->generalized[d->ngeneralized++] = (int)lua_tointeger(L, -1);
            lua_pop(L, 1);
        }
        if (!ok)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: generalized_order: must be a list of 1 to %d whole numbers "
                                 "from 1 to %d, e.g. {6, 2}", path, VIGEN_DESIGN_MAX_GENERALIZED,
                                 VIGEN_DESIGN_MAX_ORDER);
        else if (!has_flows)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: generalized_order: needs flows = { A, B } and perturbation "
                                 "= B (the flow that carries eps)", path);
    }
    lua_pop(L, 1);
    if (rc != VIGEN_OK) return rc;
    if (d->ngeneralized > 0) {
        int p = 0;
        for (int j = 0; j < d->ngeneralized; j++) {
            if (order_given && d->generalized[j] < d->order) d->generalized[j] = d->order;
            if (d->generalized[j] > p) p = d->generalized[j];
        }
        d->order = p;                /* the conditions are built to this degree */
    }
    return VIGEN_OK;
}

static int read_fields(vigen_design_spec *d, lua_State *L, const char *path, vigen_error *err)
{
    static const char *const known[] = {"name", "design", "base", "stages", "order", "symmetric", "solutions",
                                        "minimize", "starts", "seed", "screen", "homotopy", "description", "stationary",
                                        "nearest", "first", "kernel", "fix", "equal", "flows", "perturbation",
                                        "generalized_order", NULL};
    int rc = vigen_table_check_fields(L, known, path, err);
    if (rc == VIGEN_OK) rc = read_string(&d->name, L, "name", 1, path, err);
    if (rc == VIGEN_OK) {
        for (const char *c = d->name; *c; c++)
            if (!(*c == '_' || (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9')))
                return vigen_error_set(err, VIGEN_E_SPEC, "%s: name: must be letters, digits and '_' (it names the "
                                       "files written, NAME_k.lua)", path);
    }
    if (rc == VIGEN_OK) rc = read_string(&d->family, L, "design", 1, path, err);
    if (rc == VIGEN_OK && strcmp(d->family, "composition") != 0 && strcmp(d->family, "splitting") != 0 &&
        strcmp(d->family, "rkn") != 0 && strcmp(d->family, "processed") != 0)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: design: unknown family '%s' (families: composition, "
                               "splitting, rkn, processed)", path, d->family);
    int splitting = rc == VIGEN_OK && strcmp(d->family, "composition") != 0;
    if (rc == VIGEN_OK) rc = read_kernel(d, L, path, err);
    if (rc == VIGEN_OK) rc = read_string(&d->base, L, "base", !splitting, path, err);
    if (rc == VIGEN_OK && splitting && d->base)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: base: a splitting has no base (its kicks and drifts are the "
                               "unknowns; stages is the number of kicks)", path);
    long v = 0;
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "stages", 1, 0, 1, MAX_DESIGN_STAGES, path, err)) == VIGEN_OK)
        d->stages = (int)v;
    push_raw(L, "order");
    int order_given = !lua_isnil(L, -1);
    lua_pop(L, 1);
    push_raw(L, "generalized_order");
    int order_required = lua_isnil(L, -1);
    lua_pop(L, 1);
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "order", order_required, 0, 1, 1000, path, err)) == VIGEN_OK)
        d->order = (int)v;
    if (rc == VIGEN_OK) rc = read_flows(d, L, order_given, path, err);
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "starts", 0, 0, 1, MAX_STARTS, path, err)) == VIGEN_OK)
        d->starts = v;
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "seed", 0, 1, 0, 2147483647L, path, err)) == VIGEN_OK)
        d->seed = (unsigned long)v;
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "screen", 0, 0, 1, MAX_SCREEN, path, err)) == VIGEN_OK)
        d->screen = v;
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "homotopy", 0, VIGEN_DESIGN_HOMOTOPY_PATHS, 0, MAX_HOMOTOPY, path,
                                           err)) == VIGEN_OK)
        d->homotopy = v;
    if (rc == VIGEN_OK) {
        push_raw(L, "symmetric");
        if (lua_isnil(L, -1)) d->symmetric = 0;
        else if (lua_isboolean(L, -1)) d->symmetric = lua_toboolean(L, -1);
        else rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: symmetric: must be true or false", path);
        lua_pop(L, 1);
    }
    char *solutions = NULL;
    if (rc == VIGEN_OK) rc = read_string(&solutions, L, "solutions", 0, path, err);
    if (rc == VIGEN_OK) rc = read_string(&d->minimize, L, "minimize", 0, path, err);
    if (rc == VIGEN_OK) rc = design_file_read_criterion(d, L, splitting, path, err);
    if (rc == VIGEN_OK) {
        int asked = (solutions != NULL) + (d->minimize != NULL) + (d->stationary != NULL) + (d->nnearest > 0);
        if (asked > 1)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: solutions, minimize, stationary and nearest: give one of "
                                 "them", path);
        else if (asked == 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: what is wanted? give solutions = \"all\" or minimize = "
                                 "\"error_constant\"", path);
        else if (solutions && strcmp(solutions, "all") != 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: solutions: must be \"all\"", path);
        else if (d->minimize && !read_criterion(d))
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: minimize: must be \"error_constant\" (general H), "
                                 "\"error_constant_separable\", \"error_constant_nystrom\" or "
                                 "\"effective_error\" (and _separable, _nystrom: the constant times the forces "
                                 "per step to the power order)", path);
        else if (d->screen > 0 && d->minimize == NULL)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: screen: only a minimize design screens points", path);
        d->goal = d->minimize ? VIGEN_DESIGN_MINIMIZE : VIGEN_DESIGN_ALL;
        d->starts_asked = d->starts;
        if (d->starts == 0)
            d->starts = d->goal == VIGEN_DESIGN_MINIMIZE ? DEFAULT_MINIMIZE_STARTS : VIGEN_DESIGN_DEFAULT_STARTS;
    }
    free(solutions);
    if (rc == VIGEN_OK) rc = read_fix(d, L, path, err);
    if (rc == VIGEN_OK) rc = read_equal(d, L, path, err);
    if (rc == VIGEN_OK) rc = check_processed(d, path, err);
    if (rc == VIGEN_OK && d->flow_b && (d->goal != VIGEN_DESIGN_ALL || d->stationary || d->nnearest > 0))
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: flows: a splitting of named flows asks solutions = \"all\" "
                             "(its error is measured by the generalized order, not one error constant)", path);
    return rc;
}

int vigen_design_read(vigen_design_spec *d, const char *path, vigen_error *err)
{
    memset(d, 0, sizeof *d);
    vigen_sandbox *sb = NULL;
    int rc = vigen_sandbox_new(&sb, NULL, NULL, err);
    if (rc == VIGEN_OK) rc = vigen_sandbox_run_file(sb, path, err);
    if (rc == VIGEN_OK) {
        lua_State *L = vigen_sandbox_state(sb);
        vigen_sandbox_lift_memory_cap(sb);
        if (!lua_istable(L, -1) || lua_getmetatable(L, -1))
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: the file must return a plain table { name = ..., design = "
                                 "\"composition\", ... }", path);
        else rc = read_fields(d, L, path, err);
    }
    vigen_sandbox_free(sb);
    if (rc == VIGEN_OK) d->path = vigen_strdup(path);
    else vigen_design_spec_clear(d);
    return rc;
}
