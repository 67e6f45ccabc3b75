/* hand_verlet_dim.h — the hand-written Stormer-Verlet of the peer
 * benchmarks (bench/peer_bench.c, peer_icount.c): kick-drift-kick with the
 * dimension known to the compiler and the force inlined; the drift uses
 * p + h/2 f, the two half kicks of a step go into one compensated (TwoSum)
 * update of p, as in the emitted stepper; the force at the end of a step is
 * the next step's first; its passes take restrict-qualified arrays, so that
 * they vectorise where the emitted ones do.  Include it after PEER_DIM, PEER_VELOCITY(k, x),
 * peer_force and the problem pointer pb are defined.  A measurement anchor,
 * not product code. */
typedef struct {
    double buf[2][PEER_DIM], cq[PEER_DIM], cp[PEER_DIM], *f, *g;
    int have_f;
    vigen_stats st;
} hsv_ws;

static inline double twosum(double x, double d, double *c)
{
    double e = d + *c, s = x + e, bb = s - x;
    *c = (x - (s - bb)) + (e - bb);
    return s;
}

/* The two passes over restrict-qualified arrays, so that the compiler may
 * vectorise them as it does the emitted stepper's (same arithmetic, same
 * bits as loops over the workspace's pointers). */
static inline void hsv_drift(double *restrict q, const double *restrict p, const double *restrict f,
                             double *restrict cq, double hh)
{
    for (size_t k = 0; k < PEER_DIM; k++) q[k] = twosum(q[k], hh * PEER_VELOCITY(k, p[k] + 0.5 * hh * f[k]), &cq[k]);
}

static inline void hsv_kick(double *restrict p, const double *restrict f, const double *restrict g,
                            double *restrict cp, double hh)
{
    for (size_t k = 0; k < PEER_DIM; k++) p[k] = twosum(p[k], 0.5 * hh * (f[k] + g[k]), &cp[k]);
}

static int hsv_step(void *ws, double *t, double *q, double *p, double hh)
{
    hsv_ws *w = ws;
    if (!w->have_f) {
        w->f = w->buf[0];
        w->g = w->buf[1];
        peer_force(*t, q, w->f, pb);
        w->st.dHdq_evals++;
        w->have_f = 1;
    }
    double *f = w->f, *g = w->g;
    hsv_drift(q, p, f, w->cq, hh);
    peer_force(*t + hh, q, g, pb);
    hsv_kick(p, f, g, w->cp, hh);
    w->f = g;
    w->g = f;
    w->st.dHdq_evals++;
    *t += hh;
    return 0;
}
