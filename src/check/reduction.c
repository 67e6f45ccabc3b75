/* reduction.c — which order conditions of a symplectic tableau follow from
 * others, so that orders.c evaluates one or two trees per class.
 *
 * Let u and v be bicoloured trees and u o v the tree made by grafting v onto
 * the root of u as a new child.  Phi(u o v) + Phi(v o u) is
 *   sum_ij Phi_i(u) Phi_j(v) (bhat_i m_ij + bhat'_j m'_ji),
 * bhat, bhat' the weights of the colours of u's and v's roots, m, m' the
 * matrices of the edges into v's root and into u's root.  When the bracket is
 * bhat_i bhat'_j the sum is Phi(u) Phi(v), and the exact values satisfy the
 * same identity 1/gamma(u o v) + 1/gamma(v o u) = 1/(gamma(u) gamma(v))
 * (gamma(u o v) = n gamma(u) gamma(v) / |u|).  So when every condition of
 * order < n (n = |u| + |v|) holds, r(u o v) = -r(v o u), r = Phi - 1/gamma:
 * one holds exactly when the other does (Abia & Sanz-Serna, Math. Comp. 60
 * (1993) 617-634: symplecticity acts as a simplifying assumption; the same
 * identity characterises symplectic P-series in Hairer, Lubich, Wanner,
 * Geometric Numerical Integration, sec. VI.7.2).  The bracket is the
 * symplecticity condition:
 *   roots of different colours   b_i at_ij + bt_j a_ji = b_i bt_j (the pair
 *                                conditions: b = bt is not needed);
 *   two black roots              b_i a_ij + b_j a_ji = b_i b_j, and two white
 *                                roots bt_i at_ij + bt_j at_ji = bt_i bt_j:
 *                                the RK symplecticity of one part, which the
 *                                pair conditions give when At = A and bt = b
 *                                entry by entry (the Gauss methods).
 * The rule: skip a tree of order n whose root has a child v with |v| > n/2
 * across an allowed edge (such a child is unique, and it is ids[0], the
 * largest id).  Rerooting at v gives a tree whose largest child has order
 * max(|v| - 1, n - |v|) < |v|, so following skips ends, at the same order, at
 * an evaluated tree whose residual is +-r of the skipped one.
 */
#include <stdlib.h>
#include "check/check_internal.h"

static int parts_identical(const ctx_t *cx)
{
    if (cx->At == cx->A && cx->bt == cx->b) return 1;
    for (slong i = 0; i < cx->s; i++) {
        if (!arb_equal(cx->b + i, cx->bt + i)) return 0;
        for (slong j = 0; j < cx->s; j++)
            if (!arb_equal(arb_mat_entry(cx->A, i, j), arb_mat_entry(cx->At, i, j))) return 0;
    }
    return 1;
}

void chk_reduction_init(chk_reduction *red, const vigen_check_report *rep, const ctx_t *cx)
{
    red->on = 0;
    red->within_data = 0;
    for (int a = 0; a < 2; a++)
        for (int c = 0; c < 2; c++) red->edge[a][c] = 0;
    /* every tree condition evaluated: for comparing verdicts with and without */
    const char *off = getenv("VIGEN_CHECK_NO_REDUCTION");
    if (off != NULL && *off != '\0' && *off != '0') return;
    if (rep->symplectic_separable != VIGEN_CHECK_YES) return;
    red->on = 1;
    red->within_data = rep->symplectic_within_data;
    red->edge[VIGEN_TREE_BLACK][VIGEN_TREE_WHITE] = red->edge[VIGEN_TREE_WHITE][VIGEN_TREE_BLACK] = 1;
    if (parts_identical(cx)) red->edge[VIGEN_TREE_BLACK][VIGEN_TREE_BLACK] = red->edge[VIGEN_TREE_WHITE][VIGEN_TREE_WHITE] = 1;
}

int chk_reduction_skips(const chk_reduction *red, const vigen_treeset *ts, int n, int colour, const slong *ids, int k)
{
    if (!red->on || k == 0) return 0;
    const vigen_tree *v = ts->trees + ids[0];
    return 2 * (int)v->order > n && red->edge[colour][v->colour];
}
