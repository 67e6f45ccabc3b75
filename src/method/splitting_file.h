/* splitting_file.h — reading splitting and composition files: methods
 * written as published, a sequence of kicks and drifts, or a base method
 * composed with steps gamma_i h.  The conversion to a PRK tableau is
 * method/splitting.c. */
#ifndef VIGEN_METHOD_SPLITTING_FILE_H
#define VIGEN_METHOD_SPLITTING_FILE_H

#include <lua.h>
#include "lua/sandbox.h"
#include "vigen/tableau.h"

/* 1 when the value at idx is a table with a `splitting` (resp.
 * `composition`) field.  Raw reads. */
int vigen_splitting_file_detect(lua_State *L, int idx);
int vigen_composition_file_detect(lua_State *L, int idx);

/* A splitting: the kernel's substeps in order of application, and an
 * optional corrector.
 *
 * Kick/drift files (no `flows`): substep k is a drift (q <- q + coef h dT/dp)
 * when drift[k], else a kick (p <- p - coef h dV/dq); named = 0, and the
 * flow fields describe the same substeps with the two flows "drift" (index
 * 0) and "kick" (index 1), so that a reader may treat both kinds alike.
 *
 * Files with `flows = {"kepler", "interaction", ...}` (named = 1): substep k
 * advances by coef[k] h the flow flow_names[flow[k]] (the exact flow of one
 * part of H, or a stated approximation of it).  For two flows drift[k] =
 * (flow[k] == 0): the first flow takes the place of the drift (the letter A
 * of the checker), the second that of the kick (B); with three or more flows
 * drift[] is all 0 and means nothing.
 *
 * A processed method (`corrector = {...}`, ncorrector > 0): the corrector C
 * is the composition of its substeps in order of application (flow
 * corrector_flow[k] by corrector_coef[k] h), and one step of the method is
 * C, then the kernel K, then C^-1, which is C's substeps in reverse order
 * with their coefficients negated (each flow is a one-parameter group).
 * Over n steps the inner C^-1 C cancel: C once before the first step, n
 * kernel steps, and C^-1 wherever the state is output.
 *
 * Bracket flows (`brackets = { G = {"kepler", "interaction", "interaction"} }`):
 * flow G is the Hamiltonian {{kepler, interaction}, interaction}, the
 * left-nested Poisson bracket of its letters ({F, G} = F_q G_p - F_p G_q),
 * and its substep advances its exact flow by coef h^k, k its letters.  A
 * file with brackets has exactly two plain flows, the first two of `flows`
 * (flow_degree 1, flow_bracket NULL); every other flow is a bracket whose
 * letters are those two.  The arrays are set for every file (all plain
 * without brackets). */
typedef struct {
    slong n;               /* substeps of the kernel */
    int *drift;            /* [n] kick/drift files: 1 drift, 0 kick; two named flows: flow[k] == 0 */
    char **coef;           /* [n] coefficient texts (entries: exact expressions or decimals) */
    int named;             /* 1: the file has `flows`; 0: a kick/drift file */
    slong nflows;          /* number of flows (>= 2) */
    char **flow_names;     /* [nflows] in the order of `flows` ({"drift", "kick"} for kick/drift files) */
    int *flow;             /* [n] the flow of substep k, an index into flow_names */
    int perturbation;      /* index of the flow that carries epsilon in H = A + eps B: `perturbation`
                            * of the file, else the second flow (1) */
    slong ncorrector;      /* substeps of the corrector; 0: not a processed method */
    int *corrector_flow;   /* [ncorrector] flow indices */
    char **corrector_coef; /* [ncorrector] coefficient texts */
    int ngeneralized;      /* claim generalized_order = {r1, ..., rk}: k entries, 0 when absent */
    int generalized[VIGEN_MAX_GENERALIZED];
    int *flow_degree;      /* [nflows] 1 for a plain flow, k for a bracket of k letters: its substep
                            * advances it by coef h^k */
    int **flow_bracket;    /* [nflows] NULL for a plain flow, else flow_degree[j] indices of plain flows,
                            * the left-nested bracket */
} vigen_splitting;

void vigen_splitting_clear(vigen_splitting *sp);

/* Reads the table on top of sb's stack (the file has run): info (name,
 * source, description, claims order, symplectic, ...) into info (initialised by the caller with
 * vigen_tableau_init(info, 1)), the substeps into sp.  Messages name the
 * file and the entry (splitting[3][2], corrector[2][1], flows[3],
 * brackets.G[2]): unknown flow names, repeated flows, fewer than two flows,
 * a corrector that is not a list of {FLOW, coef}, a bracket of one letter,
 * a letter that is not a plain flow, brackets without flows. */
int vigen_splitting_from_table(vigen_splitting *sp, vigen_tableau *info, vigen_sandbox *sb, const char *path,
                               vigen_error *err);

/* A composition: base (a file or a method name, as written) and the step
 * fractions gamma[0 .. m-1]. */
typedef struct {
    char *base;
    slong m;
    char **gamma;
} vigen_composition;

void vigen_composition_clear(vigen_composition *co);
int vigen_composition_from_table(vigen_composition *co, vigen_tableau *info, vigen_sandbox *sb, const char *path,
                                 vigen_error *err);

#endif
