/* problems.c — the registry of the problem collection (expanded from
 * problems.def), the parameter parser ("k=v,k=v") and the problem-independent
 * part of <vigen/problems.h>: creation, queries, invariants, reference. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "problems_internal.h"

typedef struct {
    double min, max;
    int integer;
} param_range;

/* Each row's parameters (a sentinel ends every list, so that a problem
 * without parameters still has a valid array), their ranges, and the table
 * of vigen_problem_info. */
#define PARAM(name, def, lo, hi, integer, description) { name, def, description },
#define PROBLEM(id, name, description, ...)                                            \
    static const vigen_problem_param params_##id[] = { __VA_ARGS__ { NULL, 0, NULL } }; \
    _Static_assert(sizeof params_##id / sizeof params_##id[0] <= PBI_MAX_PARAMS + 1,    \
                   "too many parameters for vigen_problem.param");
#include "problems.def"
#undef PROBLEM
#undef PARAM

#define PARAM(name, def, lo, hi, integer, description) { lo, hi, integer },
#define PROBLEM(id, name, description, ...) \
    static const param_range ranges_##id[] = { __VA_ARGS__ { 0, 0, 0 } };
#include "problems.def"
#undef PROBLEM
#undef PARAM

typedef struct {
    vigen_problem_info info;
    const param_range *ranges;
    int (*setup)(vigen_problem *pb);
} problem_row;

#define PARAM(...)
#define PROBLEM(id, name, description, ...)                                                   \
    { { name, description, params_##id,                                                    \
        sizeof params_##id / sizeof params_##id[0] - 1 },                                  \
      ranges_##id, vigen_pbi_##id##_setup },
static const problem_row problems[] = {
#include "problems.def"
};
#undef PROBLEM
#undef PARAM

enum { NPROBLEMS = sizeof problems / sizeof problems[0] };

size_t vigen_problem_count(void) { return NPROBLEMS; }

const vigen_problem_info *vigen_problem_info_at(size_t i)
{
    return i < NPROBLEMS ? &problems[i].info : NULL;
}

static const problem_row *row_find(const char *name)
{
    for (size_t i = 0; name != NULL && i < NPROBLEMS; i++)
        if (strcmp(problems[i].info.name, name) == 0) return &problems[i];
    return NULL;
}

const vigen_problem_info *vigen_problem_info_find(const char *name)
{
    const problem_row *row = row_find(name);
    return row ? &row->info : NULL;
}

static int fail(char *why, size_t why_size, const char *fmt, ...)
{
    if (why != NULL && why_size > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(why, why_size, fmt, ap);
        va_end(ap);
    }
    return VIGEN_EINVAL;
}

/* "e, n" — the parameter names of a row, for messages. */
static void param_names(const problem_row *row, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (size_t k = 0; k < row->info.nparams && used < size; k++)
        used += (size_t)snprintf(out + used, size - used, "%s%s", k ? ", " : "", row->info.params[k].name);
    if (row->info.nparams == 0) snprintf(out, size, "none");
}

/* Parses "k=v,k=v" into values[] (defaults first); spaces around names and
 * values are allowed. */
static int parse_params(const problem_row *row, const char *text, double *values, char *why,
                        size_t why_size)
{
    const vigen_problem_info *info = &row->info;
    int seen[PBI_MAX_PARAMS] = { 0 };
    for (size_t k = 0; k < info->nparams; k++) values[k] = info->params[k].default_value;
    if (text == NULL) return VIGEN_SUCCESS;
    char names[200];
    param_names(row, names, sizeof names);
    const char *s = text;
    while (*s != '\0') {
        const char *end = strchr(s, ',');
        size_t len = end ? (size_t)(end - s) : strlen(s);
        char item[128];
        if (len >= sizeof item)
            return fail(why, why_size, "problem '%s': parameter '%.40s...' is too long", info->name, s);
        memcpy(item, s, len);
        item[len] = '\0';
        s = end ? end + 1 : s + len;
        char *key = item;
        while (*key == ' ') key++;
        if (*key == '\0') continue;   /* empty item: "e=0.9," */
        char *eq = strchr(key, '=');
        if (eq == NULL)
            return fail(why, why_size, "problem '%s': parameter '%s' is not NAME=VALUE (parameters: %s)",
                        info->name, key, names);
        char *kend = eq;
        while (kend > key && kend[-1] == ' ') kend--;
        *kend = '\0';
        size_t k = 0;
        while (k < info->nparams && strcmp(info->params[k].name, key) != 0) k++;
        if (k == info->nparams)
            return fail(why, why_size, "problem '%s': unknown parameter '%s' (parameters: %s)", info->name,
                        key, names);
        if (seen[k])
            return fail(why, why_size, "problem '%s': parameter '%s' given twice", info->name, key);
        seen[k] = 1;
        const char *vtext = eq + 1;
        while (*vtext == ' ') vtext++;
        char *vend;
        errno = 0;
        double v = strtod(vtext, &vend);
        while (*vend == ' ') vend++;
        if (vend == vtext || *vend != '\0' || errno == ERANGE || !isfinite(v))
            return fail(why, why_size, "problem '%s': parameter %s = '%s' is not a finite number", info->name,
                        key, vtext);
        const param_range *r = &row->ranges[k];
        if (r->integer && v != floor(v))
            return fail(why, why_size, "problem '%s': parameter %s = %s is not an integer (%s)", info->name, key,
                        vtext, info->params[k].description);
        if (!(v >= r->min && v <= r->max))
            return fail(why, why_size, "problem '%s': parameter %s = %s is out of range (%s)", info->name, key,
                        vtext, info->params[k].description);
        values[k] = v;
    }
    return VIGEN_SUCCESS;
}

int vigen_problem_create(vigen_problem **out, const char *name, const char *params, char *why,
                         size_t why_size)
{
    if (why != NULL && why_size > 0) why[0] = '\0';
    if (out == NULL) return fail(why, why_size, "vigen_problem_create: no place for the problem (out is NULL)");
    *out = NULL;
    const problem_row *row = row_find(name);
    if (row == NULL) {
        char list[400];
        size_t used = 0;
        for (size_t i = 0; i < NPROBLEMS && used < sizeof list; i++)
            used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "",
                                     problems[i].info.name);
        return fail(why, why_size, "unknown problem '%s' (problems: %s)", name ? name : "(null)", list);
    }
    vigen_problem *pb = calloc(1, sizeof *pb);
    if (pb == NULL) return VIGEN_ENOMEM;
    pb->info = &row->info;
    int st = parse_params(row, params, pb->param, why, why_size);
    if (st == VIGEN_SUCCESS) st = row->setup(pb);
    if (st == VIGEN_SUCCESS && (pb->q0 == NULL || pb->p0 == NULL)) st = VIGEN_ENOMEM;
    if (st != VIGEN_SUCCESS) {
        if (st == VIGEN_ENOMEM) fail(why, why_size, "problem '%s': out of memory", row->info.name);
        else if (why != NULL && why_size > 0 && why[0] == '\0')
            fail(why, why_size, "problem '%s': cannot be set up with these parameters", row->info.name);
        vigen_problem_free(pb);
        return st;
    }
    pb->ham.dim = pb->dim;
    pb->ham.ctx = pb;
    if (pb->lag.dim != 0) pb->lag.ctx = pb;
    *out = pb;
    return VIGEN_SUCCESS;
}

void vigen_problem_free(vigen_problem *pb)
{
    if (pb == NULL) return;
    free(pb->q0);
    free(pb->p0);
    free(pb->data);
    vigen_nbody_free(pb->nbody);
    free(pb);
}

const vigen_problem_info *vigen_problem_info_of(const vigen_problem *pb) { return pb->info; }

double vigen_problem_param_value(const vigen_problem *pb, const char *name)
{
    for (size_t k = 0; name != NULL && k < pb->info->nparams; k++)
        if (strcmp(pb->info->params[k].name, name) == 0) return pb->param[k];
    return NAN;
}

size_t vigen_problem_dim(const vigen_problem *pb) { return pb->dim; }

const vigen_hamiltonian *vigen_problem_hamiltonian(const vigen_problem *pb) { return &pb->ham; }

const vigen_lagrangian *vigen_problem_lagrangian(const vigen_problem *pb, vigen_lgrad_fn *g)
{
    if (pb->lag.dim == 0) {
        if (g != NULL) *g = NULL;
        return NULL;
    }
    if (g != NULL) *g = pb->legendre_inverse;
    return &pb->lag;
}

void vigen_problem_initial(const vigen_problem *pb, double *t, double *q, double *p)
{
    *t = pb->t0;
    memcpy(q, pb->q0, pb->dim * sizeof *q);
    memcpy(p, pb->p0, pb->dim * sizeof *p);
}

double vigen_problem_period(const vigen_problem *pb) { return pb->period; }
double vigen_problem_default_time(const vigen_problem *pb) { return pb->default_time; }

double vigen_problem_energy(const vigen_problem *pb, double t, const double *q, const double *p)
{
    return pb->ham.H(t, q, p, pb->ham.ctx);
}

size_t vigen_problem_invariant_count(const vigen_problem *pb) { return pb->ninvariants; }

const char *vigen_problem_invariant_name(const vigen_problem *pb, size_t k)
{
    return k < pb->ninvariants ? pb->invariant_names[k] : NULL;
}

double vigen_problem_invariant(const vigen_problem *pb, size_t k, double t, const double *q,
                               const double *p)
{
    return k < pb->ninvariants ? pb->invariant(pb, k, t, q, p) : NAN;
}

int vigen_problem_reference(const vigen_problem *pb, double t, double *q, double *p)
{
    if (pb->reference == NULL || !isfinite(t)) return 0;
    return pb->reference(pb, t, q, p);
}

/* The coordinates by name: NULL or "jacobi", "democratic-heliocentric". */
static int coordinates_code(const char *name)
{
    if (name == NULL || strcmp(name, "jacobi") == 0) return VIGEN_NBODY_JACOBI;
    if (strcmp(name, "democratic-heliocentric") == 0) return VIGEN_NBODY_DEMOCRATIC;
    return -1;
}

int vigen_problem_split(vigen_problem *pb, const char *coordinates, vigen_split_problem *out, char *why,
                        size_t why_size)
{
    if (why != NULL && why_size > 0) why[0] = '\0';
    if (pb == NULL || out == NULL) return fail(why, why_size, "vigen_problem_split: NULL problem or result");
    if (pb->split == NULL)
        return fail(why, why_size, "problem '%s' has no Kepler splitting (problems with one: kepler, "
                    "outer-solar-system, jupiter-saturn)", pb->info->name);
    int coords = coordinates_code(coordinates);
    if (coords < 0)
        return fail(why, why_size, "unknown coordinates '%s' (coordinates: jacobi, democratic-heliocentric)",
                    coordinates);
    if (pb->split(pb, coords, out) != VIGEN_SUCCESS)
        return fail(why, why_size, "problem '%s' offers no splitting in %s coordinates", pb->info->name,
                    coordinates);
    pb->split_coords = coords;
    return VIGEN_SUCCESS;
}

const char *vigen_problem_split_flow_name(const vigen_problem *pb, size_t k)
{
    return pb != NULL && pb->split != NULL ? vigen_nbody_flow_name(pb->split_coords, k) : NULL;
}

int vigen_problem_split_state(const vigen_problem *pb, int to_split, const double *q, const double *p, double *qs,
                              double *ps)
{
    if (pb == NULL || pb->split_convert == NULL || !q || !p || !qs || !ps) return VIGEN_EINVAL;
    return pb->split_convert(pb, to_split, q, p, qs, ps);
}
