/* spec.h — method spec files: what the user asks the generator for.
 *
 * A spec file (tableaux/specs/NAME.lua) is a Lua chunk returning a table:
 *   name        string (required)
 *   description string (optional)
 *   source      string (optional; where the method comes from)
 *   nodes       list of exact expression strings or Lua integers, e.g.
 *               {"0", "1/2 - sqrt(3)/6"}, or a node family, e.g. gauss_legendre(3)
 *   basis       "lagrange", a family (monomials(s), trig(s), legendre(s),
 *               chebyshev_t(s)), or a list of expression strings in t
 *               ("cos(pi*t)") and/or Lua functions of a ball t
 * Lua floats are refused everywhere with a message naming the entry.
 */
#ifndef VIGEN_SPEC_H
#define VIGEN_SPEC_H

#include <acb.h>
#include "vigen/error.h"
#include "core/expr.h"
#include "lua/sandbox.h"
#include "vigen/limits.h"

enum { VIGEN_SPEC_NODES_LIST, VIGEN_SPEC_NODES_FAMILY };
enum { VIGEN_SPEC_BASIS_LAGRANGE, VIGEN_SPEC_BASIS_FAMILY, VIGEN_SPEC_BASIS_LIST };
enum { VIGEN_SPEC_ITEM_EXPR, VIGEN_SPEC_ITEM_LUA };

typedef struct {
    int kind;            /* VIGEN_SPEC_ITEM_EXPR or VIGEN_SPEC_ITEM_LUA */
    vigen_expr *expr;    /* ITEM_EXPR: parsed with t allowed */
    int lua_ref;         /* ITEM_LUA: registry reference to the function */
    char *label;         /* "cos(pi*t)" or "<Lua function, basis[3]>" */
} vigen_spec_basis_item;

typedef struct {
    char *path;
    char *name, *description, *source;
    int claim_order;             /* order = p stated by the spec (checked at generation), -1 when absent */

    int nodes_kind;
    slong s;                     /* number of nodes */
    vigen_expr **node_exprs;     /* NODES_LIST: s constant expressions */
    char *node_family;           /* NODES_FAMILY: "gauss_legendre", ... */

    int basis_kind;
    char *basis_family;          /* BASIS_FAMILY: a name of basis.def, e.g. "trig" */
    slong basis_count;           /* number of basis functions (family s, list length, or s for lagrange) */
    vigen_spec_basis_item *items;/* BASIS_LIST: basis_count items */

    /* Lua-readable descriptions for tableau metadata, e.g. `gauss_legendre(3)`,
     * `{"0", "1/2", "1"}`, `"lagrange"`, `trig(5)`, `{"1", "cos(pi*t)", "<Lua function>"}`. */
    char *nodes_text, *basis_text;

    vigen_sandbox *sandbox;      /* kept alive for Lua basis functions */
} vigen_spec;

/* 1 if the value at idx looks like a spec (a table with nodes or basis),
 * else 0.  Raw reads; may raise only "not enough memory" (call it protected). */
int vigen_spec_detect(lua_State *L, int idx);

/* Reads and validates the spec that the file at path returned: the value on
 * top of sb's stack (vigen_sandbox_run_file).  Takes sb: the spec keeps it
 * alive for its Lua basis functions, and it is freed on failure.  Unknown
 * fields of the spec table are warned about (vigen_warn), not refused.
 * Messages start with "PATH: " and name the field ("nodes[2]", "basis[3]"), e.g.
 *   spec.lua: nodes[2] is the Lua float 0.3333333333333333; write the exact string "1/3"
 *   spec.lua:4: unknown name 'gauss' (node families: gauss_legendre, ...)
 *   spec.lua: nodes: unknown node family 'gaus' (known: gauss_legendre, ...)
 * The checks needing arithmetic (repeated nodes, singular M) belong to galerkin.c. */
int vigen_spec_from_table(vigen_spec **out, vigen_sandbox *sb, const char *path, vigen_error *err);
/* The same for a file not run yet: a fresh sandbox with these limits, the
 * file run once, then vigen_spec_from_table. */
int vigen_spec_load(vigen_spec **out, const char *path, const vigen_sandbox_limits *limits,
                    vigen_error *err);
void vigen_spec_free(vigen_spec *spec);

/* Evaluates Lua basis item `index` (0-based) at t (an expression item of the
 * list is evaluated with vigen_expr_eval_acb); contract as
 * vigen_expr_eval_acb (indeterminate result when analytic and not certainly
 * holomorphic).  A Lua error or a non-ball return value is reported through err
 * with the path and basis index. */
int vigen_spec_call_basis(acb_t res, vigen_spec *spec, slong index, const acb_t t, int analytic,
                          slong prec, vigen_error *err);

#endif
