/* test_check_reduction.c — the order conditions a symplectic tableau lets the
 * checker skip (src/check/reduction.c, orders.c).
 *
 * Independent sources:
 *  - the identity Phi(u o v) + Phi(v o u) = Phi(u) Phi(v) (u o v: v grafted
 *    onto the root of u) for trees whose roots have different colours when
 *    b_i at_ij + bt_j a_ji = b_i bt_j (Abia & Sanz-Serna, Math. Comp. 60
 *    (1993); Hairer, Lubich, Wanner, GNI sec. VI.7.2), and for roots of one
 *    colour when that part alone is a symplectic RK method; computed here in
 *    exact rationals on random trees from the definition of the elementary
 *    weights, for Lobatto IIIA-IIIB s = 3 (Hairer, Wanner II, Tables IV.5.7
 *    and IV.5.9; symplectic, GNI Thm VI.4.6) and for the midpoint rule taken
 *    three times with step 1/3 (a symplectic RK method: a composition of
 *    symplectic maps); it fails for RK4 and for Lobatto IIIA used for both
 *    parts (not symplectic), and for roots of one colour on Lobatto
 *    IIIA-IIIB (IIIA alone is not symplectic); the density identity
 *    1/gamma(u o v) + 1/gamma(v o u) = 1/(gamma(u) gamma(v));
 *  - the classes of rerootings, computed here by brute force on every tree
 *    up to order 8 (every vertex of the free tree as root, the component of
 *    allowed edges): each class keeps one tree, or two when its two
 *    centroids are joined by an allowed edge, and the skip rule moves to a
 *    tree of the same class whose largest child is smaller;
 *  - the checker with the reduction against the checker without it
 *    (VIGEN_CHECK_NO_REDUCTION): the same levels, counts, first failing trees
 *    and error constants, on exact, rounded, splitting and non-symplectic
 *    tableaux (RK4: its order-5 failure, Hairer, Norsett, Wanner I, II.1).
 */
#define _GNU_SOURCE
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq.h>
#include "check/check_internal.h"
#include "test_check_load.h"
#include "testlib.h"

/* ---- trees as parent arrays, elementary weights in Q --------------------- */

#define T_MAX 16

typedef struct {
    int n;
    int parent[T_MAX];           /* parent[0] = -1; parent[v] < v */
    int colour[T_MAX];
} ptree;

typedef struct {
    int s;                       /* at most 4 */
    const char *A[2][16], *b[2][4];  /* [colour]: (A, b) black, (At, bt) white */
} qtableau;

static void ptree_random(ptree *t, int n, flint_rand_t st)
{
    t->n = n;
    t->parent[0] = -1;
    for (int v = 0; v < n; v++) {
        if (v) t->parent[v] = (int)n_randint(st, (ulong)v);
        t->colour[v] = (int)n_randint(st, 2);
    }
}

/* u o v: the vertices of v after those of u, v's root a child of u's root. */
static void ptree_graft(ptree *out, const ptree *u, const ptree *v)
{
    *out = *u;
    for (int w = 0; w < v->n; w++) {
        out->parent[u->n + w] = w ? u->n + v->parent[w] : 0;
        out->colour[u->n + w] = v->colour[w];
    }
    out->n = u->n + v->n;
}

/* Phi(t) = sum_i bhat_i Phi_i(root), Phi_i(x) = prod over the children y of
 * x of sum_j m_ij Phi_j(y) (m: A for a black y, At for a white one); children
 * have larger numbers, so one sweep from the last vertex does it. */
static void weight(fmpq_t out, const ptree *t, const qtableau *q)
{
    fmpq phi[T_MAX][4];
    fmpq_t a, sum;
    fmpq_init(a);
    fmpq_init(sum);
    for (int v = 0; v < t->n; v++)
        for (int i = 0; i < q->s; i++) {
            fmpq_init(&phi[v][i]);
            fmpq_one(&phi[v][i]);
        }
    for (int v = t->n - 1; v > 0; v--) {
        int p = t->parent[v];
        for (int i = 0; i < q->s; i++) {
            fmpq_zero(sum);
            for (int j = 0; j < q->s; j++) {
                fmpq_set_str(a, q->A[t->colour[v]][i * q->s + j], 10);
                fmpq_addmul(sum, a, &phi[v][j]);
            }
            fmpq_mul(&phi[p][i], &phi[p][i], sum);
        }
    }
    fmpq_zero(out);
    for (int i = 0; i < q->s; i++) {
        fmpq_set_str(a, q->b[t->colour[0]][i], 10);
        fmpq_addmul(out, a, &phi[0][i]);
    }
    for (int v = 0; v < t->n; v++)
        for (int i = 0; i < q->s; i++) fmpq_clear(&phi[v][i]);
    fmpq_clear(a);
    fmpq_clear(sum);
}

/* gamma = product of the sizes of the subtrees at every vertex */
static ulong density(const ptree *t)
{
    int size[T_MAX];
    for (int v = 0; v < t->n; v++) size[v] = 1;
    for (int v = t->n - 1; v > 0; v--) size[t->parent[v]] += size[v];
    ulong g = 1;
    for (int v = 0; v < t->n; v++) g *= (ulong)size[v];
    return g;
}

/* Lobatto IIIA (black) and IIIB (white), s = 3 */
static const qtableau lobatto3 = {3,
    {{"0", "0", "0", "5/24", "1/3", "-1/24", "1/6", "2/3", "1/6"},
     {"1/6", "-1/6", "0", "1/6", "1/3", "0", "1/6", "5/6", "0"}},
    {{"1/6", "2/3", "1/6"}, {"1/6", "2/3", "1/6"}}};
/* the midpoint rule three times with step 1/3: a_ii = 1/6, a_ij = 1/3 (j < i) */
static const qtableau midpoint3 = {3,
    {{"1/6", "0", "0", "1/3", "1/6", "0", "1/3", "1/3", "1/6"},
     {"1/6", "0", "0", "1/3", "1/6", "0", "1/3", "1/3", "1/6"}},
    {{"1/3", "1/3", "1/3"}, {"1/3", "1/3", "1/3"}}};
/* RK4 (Hairer, Norsett, Wanner I, Table II.1.2) for both parts */
static const qtableau rk4 = {4,
    {{"0", "0", "0", "0", "1/2", "0", "0", "0", "0", "1/2", "0", "0", "0", "0", "1", "0"},
     {"0", "0", "0", "0", "1/2", "0", "0", "0", "0", "1/2", "0", "0", "0", "0", "1", "0"}},
    {{"1/6", "1/3", "1/3", "1/6"}, {"1/6", "1/3", "1/3", "1/6"}}};

/* Counts the random pairs (u, v), roots of colours (cu, cv) (-1: either),
 * for which the identity fails, and in *low those of total order <= 4; the
 * density identity is checked on every pair. */
static int identity_failures(const qtableau *q, int cu, int cv, int pairs, int *low, flint_rand_t st)
{
    int bad = 0;
    *low = 0;
    fmpq_t pu, pv, puv, pvu, lhs, rhs;
    fmpq_init(pu), fmpq_init(pv), fmpq_init(puv), fmpq_init(pvu), fmpq_init(lhs), fmpq_init(rhs);
    for (int k = 0; k < pairs; k++) {
        ptree u, v, uv, vu;
        ptree_random(&u, 1 + (int)n_randint(st, 4), st);
        ptree_random(&v, 1 + (int)n_randint(st, 4), st);
        if (cu >= 0) u.colour[0] = cu;
        if (cv >= 0) v.colour[0] = cv;
        ptree_graft(&uv, &u, &v);
        ptree_graft(&vu, &v, &u);
        weight(pu, &u, q);
        weight(pv, &v, q);
        weight(puv, &uv, q);
        weight(pvu, &vu, q);
        fmpq_add(lhs, puv, pvu);
        fmpq_mul(rhs, pu, pv);
        int fails = !fmpq_equal(lhs, rhs);
        bad += fails;
        *low += fails && uv.n <= 4;
        /* 1/gamma(u o v) + 1/gamma(v o u) = 1/(gamma(u) gamma(v)) */
        fmpq_set_si(lhs, 1, density(&uv));
        fmpq_set_si(rhs, 1, density(&vu));
        fmpq_add(lhs, lhs, rhs);
        fmpq_set_si(rhs, 1, density(&u) * density(&v));
        CHECK(fmpq_equal(lhs, rhs));
    }
    fmpq_clear(pu), fmpq_clear(pv), fmpq_clear(puv), fmpq_clear(pvu), fmpq_clear(lhs), fmpq_clear(rhs);
    return bad;
}

static void test_identity(void)
{
    flint_rand_t st;
    flint_randinit(st);
    int low;
    /* different colours: symplectic pairs satisfy it, on every pair */
    CHECK(identity_failures(&lobatto3, 0, 1, 300, &low, st) == 0);
    CHECK(identity_failures(&lobatto3, 1, 0, 300, &low, st) == 0);
    /* one colour: Lobatto IIIA alone is not a symplectic RK method */
    CHECK(identity_failures(&lobatto3, 0, 0, 300, &low, st) > 0);
    /* ... the midpoint composition is, for both colours */
    CHECK(identity_failures(&midpoint3, 0, 0, 300, &low, st) == 0);
    CHECK(identity_failures(&midpoint3, 1, 1, 300, &low, st) == 0);
    CHECK(identity_failures(&midpoint3, 0, 1, 300, &low, st) == 0);
    /* a non-symplectic pair: Lobatto IIIA for both parts */
    qtableau iiia = lobatto3;
    for (int k = 0; k < 9; k++) iiia.A[1][k] = lobatto3.A[0][k];
    CHECK(identity_failures(&iiia, 0, 1, 300, &low, st) > 0);
    /* RK4, not symplectic: it fails, but only above order 4, where the
     * conditions on both sides no longer hold */
    CHECK(identity_failures(&rk4, -1, -1, 300, &low, st) > 0 && low == 0);
    flint_randclear(st);
}

/* ---- classes of rerootings ------------------------------------------------ */

#define C_MAX 8

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* canonical string of the branch at x away from `from` in an unrooted tree */
static char *branch_str(int adj[][C_MAX], const int *deg, const int *colour, int x, int from)
{
    char *kids[C_MAX];
    int k = 0;
    size_t len = 4;
    for (int e = 0; e < deg[x]; e++)
        if (adj[x][e] != from) {
            kids[k] = branch_str(adj, deg, colour, adj[x][e], x);
            len += strlen(kids[k++]) + 1;
        }
    qsort(kids, (size_t)k, sizeof(char *), cmp_str);
    char *s = malloc(len);
    strcpy(s, colour[x] ? "w" : "b");
    if (k) {
        strcat(s, "(");
        for (int i = 0; i < k; i++) {
            strcat(s, kids[i]);
            strcat(s, i + 1 < k ? "," : ")");
            free(kids[i]);
        }
    }
    return s;
}

static int branch_size(int adj[][C_MAX], const int *deg, int x, int from)
{
    int m = 1;
    for (int e = 0; e < deg[x]; e++)
        if (adj[x][e] != from) m += branch_size(adj, deg, adj[x][e], x);
    return m;
}

typedef struct {
    char *key;
    slong id;
} named;

static int cmp_named(const void *a, const void *b) { return strcmp(((const named *)a)->key, ((const named *)b)->key); }

static slong lookup(const named *tab, slong n, char *key)
{
    named k = {key, 0};
    const named *r = bsearch(&k, tab, (size_t)n, sizeof(named), cmp_named);
    return r ? r->id : -1;
}

static int cmp_slong_desc(const void *a, const void *b)
{
    slong x = *(const slong *)a, y = *(const slong *)b;
    return x < y ? 1 : x > y ? -1 : 0;
}

/* Every tree up to order C_MAX, every vertex as root: which rootings the rule
 * keeps, per class (component of allowed edges). */
static void test_classes(int mono)
{
    vigen_treeset ts;
    vigen_error err;
    vigen_error_init(&err);
    CHECK(vigen_treeset_init(&ts, C_MAX, &err) == VIGEN_OK);
    chk_reduction red;
    memset(&red, 0, sizeof(red));
    red.on = 1;
    red.edge[0][1] = red.edge[1][0] = 1;
    red.edge[0][0] = red.edge[1][1] = mono;
    /* canonical strings of the stored trees, from their children */
    char **str = calloc((size_t)ts.n, sizeof(char *));
    named *tab = calloc((size_t)ts.n, sizeof(named));
    for (slong id = 0; id < ts.n; id++) {
        const vigen_tree *t = vigen_treeset_tree(&ts, id);
        const slong *ch = vigen_treeset_children(&ts, id);
        char *kids[C_MAX];
        size_t len = 4;
        for (int i = 0; i < t->nchildren; i++) kids[i] = str[ch[i]], len += strlen(kids[i]) + 1;
        qsort(kids, t->nchildren, sizeof(char *), cmp_str);
        str[id] = malloc(len);
        strcpy(str[id], t->colour ? "w" : "b");
        for (int i = 0; i < t->nchildren; i++) {
            strcat(str[id], i ? "," : "(");
            strcat(str[id], kids[i]);
        }
        if (t->nchildren) strcat(str[id], ")");
        tab[id].key = str[id];
        tab[id].id = id;
    }
    qsort(tab, (size_t)ts.n, sizeof(named), cmp_named);
    long classes = 0, two = 0, bad_keep = 0, bad_step = 0;
    for (slong id = 0; id < ts.n; id++) {
        const vigen_tree *t = vigen_treeset_tree(&ts, id);
        int n = t->order;
        if (n < 2) continue;
        /* the free tree: vertices by a walk over the stored structure */
        int adj[C_MAX][C_MAX], deg[C_MAX] = {0}, colour[C_MAX], m = 0;
        slong stack[C_MAX];
        int vert[C_MAX], sp = 0;
        stack[sp] = id, vert[sp++] = m, colour[m++] = t->colour;
        while (sp) {
            slong u = stack[--sp];
            int x = vert[sp];
            const slong *ch = vigen_treeset_children(&ts, u);
            for (int i = 0; i < vigen_treeset_tree(&ts, u)->nchildren; i++) {
                int y = m++;
                colour[y] = vigen_treeset_tree(&ts, ch[i])->colour;
                adj[x][deg[x]++] = y;
                adj[y][deg[y]++] = x;
                stack[sp] = ch[i], vert[sp++] = y;
            }
        }
        /* each rooting: kept or skipped, by the checker's rule */
        int skipped[C_MAX], kmax[C_MAX];
        slong heavy_id[C_MAX];
        for (int x = 0; x < n; x++) {
            slong ids[C_MAX];
            int k = 0;
            kmax[x] = 0;
            heavy_id[x] = -1;
            for (int e = 0; e < deg[x]; e++) {
                char *b = branch_str(adj, deg, colour, adj[x][e], x);
                ids[k++] = lookup(tab, ts.n, b);
                free(b);
                int sz = branch_size(adj, deg, adj[x][e], x);
                if (sz > kmax[x]) kmax[x] = sz;
            }
            qsort(ids, (size_t)k, sizeof(slong), cmp_slong_desc);
            skipped[x] = chk_reduction_skips(&red, &ts, n, colour[x], ids, k);
            heavy_id[x] = k ? ids[0] : -1;
        }
        /* a skipped rooting moves to its heaviest neighbour, across an allowed
         * edge, where the largest child is smaller */
        for (int x = 0; x < n; x++) {
            if (!skipped[x]) continue;
            int ok = 0;
            for (int e = 0; e < deg[x]; e++) {
                int y = adj[x][e];
                char *b = branch_str(adj, deg, colour, y, x);
                int heavy = lookup(tab, ts.n, b) == heavy_id[x];
                free(b);
                if (heavy && red.edge[colour[x]][colour[y]] && 2 * branch_size(adj, deg, y, x) > n && kmax[y] < kmax[x])
                    ok = 1;
            }
            bad_step += !ok;
        }
        /* components of allowed edges: one kept rooting, two when it holds both centroids */
        int comp[C_MAX];
        for (int x = 0; x < n; x++) comp[x] = -1;
        for (int x = 0; x < n; x++) {
            if (comp[x] >= 0) continue;
            int q[C_MAX], qh = 0, qt = 0, kept = 0;
            comp[x] = x;
            q[qt++] = x;
            while (qh < qt) {
                int y = q[qh++];
                kept += !skipped[y];
                for (int e = 0; e < deg[y]; e++) {
                    int z = adj[y][e];
                    if (comp[z] < 0 && red.edge[colour[y]][colour[z]]) comp[z] = x, q[qt++] = z;
                }
            }
            classes++;
            two += kept == 2;
            bad_keep += kept < 1 || kept > 2;
        }
    }
    CHECK_MSG(bad_keep == 0, "%ld classes keep no rooting or more than two", bad_keep);
    CHECK_MSG(bad_step == 0, "%ld skips do not move to a smaller largest child", bad_step);
    CHECK(classes > 0 && two > 0);
    for (slong id = 0; id < ts.n; id++) free(str[id]);
    free(str);
    free(tab);
    vigen_treeset_clear(&ts);
    vigen_error_clear(&err);
}

/* ---- the checker with and without the reduction -------------------------- */

static void same_reports(const vigen_check_report *a, const vigen_check_report *b, const char *what)
{
    for (int f = 0; f < VIGEN_CHECK_FAMILIES; f++) {
        const vigen_check_orders *x = &a->orders[f], *y = &b->orders[f];
        CHECK_MSG(memcmp(&x->level, &y->level, sizeof(x->level)) == 0, "%s family %d: levels differ", what, f);
        CHECK_MSG(x->evaluated_to == y->evaluated_to, "%s family %d", what, f);
        for (int n = 1; n <= x->evaluated_to; n++) {
            CHECK_MSG(x->count[n] == y->count[n] && x->hold[n] == y->hold[n] && x->fail[n] == y->fail[n] &&
                          x->undecided[n] == y->undecided[n],
                      "%s family %d order %d: %ld/%ld/%ld vs %ld/%ld/%ld", what, f, n, (long)x->hold[n],
                      (long)x->fail[n], (long)x->count[n], (long)y->hold[n], (long)y->fail[n], (long)y->count[n]);
            CHECK(y->inferred[n] == 0);
        }
        CHECK_MSG((x->fail_tree == NULL) == (y->fail_tree == NULL) &&
                      (x->fail_tree == NULL || strcmp(x->fail_tree, y->fail_tree) == 0),
                  "%s family %d: first failing trees %s, %s", what, f, x->fail_tree ? x->fail_tree : "-",
                  y->fail_tree ? y->fail_tree : "-");
    }
    for (int e = 0; e < VIGEN_CHECK_EC_FAMILIES; e++) {
        const vigen_check_error_constant *x = &a->error_constant[e], *y = &b->error_constant[e];
        CHECK_MSG(x->available == y->available && x->ntrees == y->ntrees, "%s error constant %d", what, e);
        if (x->available && y->available) {
            /* the same sum in another order: overlapping balls, midpoints to 12 digits */
            arb_t mx, my;
            arb_init(mx);
            arb_init(my);
            arb_set_arf(mx, arb_midref(x->value));
            arb_set_arf(my, arb_midref(y->value));
            CHECK(arb_overlaps(x->value, y->value));
            CHECK_CLOSE(mx, my, 12, 128);
            arb_clear(mx);
            arb_clear(my);
        }
    }
    CHECK(a->claim_order_status == b->claim_order_status && a->exit_code == b->exit_code);
}

static long inferred_total(const vigen_check_report *rep)
{
    long k = 0;
    for (int n = 1; n <= VIGEN_TREE_MAX_ORDER; n++) k += (long)rep->orders[VIGEN_CHECK_GENERAL].inferred[n];
    return k;
}

/* returns the number of conditions inferred with the reduction */
static long compare(const char *rel, int P)
{
    vigen_check_report a, b;
    unsetenv("VIGEN_CHECK_NO_REDUCTION");
    int ra = check_file_claim(&a, rel, -2, P);
    setenv("VIGEN_CHECK_NO_REDUCTION", "1", 1);
    int rb = check_file_claim(&b, rel, -2, P);
    unsetenv("VIGEN_CHECK_NO_REDUCTION");
    CHECK(ra == VIGEN_OK && rb == VIGEN_OK);
    long k = inferred_total(&a);
    if (ra == VIGEN_OK && rb == VIGEN_OK) same_reports(&a, &b, rel);
    vigen_check_report_clear(&a);
    vigen_check_report_clear(&b);
    return k;
}

static void test_verdicts(void)
{
    /* exact rationals, order 4, fails at 5 (Hairer, Wanner II, IV.5) */
    CHECK(compare("tableaux/published/lobatto_iiia_iiib_3.lua", 7) > 0);
    /* Q(sqrt 3): Gauss s = 2 (order 4), proved with the conjugate tableau */
    CHECK(compare("tableaux/published/gauss_2.lua", 7) > 0);
    /* rounded data: Gauss s = 4 (order 8), Lobatto IIIA-IIIB s = 5 (order 8) */
    CHECK(compare("tableaux/generated/gauss_legendre_s4.lua", 10) > 0);
    CHECK(compare("tableaux/generated/gauss_lobatto_s5.lua", 10) > 0);
    /* splitting methods: bt != b, symplectic for separable H */
    CHECK(compare("tableaux/published/yoshida_6.lua", 8) > 0);
    CHECK(compare("tableaux/published/blanes_moan_s10_6.lua", 8) > 0);
    /* not symplectic: every condition evaluated, the order-5 failure found */
    CHECK(compare("tests/data/check/rk4.lua", 8) == 0);
    vigen_check_report r;
    CHECK(check_file_claim(&r, "tests/data/check/rk4.lua", -2, 8) == VIGEN_OK);
    CHECK(r.orders[VIGEN_CHECK_GENERAL].level.value == 4 && r.orders[VIGEN_CHECK_GENERAL].fail_order == 5);
    vigen_check_report_clear(&r);
    /* Gauss s = 3 with one entry moved by 1e-30: not symplectic, no reduction */
    CHECK(compare("tests/data/check/gauss3_40_perturbed.lua", 7) == 0);
}

/* With the reduction every condition is still counted: the numbers of
 * bicoloured trees, OEIS A038055 (2 * A000151), all holding for Gauss s = 4
 * up to its order 8, and fewer evaluated. */
static void test_counts(void)
{
    static const long A038055[9] = {0, 2, 4, 14, 52, 214, 916, 4116, 18996};
    vigen_check_report r;
    CHECK(check_file_claim(&r, "tableaux/generated/gauss_legendre_s4.lua", -1, 8) == VIGEN_OK);
    const vigen_check_orders *g = &r.orders[VIGEN_CHECK_GENERAL];
    for (int n = 1; n <= 8; n++) {
        CHECK(g->count[n] == A038055[n] && g->hold[n] == A038055[n]);
        if (n >= 3) CHECK(g->inferred[n] > 0 && g->inferred[n] < g->count[n]);
    }
    CHECK(g->level.value == 8 && g->level.capped && g->level.within_data);
    vigen_check_report_clear(&r);
}

int main(void)
{
    test_identity();
    test_classes(0);
    test_classes(1);
    test_verdicts();
    test_counts();
    TEST_MAIN_END();
}
