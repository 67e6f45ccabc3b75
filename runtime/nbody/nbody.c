/* nbody.c — the N-body system (masses, G, the scratch memory of its
 * flows), its energy and forces in the inertial frame, and the canonical
 * changes of coordinates inertial <-> Jacobi and inertial <-> democratic
 * heliocentric (vigen/nbody.h gives the formulas), and the force of the
 * Jacobi interaction that the interaction flows share.  Every change is linear,
 * q' = A x with p' = A^-T p; the same code maps velocities like positions
 * and forces like momenta, which the vector fields of flows.c use. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "nbody_internal.h"

int vigen_nbody_alloc(vigen_nbody **out, size_t n, double G, const double *mass)
{
    if (out == NULL) return VIGEN_EINVAL;
    *out = NULL;
    if (n < 2 || mass == NULL || !(G > 0) || !isfinite(G)) return VIGEN_EINVAL;
    for (size_t i = 0; i < n; i++)
        if (!(mass[i] > 0) || !isfinite(mass[i])) return VIGEN_EINVAL;
    vigen_nbody *s = calloc(1, sizeof *s);
    double *block = calloc(27 * n, sizeof *block);
    if (s == NULL || block == NULL) {
        free(s);
        free(block);
        return VIGEN_ENOMEM;
    }
    s->n = n;
    s->G = G;
    s->m = block;
    s->interior = block + n;
    s->frac = block + 2 * n;
    s->mred = block + 3 * n;
    s->mu = block + 4 * n;
    s->work = block + 5 * n;
    s->saved = block + 20 * n;
    s->gjac = block + 26 * n;
    double M = 0;
    for (size_t i = 0; i < n; i++) {
        s->m[i] = mass[i];
        double before = M;
        M += mass[i];
        s->interior[i] = M;
        s->frac[i] = mass[i] / M;
        s->mred[i] = i == 0 ? 0 : mass[i] * before / M;
        s->mu[i] = G * M;
        s->gjac[i] = G * mass[i] * before;
    }
    s->mtot = M;
    s->mred[0] = M;
    *out = s;
    return VIGEN_SUCCESS;
}

vigen_nbody *vigen_nbody_clone(const vigen_nbody *sys)
{
    vigen_nbody *c = NULL;
    if (sys == NULL || vigen_nbody_alloc(&c, sys->n, sys->G, sys->m) != VIGEN_SUCCESS) return NULL;
    return c;
}

void vigen_nbody_free(vigen_nbody *sys)
{
    if (sys == NULL) return;
    free(sys->m);
    free(sys->geo);
    free(sys);
}

size_t vigen_nbody_count(const vigen_nbody *sys) { return sys ? sys->n : 0; }

/* Neumaier's compensated sum, one term at a time. */
static void neumaier_add(double *s, double *c, double x)
{
    double t = *s + x;
    *c += fabs(*s) >= fabs(x) ? (*s - t) + x : (x - t) + *s;
    *s = t;
}

double vigen_nbody_energy(const vigen_nbody *sys, const double *x, const double *p)
{
    double s = 0, c = 0;
    size_t n = sys->n;
    for (size_t i = 0; i < n; i++) {
        const double *y = p + 3 * i;
        neumaier_add(&s, &c, (y[0] * y[0] + y[1] * y[1] + y[2] * y[2]) / (2 * sys->m[i]));
    }
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            double dx = x[3 * i] - x[3 * j], dy = x[3 * i + 1] - x[3 * j + 1], dz = x[3 * i + 2] - x[3 * j + 2];
            neumaier_add(&s, &c, -sys->G * sys->m[i] * sys->m[j] / sqrt(dx * dx + dy * dy + dz * dz));
        }
    return s + c;
}

/* Pair forces f_i = -dV/dx_i of V = -sum G m_i m_j/|x_i - x_j| over the
 * pairs i < j with i >= from, the pair (0, 1) left out when skip01; with
 * geo, each pair's d = x_j - x_i, k = G m_i m_j/|d|^3 and 3/|d|^2 stored
 * there in the order of the loops (5 per pair), for a second pass over the
 * same pairs.  Row i's force is summed in a register from f_i's value at
 * the start of the row: the additions are those of f_i += k d in j order. */
static inline void pair_pass(const vigen_nbody *sys, const double *x, double *f, size_t from, int skip01,
                             double *geo)
{
    size_t n = sys->n;
    const double *m = sys->m;
    for (size_t k = 0; k < 3 * n; k++) f[k] = 0;
    for (size_t i = from; i < n; i++) {
        double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2], gmi = sys->G * m[i];
        double fi0 = f[3 * i], fi1 = f[3 * i + 1], fi2 = f[3 * i + 2];
        for (size_t j = skip01 && i == 0 ? 2 : i + 1; j < n; j++) {
            double *fj = f + 3 * j;
            double d0 = x[3 * j] - xi0, d1 = x[3 * j + 1] - xi1, d2 = x[3 * j + 2] - xi2;
            double r2 = d0 * d0 + d1 * d1 + d2 * d2;
            double k = gmi * m[j] / (r2 * sqrt(r2));
            double e0 = k * d0, e1 = k * d1, e2 = k * d2;
            fi0 += e0;
            fi1 += e1;
            fi2 += e2;
            fj[0] -= e0;
            fj[1] -= e1;
            fj[2] -= e2;
            if (geo) {
                geo[0] = d0;
                geo[1] = d1;
                geo[2] = d2;
                geo[3] = k;
                geo[4] = 3 / r2;
                geo += 5;
            }
        }
        f[3 * i] = fi0;
        f[3 * i + 1] = fi1;
        f[3 * i + 2] = fi2;
    }
}

void vigen_nbody_pair_forces(const vigen_nbody *sys, const double *x, double *f, size_t from, int skip01)
{
    pair_pass(sys, x, f, from, skip01, NULL);
}

void vigen_nbody_forces(const vigen_nbody *sys, const double *x, double *f)
{
    vigen_nbody_pair_forces(sys, x, f, 0, 0);
}

/* ---- Jacobi ------------------------------------------------------------ */
/* Positions (and velocities): q_i = x_i - R_{i-1}, R_i = R_{i-1} + (m_i/M_i) q_i,
 * q_0 = R_{n-1}.  In place: x_i is read before q_i is written. */
void vigen_nbody_jacobi_positions(const vigen_nbody *sys, const double *x, double *q)
{
    double R[3] = { x[0], x[1], x[2] };
    for (size_t i = 1; i < sys->n; i++)
        for (int c = 0; c < 3; c++) {
            double qi = x[3 * i + c] - R[c];
            q[3 * i + c] = qi;
            R[c] += sys->frac[i] * qi;
        }
    for (int c = 0; c < 3; c++) q[c] = R[c];
}

void vigen_nbody_jacobi_positions_inverse(const vigen_nbody *sys, const double *q, double *x)
{
    double R0 = q[0], R1 = q[1], R2 = q[2];
    for (size_t i = sys->n - 1; i >= 1; i--) {
        const double *qi = q + 3 * i;
        double *xi = x + 3 * i, a = sys->frac[i], q0 = qi[0], q1 = qi[1], q2 = qi[2];
        R0 -= a * q0;
        R1 -= a * q1;
        R2 -= a * q2;
        xi[0] = R0 + q0;
        xi[1] = R1 + q1;
        xi[2] = R2 + q2;
    }
    x[0] = R0;
    x[1] = R1;
    x[2] = R2;
}

/* Momenta (and forces): P_i = p_0 + ... + p_i, p'_i = p_i - (m_i/M_i) P_i,
 * p'_0 = P_{n-1}; the inverse p_i = p'_i + (m_i/M_i) P_i from the top. */
void vigen_nbody_jacobi_momenta(const vigen_nbody *sys, const double *p, double *pj)
{
    double P[3] = { p[0], p[1], p[2] };
    for (size_t i = 1; i < sys->n; i++)
        for (int c = 0; c < 3; c++) {
            double pi = p[3 * i + c];
            P[c] += pi;
            pj[3 * i + c] = pi - sys->frac[i] * P[c];
        }
    for (int c = 0; c < 3; c++) pj[c] = P[c];
}

void vigen_nbody_jacobi_momenta_inverse(const vigen_nbody *sys, const double *pj, double *p)
{
    double P[3] = { pj[0], pj[1], pj[2] };
    for (size_t i = sys->n - 1; i >= 1; i--)
        for (int c = 0; c < 3; c++) {
            double pi = pj[3 * i + c] + sys->frac[i] * P[c];
            p[3 * i + c] = pi;
            P[c] -= pi;
        }
    for (int c = 0; c < 3; c++) p[c] = P[c];
}

/* The force of the Jacobi interaction, -dH_interaction/dq: the pair forces
 * mapped like momenta (vigen_nbody_jacobi_momenta's sums), and the Jacobi
 * terms of bodies 2.. ; with geo, the pairs' geometry (pair_pass), then
 * each Jacobi term's k = G m_i M_{i-1}/|q_i|^3 and 3/|q_i|^2. */
void vigen_nbody_jacobi_interaction_force(const vigen_nbody *sys, const double *q, double *x, double *f, double *geo)
{
    size_t n = sys->n;
    vigen_nbody_jacobi_positions_inverse(sys, q, x);
    /* the pair (0, 1) and the Jacobi term of body 1 cancel exactly
     * (x_1 - x_0 = q_1): both left out */
    if (geo) {
        pair_pass(sys, x, f, 0, 1, geo);
        geo += 5 * (n * (n - 1) / 2 - 1);
    } else {
        pair_pass(sys, x, f, 0, 1, NULL);
    }
    double P0 = f[0], P1 = f[1], P2 = f[2];
    for (size_t i = 1; i < n; i++) {
        double *fi = f + 3 * i, a = sys->frac[i], f0 = fi[0], f1 = fi[1], f2 = fi[2];
        P0 += f0;
        P1 += f1;
        P2 += f2;
        f0 -= a * P0;
        f1 -= a * P1;
        f2 -= a * P2;
        if (i >= 2) {
            const double *qi = q + 3 * i;
            double r2 = qi[0] * qi[0] + qi[1] * qi[1] + qi[2] * qi[2];
            double k = sys->gjac[i] / (r2 * sqrt(r2));
            f0 += k * qi[0];
            f1 += k * qi[1];
            f2 += k * qi[2];
            if (geo) {
                geo[0] = k;
                geo[1] = 3 / r2;
                geo += 2;
            }
        }
        fi[0] = f0;
        fi[1] = f1;
        fi[2] = f2;
    }
    f[0] = P0;
    f[1] = P1;
    f[2] = P2;
}

/* The change of the pairs' forces along u from their geometry geo
 * (pair_pass): df = -Hess(V) u, pairs i < j without (0, 1).  One pair's
 * force k d changes by k (du - 3 (d.du) d/|d|^2), du = u_j - u_i. */
void vigen_nbody_jacobi_pair_hessian(const vigen_nbody *sys, const double *geo, const double *u, double *df)
{
    size_t n = sys->n;
    for (size_t k = 0; k < 3 * n; k++) df[k] = 0;
    for (size_t i = 0; i < n; i++) {
        double ui0 = u[3 * i], ui1 = u[3 * i + 1], ui2 = u[3 * i + 2];
        double g0 = df[3 * i], g1 = df[3 * i + 1], g2 = df[3 * i + 2];
        for (size_t j = i == 0 ? 2 : i + 1; j < n; j++, geo += 5) {
            double *dj = df + 3 * j;
            double du0 = u[3 * j] - ui0, du1 = u[3 * j + 1] - ui1, du2 = u[3 * j + 2] - ui2;
            double s = geo[4] * (geo[0] * du0 + geo[1] * du1 + geo[2] * du2), k = geo[3];
            double e0 = k * (du0 - s * geo[0]), e1 = k * (du1 - s * geo[1]), e2 = k * (du2 - s * geo[2]);
            g0 += e0;
            g1 += e1;
            g2 += e2;
            dj[0] -= e0;
            dj[1] -= e1;
            dj[2] -= e2;
        }
        df[3 * i] = g0;
        df[3 * i + 1] = g1;
        df[3 * i + 2] = g2;
    }
}

/* ---- democratic heliocentric ----------------------------------------- */
/* q_0 = sum m_i x_i / M, q_i = x_i - x_0. */
void vigen_nbody_democratic_positions(const vigen_nbody *sys, const double *x, double *q)
{
    double X[3] = { 0, 0, 0 }, x0[3] = { x[0], x[1], x[2] };
    for (size_t i = 0; i < sys->n; i++)
        for (int c = 0; c < 3; c++) X[c] += sys->m[i] * x[3 * i + c];
    for (size_t i = 1; i < sys->n; i++)
        for (int c = 0; c < 3; c++) q[3 * i + c] = x[3 * i + c] - x0[c];
    for (int c = 0; c < 3; c++) q[c] = X[c] / sys->mtot;
}

/* x_0 = q_0 - sum_{i>=1} m_i q_i / M, x_i = q_i + x_0. */
void vigen_nbody_democratic_positions_inverse(const vigen_nbody *sys, const double *q, double *x)
{
    double S[3] = { 0, 0, 0 };
    for (size_t i = 1; i < sys->n; i++)
        for (int c = 0; c < 3; c++) S[c] += sys->m[i] * q[3 * i + c];
    double x0[3];
    for (int c = 0; c < 3; c++) x0[c] = q[c] - S[c] / sys->mtot;
    for (size_t i = 1; i < sys->n; i++)
        for (int c = 0; c < 3; c++) x[3 * i + c] = q[3 * i + c] + x0[c];
    for (int c = 0; c < 3; c++) x[c] = x0[c];
}

/* p'_0 = sum p_i, p'_i = p_i - (m_i/M) p'_0. */
void vigen_nbody_democratic_momenta(const vigen_nbody *sys, const double *p, double *pd)
{
    double P[3] = { 0, 0, 0 };
    for (size_t i = 0; i < sys->n; i++)
        for (int c = 0; c < 3; c++) P[c] += p[3 * i + c];
    for (size_t i = 1; i < sys->n; i++)
        for (int c = 0; c < 3; c++) pd[3 * i + c] = p[3 * i + c] - sys->m[i] / sys->mtot * P[c];
    for (int c = 0; c < 3; c++) pd[c] = P[c];
}

/* p_i = p'_i + (m_i/M) p'_0 (i >= 1), p_0 = p'_0 - sum_{i>=1} p_i. */
void vigen_nbody_democratic_momenta_inverse(const vigen_nbody *sys, const double *pd, double *p)
{
    double P[3] = { pd[0], pd[1], pd[2] }, p0[3] = { pd[0], pd[1], pd[2] };
    for (size_t i = 1; i < sys->n; i++)
        for (int c = 0; c < 3; c++) {
            double pi = pd[3 * i + c] + sys->m[i] / sys->mtot * P[c];
            p[3 * i + c] = pi;
            p0[c] -= pi;
        }
    for (int c = 0; c < 3; c++) p[c] = p0[c];
}

int vigen_nbody_to_jacobi(const vigen_nbody *sys, const double *x, const double *p, double *q, double *pj)
{
    if (!sys || !x || !p || !q || !pj) return VIGEN_EINVAL;
    vigen_nbody_jacobi_positions(sys, x, q);
    vigen_nbody_jacobi_momenta(sys, p, pj);
    return VIGEN_SUCCESS;
}

int vigen_nbody_from_jacobi(const vigen_nbody *sys, const double *q, const double *pj, double *x, double *p)
{
    if (!sys || !x || !p || !q || !pj) return VIGEN_EINVAL;
    vigen_nbody_jacobi_positions_inverse(sys, q, x);
    vigen_nbody_jacobi_momenta_inverse(sys, pj, p);
    return VIGEN_SUCCESS;
}

int vigen_nbody_to_democratic(const vigen_nbody *sys, const double *x, const double *p, double *q, double *pd)
{
    if (!sys || !x || !p || !q || !pd) return VIGEN_EINVAL;
    vigen_nbody_democratic_positions(sys, x, q);
    vigen_nbody_democratic_momenta(sys, p, pd);
    return VIGEN_SUCCESS;
}

int vigen_nbody_from_democratic(const vigen_nbody *sys, const double *q, const double *pd, double *x, double *p)
{
    if (!sys || !x || !p || !q || !pd) return VIGEN_EINVAL;
    vigen_nbody_democratic_positions_inverse(sys, q, x);
    vigen_nbody_democratic_momenta_inverse(sys, pd, p);
    return VIGEN_SUCCESS;
}

int vigen_nbody_to_coordinates(const vigen_nbody *sys, int coords, const double *x, const double *p, double *q,
                               double *pc)
{
    if (coords == VIGEN_NBODY_JACOBI) return vigen_nbody_to_jacobi(sys, x, p, q, pc);
    if (coords == VIGEN_NBODY_DEMOCRATIC) return vigen_nbody_to_democratic(sys, x, p, q, pc);
    return VIGEN_EINVAL;
}

int vigen_nbody_from_coordinates(const vigen_nbody *sys, int coords, const double *q, const double *pc, double *x,
                                 double *p)
{
    if (coords == VIGEN_NBODY_JACOBI) return vigen_nbody_from_jacobi(sys, q, pc, x, p);
    if (coords == VIGEN_NBODY_DEMOCRATIC) return vigen_nbody_from_democratic(sys, q, pc, x, p);
    return VIGEN_EINVAL;
}
