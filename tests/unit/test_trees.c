/* test_trees.c — bicoloured rooted trees (src/check/trees.c).
 *
 * Independent sources:
 *  - counts per order: OEIS A038055 (= 2 * A000151, rooted trees with vertices
 *    of 2 colours): 2, 4, 14, 52, 214, 916, 4116, 18996, 89894, 433196;
 *  - separable (alternating) and monochromatic trees: a colour of the root and
 *    an uncoloured rooted tree determine them, so each count is 2 * A000081(n),
 *    A000081 = 1, 1, 2, 4, 9, 20, 48, 115, 286, 719 (also recomputed here from
 *    its recurrence);
 *  - a brute-force enumeration done differently: grow every tree of order n - 1
 *    by a leaf of either colour at every vertex (parent arrays), canonicalise by
 *    sorting child strings, deduplicate; compare the sets of trees, densities
 *    (product of subtree sizes) and classifications up to order 7.
 */
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "vigen/trees.h"
#include "testlib.h"

static const long A038055[11] = {0, 2, 4, 14, 52, 214, 916, 4116, 18996, 89894, 433196};
static const long A000081[11] = {0, 1, 1, 2, 4, 9, 20, 48, 115, 286, 719};

/* ---- brute force on parent arrays ---------------------------------------- */

#define BF_MAX 8

typedef struct {
    int n;
    int parent[BF_MAX];  /* parent[0] = -1 */
    int colour[BF_MAX];
} bf_tree;

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Canonical string of the subtree at v: colour letter, then the children's
 * canonical strings sorted by strcmp inside brackets. */
static char *bf_canon(const bf_tree *t, int v)
{
    char *kids[BF_MAX];
    int nk = 0;
    size_t len = 2;
    for (int u = 0; u < t->n; u++) {
        if (t->parent[u] == v) {
            kids[nk] = bf_canon(t, u);
            len += strlen(kids[nk]) + 1;
            nk++;
        }
    }
    qsort(kids, (size_t)nk, sizeof(char *), cmp_str);
    char *s = malloc(len + 2);
    s[0] = t->colour[v] ? 'w' : 'b';
    s[1] = 0;
    if (nk) {
        strcat(s, "[");
        for (int i = 0; i < nk; i++) {
            strcat(s, kids[i]);
            strcat(s, i + 1 < nk ? "," : "]");
            free(kids[i]);
        }
    }
    return s;
}

static long bf_gamma(const bf_tree *t)
{
    long g = 1;
    for (int v = 0; v < t->n; v++) {
        /* subtree size of v: vertices whose ancestor chain meets v */
        int size = 0;
        for (int u = 0; u < t->n; u++) {
            int w = u;
            while (w != -1 && w != v) w = t->parent[w];
            if (w == v) size++;
        }
        g *= size;
    }
    return g;
}

static int bf_flags(const bf_tree *t)
{
    int sep = 1, mono = 1;
    for (int u = 1; u < t->n; u++) {
        if (t->colour[u] == t->colour[t->parent[u]]) sep = 0;
        if (t->colour[u] != t->colour[0]) mono = 0;
    }
    return (sep ? VIGEN_TREE_SEPARABLE : 0) | (mono ? VIGEN_TREE_MONO : 0);
}

typedef struct {
    char *canon;
    bf_tree t;
} bf_entry;

static int cmp_entry(const void *a, const void *b)
{
    return strcmp(((const bf_entry *)a)->canon, ((const bf_entry *)b)->canon);
}

/* level[n] = sorted unique trees of order n */
static bf_entry *level[BF_MAX + 1];
static long nlevel[BF_MAX + 1];

static void bf_build(int maxn)
{
    level[1] = malloc(2 * sizeof(bf_entry));
    for (int c = 0; c < 2; c++) {
        bf_tree t = {1, {-1}, {c}};
        level[1][c].t = t;
        level[1][c].canon = bf_canon(&t, 0);
    }
    nlevel[1] = 2;
    qsort(level[1], 2, sizeof(bf_entry), cmp_entry);
    for (int n = 2; n <= maxn; n++) {
        long cap = nlevel[n - 1] * (n - 1) * 2, cnt = 0;
        bf_entry *cand = malloc((size_t)cap * sizeof(bf_entry));
        for (long i = 0; i < nlevel[n - 1]; i++) {
            for (int v = 0; v < n - 1; v++) {
                for (int c = 0; c < 2; c++) {
                    bf_tree t = level[n - 1][i].t;
                    t.parent[n - 1] = v;
                    t.colour[n - 1] = c;
                    t.n = n;
                    cand[cnt].t = t;
                    cand[cnt].canon = bf_canon(&t, 0);
                    cnt++;
                }
            }
        }
        qsort(cand, (size_t)cnt, sizeof(bf_entry), cmp_entry);
        long u = 0;
        for (long i = 0; i < cnt; i++) {
            if (u > 0 && strcmp(cand[u - 1].canon, cand[i].canon) == 0) {
                free(cand[i].canon);
                continue;
            }
            cand[u++] = cand[i];
        }
        level[n] = cand;
        nlevel[n] = u;
    }
}

/* Parses the module's bracket notation into a parent array. */
static const char *parse_tree(bf_tree *t, int parent, const char *s)
{
    int v = t->n++;
    t->parent[v] = parent;
    t->colour[v] = (*s == 'w');
    s++;
    if (*s == '[') {
        s++;
        for (;;) {
            s = parse_tree(t, v, s);
            if (*s == ',') { s++; continue; }
            if (*s == ']') { s++; break; }
            return s; /* malformed: caller sees the mismatch */
        }
    }
    return s;
}

/* ---- independent recurrence for A000081 -------------------------------- */

static void a000081(long *r, int nmax)
{
    /* r(n+1) = (1/n) sum_{k=1}^{n} (sum_{d|k} d r(d)) r(n-k+1), r(1) = 1 */
    r[1] = 1;
    for (int n = 1; n < nmax; n++) {
        long s = 0;
        for (int k = 1; k <= n; k++) {
            long sd = 0;
            for (int d = 1; d <= k; d++) if (k % d == 0) sd += d * r[d];
            s += sd * r[n - k + 1];
        }
        r[n + 1] = s / n;
    }
}

int main(void)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_treeset ts;

    /* Counts, order 1..9 stored; order 10 through the forests of order 9. */
    clock_t t0 = clock();
    CHECK(vigen_treeset_init(&ts, 9, &err) == VIGEN_OK);
    long sep[11] = {0}, mono[11] = {0};
    for (int n = 1; n <= 9; n++) {
        CHECK_MSG(vigen_treeset_count(&ts, n) == A038055[n], "order %d: %ld trees, expected %ld", n,
                  (long)vigen_treeset_count(&ts, n), A038055[n]);
        for (slong id = ts.start[n]; id < ts.start[n + 1]; id++) {
            const vigen_tree *t = vigen_treeset_tree(&ts, id);
            CHECK(t->order == n);
            if (t->flags & VIGEN_TREE_SEPARABLE) sep[n]++;
            if (t->flags & VIGEN_TREE_MONO) mono[n]++;
            /* children are nonincreasing ids of total order n - 1 */
            const slong *ch = vigen_treeset_children(&ts, id);
            int tot = 0;
            for (int i = 0; i < t->nchildren; i++) {
                tot += ts.trees[ch[i]].order;
                if (i) CHECK(ch[i] <= ch[i - 1]);
            }
            CHECK(tot == n - 1);
        }
    }
    {
        vigen_forest_iter it;
        vigen_forest_iter_init(&it, &ts, 9);
        long forests = 0;
        while (vigen_forest_iter_next(&it)) {
            forests++;
            CHECK(vigen_forest_tree_order(&ts, it.ids, it.k) == 10);
            for (int c = 0; c < 2; c++) {
                int f = vigen_forest_tree_flags(&ts, c, it.ids, it.k);
                if (f & VIGEN_TREE_SEPARABLE) sep[10]++;
                if (f & VIGEN_TREE_MONO) mono[10]++;
            }
        }
        CHECK(it.index + 1 == forests);
        vigen_forest_iter_clear(&it);
        CHECK_MSG(2 * forests == A038055[10], "order 10: %ld trees", 2 * forests);
    }
    double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
    printf("trees up to order 10 enumerated in %.3f s (%ld stored)\n", secs, (long)ts.n);

    long r[11];
    a000081(r, 10);
    for (int n = 1; n <= 10; n++) {
        CHECK(r[n] == A000081[n]);
        CHECK_MSG(sep[n] == 2 * A000081[n], "order %d: %ld separable", n, sep[n]);
        CHECK_MSG(mono[n] == 2 * A000081[n], "order %d: %ld monochromatic", n, mono[n]);
    }

    /* A few trees by hand: densities gamma(b[b,b]) = 3, gamma(b[b[b]]) = 6;
     * order-1 ids 0 = b, 1 = w. */
    CHECK(ts.trees[0].colour == VIGEN_TREE_BLACK && ts.trees[1].colour == VIGEN_TREE_WHITE);
    {
        char *text = vigen_tree_text(&ts, 0);
        CHECK(text && strcmp(text, "b") == 0);
        free(text);
        slong bb[2] = {0, 0};
        text = vigen_forest_tree_text(&ts, VIGEN_TREE_BLACK, bb, 2);
        CHECK(text && strcmp(text, "b[b,b]") == 0);
        free(text);
        CHECK(vigen_forest_tree_gamma(&ts, bb, 2) == 3);
        CHECK(vigen_forest_tree_flags(&ts, VIGEN_TREE_BLACK, bb, 2) == VIGEN_TREE_MONO);
        slong wb[2] = {1, 0};
        CHECK(vigen_forest_tree_flags(&ts, VIGEN_TREE_BLACK, wb, 2) == 0);
        slong ww[2] = {1, 1};
        CHECK(vigen_forest_tree_flags(&ts, VIGEN_TREE_BLACK, ww, 2) == VIGEN_TREE_SEPARABLE);
    }

    /* Brute force, orders 1..7: same set of trees, densities and flags. */
    bf_build(7);
    for (int n = 1; n <= 7; n++) {
        CHECK_MSG(nlevel[n] == A038055[n], "brute force order %d: %ld", n, nlevel[n]);
        char **mine = malloc(sizeof(char *) * (size_t)vigen_treeset_count(&ts, n));
        long cnt = 0;
        for (slong id = ts.start[n]; id < ts.start[n + 1]; id++) {
            char *text = vigen_tree_text(&ts, id);
            bf_tree t;
            t.n = 0;
            const char *end = parse_tree(&t, -1, text);
            CHECK(*end == 0 && t.n == n);
            char *canon = bf_canon(&t, 0);
            bf_entry key = {canon, t};
            bf_entry *hit = bsearch(&key, level[n], (size_t)nlevel[n], sizeof(bf_entry), cmp_entry);
            CHECK_MSG(hit != NULL, "tree %s not found by brute force", text);
            if (hit) {
                CHECK_MSG((long)ts.trees[id].gamma == bf_gamma(&hit->t), "gamma of %s", text);
                CHECK_MSG(ts.trees[id].flags == bf_flags(&hit->t), "flags of %s", text);
            }
            mine[cnt++] = canon;
            free(text);
        }
        /* no duplicates among the module's trees */
        qsort(mine, (size_t)cnt, sizeof(char *), cmp_str);
        for (long i = 1; i < cnt; i++) CHECK(strcmp(mine[i - 1], mine[i]) != 0);
        for (long i = 0; i < cnt; i++) free(mine[i]);
        free(mine);
    }
    for (int n = 1; n <= 7; n++) {
        for (long i = 0; i < nlevel[n]; i++) free(level[n][i].canon);
        free(level[n]);
    }

    /* Out-of-range orders are refused. */
    vigen_treeset bad;
    CHECK(vigen_treeset_init(&bad, VIGEN_TREE_MAX_ORDER + 1, &err) == VIGEN_E_USAGE);
    vigen_treeset_clear(&bad);
    vigen_error_clear(&err);

    /* Order 0: one empty forest. */
    {
        vigen_forest_iter it;
        vigen_forest_iter_init(&it, &ts, 0);
        CHECK(vigen_forest_iter_next(&it) == 1 && it.k == 0);
        CHECK(vigen_forest_iter_next(&it) == 0);
        vigen_forest_iter_clear(&it);
    }

    vigen_treeset_clear(&ts);
    TEST_MAIN_END();
}
