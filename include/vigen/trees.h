/* trees.h — bicoloured rooted trees: the index set of the order conditions of
 * partitioned Runge–Kutta methods (Hairer, Lubich, Wanner, Geometric Numerical
 * Integration, sec. III.2).
 *
 * A black vertex stands for the q equation (q' = dH/dp: matrix A, weights b), a
 * white vertex for the p equation (p' = -dH/dq: matrix At, weights bt).  A tree
 * is a root colour plus a multiset of child trees (a "forest"); its order is
 * its number of vertices and its density is gamma(t) = |t| prod gamma(u) over
 * the children u.
 *
 * Trees are numbered 0, 1, 2, ... by increasing order.  Within one order n the
 * forests of order n - 1 are enumerated by vigen_forest_iter (always in the
 * same order) and each forest F gives two trees, the black root then the white
 * root: tree id = ts->start[n] + 2 f + colour, f the index of F.  A forest is
 * stored as its child ids in nonincreasing order, so structure is shared: a
 * subtree is stored once and referred to by id, and a caller computing
 * elementary weights keeps one vector per stored tree (memoisation) and one
 * partial product per depth of the forest iterator.
 *
 * A table up to order N costs about 30 bytes per tree (order 9: 116780 trees,
 * order 10: 570040).  Trees of order N + 1 need not be stored: iterate the
 * forests of order N and pair each with a root colour.
 *
 * Bracket notation (vigen_tree_text): "b" is a black vertex, "w" a white one,
 * and x[t1,t2,...] is a vertex x whose children are the subtrees t1, t2, ...
 * (listed simplest first), e.g. b[w,w[b]].
 */
#ifndef VIGEN_TREES_H
#define VIGEN_TREES_H

#include <flint/flint.h>
#include "vigen/error.h"

#define VIGEN_TREE_MAX_ORDER 12

enum { VIGEN_TREE_BLACK = 0, VIGEN_TREE_WHITE = 1 };

/* Classification flags. */
enum {
    VIGEN_TREE_SEPARABLE = 1,   /* every edge joins vertices of different colours:
                                   the conditions that matter for H = T(p) + V(q) */
    VIGEN_TREE_MONO = 2         /* all vertices have the root's colour: the ordinary
                                   RK conditions of that part alone */
};

typedef struct {
    unsigned char order;        /* number of vertices */
    unsigned char colour;       /* VIGEN_TREE_BLACK or VIGEN_TREE_WHITE */
    unsigned char flags;        /* VIGEN_TREE_SEPARABLE | VIGEN_TREE_MONO */
    unsigned char nchildren;
    ulong gamma;                /* density */
    slong children;             /* offset of the child ids in ts->child_ids */
} vigen_tree;

typedef struct {
    int max_order;
    slong n;                    /* number of stored trees */
    vigen_tree *trees;
    slong *child_ids;           /* nonincreasing within each tree */
    slong nchild_ids;
    slong start[VIGEN_TREE_MAX_ORDER + 2];  /* trees of order k: ids start[k] .. start[k+1]-1 */
} vigen_treeset;

/* Builds every tree of order 1..max_order (0 <= max_order <= VIGEN_TREE_MAX_ORDER).
 * Returns VIGEN_E_USAGE for an order out of range, VIGEN_E_MEMORY when the
 * table cannot be allocated; the set is then empty but valid (clear it). */
int vigen_treeset_init(vigen_treeset *ts, int max_order, vigen_error *err);
void vigen_treeset_clear(vigen_treeset *ts);

/* Number of stored trees of the given order (0 when order is out of range). */
slong vigen_treeset_count(const vigen_treeset *ts, int order);

/* The stored tree with this id. */
static inline const vigen_tree *vigen_treeset_tree(const vigen_treeset *ts, slong id)
{
    return ts->trees + id;
}

/* The ids of the children of the stored tree with this id. */
static inline const slong *vigen_treeset_children(const vigen_treeset *ts, slong id)
{
    return ts->child_ids + ts->trees[id].children;
}

/* Iterates over the forests (multisets of stored trees) of total order m,
 * 0 <= m <= ts->max_order, as nonincreasing id sequences ids[0] >= ids[1] >= ...
 * in lexicographic order, starting with m black leaves; m = 0 gives the empty
 * forest once.  After each successful next(), `changed` is the first position
 * whose id differs from the previous forest: a caller keeping partial products
 * prod[d] = prod[d-1] * w(ids[d]) recomputes only positions changed .. k-1. */
typedef struct {
    const vigen_treeset *ts;
    int m;
    int k;                      /* number of trees in the current forest */
    int changed;
    slong index;                /* 0-based index of the current forest */
    slong *ids;                 /* m entries */
    int *used;                  /* used[d] = total order of ids[0..d-1] */
    int started, done;
} vigen_forest_iter;

/* An iterator over the forests of total order m of stored trees (freed by
 * vigen_forest_iter_clear). */
void vigen_forest_iter_init(vigen_forest_iter *it, const vigen_treeset *ts, int m);
void vigen_forest_iter_clear(vigen_forest_iter *it);
/* 1 when a forest is available in it->ids[0 .. it->k - 1], 0 at the end. */
int vigen_forest_iter_next(vigen_forest_iter *it);

/* Order, density and flags of the tree (colour, forest ids[0..k-1]). */
int vigen_forest_tree_order(const vigen_treeset *ts, const slong *ids, int k);
ulong vigen_forest_tree_gamma(const vigen_treeset *ts, const slong *ids, int k);
int vigen_forest_tree_flags(const vigen_treeset *ts, int colour, const slong *ids, int k);

/* The bracket notation of a stored tree, or of the tree (colour, forest):
 * a new string (release it with free()). */
char *vigen_tree_text(const vigen_treeset *ts, slong id);
char *vigen_forest_tree_text(const vigen_treeset *ts, int colour, const slong *ids, int k);

/* One sentence explaining the bracket notation, for reports. */
const char *vigen_tree_notation_help(void);

#endif
