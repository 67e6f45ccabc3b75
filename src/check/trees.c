/* trees.c — enumeration of bicoloured rooted trees (see trees.h). */
#include <stdlib.h>
#include <string.h>
#include "vigen/trees.h"
#include "support/strbuf.h"
#include "check/check_internal.h"

const char *vigen_tree_notation_help(void)
{
    return "b = black vertex (q part: A, b), w = white vertex (p part: At, bt); "
           "x[t1,t2,...] is a vertex x whose children are the subtrees t1, t2, ...";
}

/* ---- forests -------------------------------------------------------------- */

void vigen_forest_iter_init(vigen_forest_iter *it, const vigen_treeset *ts, int m)
{
    it->ts = ts;
    it->m = m;
    it->k = 0;
    it->changed = 0;
    it->index = -1;
    it->ids = flint_malloc(sizeof(slong) * (size_t)(m > 0 ? m : 1));
    it->used = flint_malloc(sizeof(int) * (size_t)(m + 1));
    it->used[0] = 0;
    it->started = 0;
    it->done = (m < 0 || m > ts->max_order);
}

void vigen_forest_iter_clear(vigen_forest_iter *it)
{
    flint_free(it->ids);
    flint_free(it->used);
    it->ids = NULL;
    it->used = NULL;
}

/* Fills positions d, d+1, ... with black leaves (id 0) up to total order m. */
static void fill_leaves(vigen_forest_iter *it, int d)
{
    while (it->used[d] < it->m) {
        it->ids[d] = 0;
        it->used[d + 1] = it->used[d] + 1;
        d++;
    }
    it->k = d;
}

int vigen_forest_iter_next(vigen_forest_iter *it)
{
    const vigen_treeset *ts = it->ts;
    if (it->done) return 0;
    if (!it->started) {
        it->started = 1;
        fill_leaves(it, 0);
        it->changed = 0;
        it->index = 0;
        return 1;
    }
    /* The rightmost position that can take the next larger id; the smallest
     * completion after it is all black leaves (id 0 is the smallest id). */
    for (int d = it->k - 1; d >= 0; d--) {
        slong cand = it->ids[d] + 1;
        slong limit = d > 0 ? it->ids[d - 1] : ts->start[it->m + 1] - 1;
        int rem = it->m - it->used[d];
        if (cand > limit || ts->trees[cand].order > rem) continue;
        it->ids[d] = cand;
        it->used[d + 1] = it->used[d] + ts->trees[cand].order;
        fill_leaves(it, d + 1);
        it->changed = d;
        it->index++;
        return 1;
    }
    it->done = 1;
    return 0;
}

int vigen_forest_tree_order(const vigen_treeset *ts, const slong *ids, int k)
{
    int n = 1;
    for (int i = 0; i < k; i++) n += ts->trees[ids[i]].order;
    return n;
}

ulong vigen_forest_tree_gamma(const vigen_treeset *ts, const slong *ids, int k)
{
    ulong g = (ulong)vigen_forest_tree_order(ts, ids, k);
    for (int i = 0; i < k; i++) g *= ts->trees[ids[i]].gamma;
    return g;
}

int vigen_forest_tree_flags(const vigen_treeset *ts, int colour, const slong *ids, int k)
{
    int sep = 1, mono = 1;
    for (int i = 0; i < k; i++) {
        const vigen_tree *u = ts->trees + ids[i];
        if (!(u->flags & VIGEN_TREE_SEPARABLE) || u->colour == colour) sep = 0;
        if (!(u->flags & VIGEN_TREE_MONO) || u->colour != colour) mono = 0;
    }
    return (sep ? VIGEN_TREE_SEPARABLE : 0) | (mono ? VIGEN_TREE_MONO : 0);
}

/* ---- the table ------------------------------------------------------------ */

void vigen_treeset_clear(vigen_treeset *ts)
{
    flint_free(ts->trees);
    flint_free(ts->child_ids);
    ts->trees = NULL;
    ts->child_ids = NULL;
    ts->n = 0;
    ts->nchild_ids = 0;
}

slong vigen_treeset_count(const vigen_treeset *ts, int order)
{
    if (order < 1 || order > ts->max_order) return 0;
    return ts->start[order + 1] - ts->start[order];
}

/* Grows *p to hold at least need elements; 0 when out of memory. */
static int grow(void **p, slong *cap, slong need, size_t size)
{
    if (need <= *cap && *p != NULL) return 1;
    slong c = *cap > 0 ? *cap : 64;
    while (c < need) c *= 2;
    void *q = realloc(*p, (size_t)c * size);
    if (q == NULL) return 0;
    *p = q;
    *cap = c;
    return 1;
}

int vigen_treeset_init(vigen_treeset *ts, int max_order, vigen_error *err)
{
    memset(ts, 0, sizeof(*ts));
    if (max_order < 0 || max_order > VIGEN_TREE_MAX_ORDER) {
        return vigen_error_set(err, VIGEN_E_USAGE,
                               "tree order %d is out of range (0 .. %d)", max_order,
                               VIGEN_TREE_MAX_ORDER);
    }
    /* Built with realloc (not flint_realloc, which aborts) so that running out
     * of memory is reported; copied into flint_malloc storage at the end. */
    vigen_tree *trees = NULL;
    slong *child = NULL;
    slong tcap = 0, ccap = 0, n = 0, nc = 0;

    ts->max_order = 0;
    ts->start[1] = 0;
    for (int order = 1; order <= max_order; order++) {
        /* ts->trees must describe orders < order for the iterator. */
        ts->trees = trees;
        ts->child_ids = child;
        ts->max_order = order - 1;
        ts->start[order] = n;

        vigen_forest_iter it;
        vigen_forest_iter_init(&it, ts, order - 1);
        while (vigen_forest_iter_next(&it)) {
            void *tp = trees, *cp = child;
            int ok = grow(&tp, &tcap, n + 2, sizeof(vigen_tree));
            trees = tp;
            ok = ok && grow(&cp, &ccap, nc + it.k, sizeof(slong));
            child = cp;
            if (!ok) goto oom;
            ts->trees = trees;
            ts->child_ids = child;
            memcpy(child + nc, it.ids, sizeof(slong) * (size_t)it.k);
            ulong gamma = vigen_forest_tree_gamma(ts, it.ids, it.k);
            for (int colour = 0; colour < 2; colour++) {
                vigen_tree *t = trees + n++;
                t->order = (unsigned char)order;
                t->colour = (unsigned char)colour;
                t->flags = (unsigned char)vigen_forest_tree_flags(ts, colour, it.ids, it.k);
                t->nchildren = (unsigned char)it.k;
                t->gamma = gamma;
                t->children = nc;
            }
            nc += it.k;
            continue;
        oom:
            vigen_forest_iter_clear(&it);
            free(trees);
            free(child);
            memset(ts, 0, sizeof(*ts));
            return vigen_error_set(err, VIGEN_E_MEMORY,
                                   "out of memory building the trees of order %d; "
                                   "use a smaller --max-order", order);
        }
        vigen_forest_iter_clear(&it);
        ts->start[order + 1] = n;
    }

    ts->trees = flint_malloc(sizeof(vigen_tree) * (size_t)(n > 0 ? n : 1));
    ts->child_ids = flint_malloc(sizeof(slong) * (size_t)(nc > 0 ? nc : 1));
    if (n) memcpy(ts->trees, trees, sizeof(vigen_tree) * (size_t)n);
    if (nc) memcpy(ts->child_ids, child, sizeof(slong) * (size_t)nc);
    free(trees);
    free(child);
    ts->n = n;
    ts->nchild_ids = nc;
    ts->max_order = max_order;
    if (max_order == 0) ts->start[1] = 0;
    return VIGEN_OK;
}

/* ---- printing ------------------------------------------------------------- */

static void append_forest(vigen_strbuf *sb, const vigen_treeset *ts, const slong *ids, int k)
{
    if (k == 0) return;
    vigen_strbuf_append(sb, "[");
    for (int i = k - 1; i >= 0; i--) {           /* simplest (smallest id) first */
        chk_tree_append(sb, ts, ids[i]);
        if (i > 0) vigen_strbuf_append(sb, ",");
    }
    vigen_strbuf_append(sb, "]");
}

void chk_tree_append(vigen_strbuf *sb, const vigen_treeset *ts, slong id)
{
    const vigen_tree *t = ts->trees + id;
    vigen_strbuf_append(sb, t->colour == VIGEN_TREE_BLACK ? "b" : "w");
    append_forest(sb, ts, ts->child_ids + t->children, t->nchildren);
}

void chk_forest_tree_append(vigen_strbuf *sb, const vigen_treeset *ts, int colour,
                              const slong *ids, int k)
{
    vigen_strbuf_append(sb, colour == VIGEN_TREE_BLACK ? "b" : "w");
    append_forest(sb, ts, ids, k);
}

char *vigen_tree_text(const vigen_treeset *ts, slong id)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    chk_tree_append(&sb, ts, id);
    return sb.data;
}

char *vigen_forest_tree_text(const vigen_treeset *ts, int colour, const slong *ids, int k)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    chk_forest_tree_append(&sb, ts, colour, ids, k);
    return sb.data;
}
