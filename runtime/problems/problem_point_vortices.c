/* problem_point_vortices.c — n point vortices of strengths Gamma_i in the
 * plane, in canonical coordinates q_i = x_i, p_i = Gamma_i y_i:
 *   H = -1/(4 pi) sum_{i<j} Gamma_i Gamma_j log |z_i - z_j|^2,
 * so that q' = dH/dp, p' = -dH/dq are Kirchhoff's equations
 *   x_i' = -1/(2 pi) sum_j Gamma_j (y_i - y_j)/r_ij^2,
 *   y_i' =  1/(2 pi) sum_j Gamma_j (x_i - x_j)/r_ij^2
 * (velocity Gamma/(2 pi r) counterclockwise around a positive vortex).  H is
 * not separable, and as a Lagrangian (L = sum p_i q_i' - H with p a function
 * of q's partner) it is degenerate: no Lagrangian version is offered.
 *
 * Standard value: Gamma_i = 1, the vortices at the n-th roots of unity, the
 * first moved radially by the parameter `perturbation`.  Unperturbed, the
 * polygon rotates rigidly with angular velocity Omega = (n - 1)/(4 pi) (the
 * reference solution); perturbed, there is none.  Invariants: the linear
 * impulse (sum Gamma x, sum Gamma y) and the angular impulse
 * sum Gamma (x^2 + y^2). */
#include <math.h>
#include <stdlib.h>
#include "problems_internal.h"

typedef struct {
    size_t n;
    double omega;      /* rigid rotation rate of the unperturbed polygon */
    double gamma[];    /* n strengths */
} vortices;

static const vortices *vortices_of(void *ctx) { return ((const vigen_problem *)ctx)->data; }

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t;
    const vortices *v = vortices_of(ctx);
    vigen_neumaier s = { 0, 0 };
    for (size_t i = 0; i < v->n; i++)
        for (size_t j = i + 1; j < v->n; j++) {
            double dx = q[i] - q[j], dy = p[i] / v->gamma[i] - p[j] / v->gamma[j];
            vigen_neumaier_add(&s, v->gamma[i] * v->gamma[j] * log(dx * dx + dy * dy));
        }
    return -vigen_neumaier_result(&s) / (4 * PBI_PI);
}

/* which = 0: dH/dq_i = -1/(2 pi) sum_j Gamma_i Gamma_j (x_i - x_j)/r^2;
 * which = 1: dH/dp_i = (1/Gamma_i) dH/dy_i = -1/(2 pi) sum_j Gamma_j (y_i - y_j)/r^2 */
static void gradient(const vortices *v, const double *q, const double *p, double *out, int which)
{
    for (size_t i = 0; i < v->n; i++) {
        double s = 0;
        for (size_t j = 0; j < v->n; j++) {
            if (j == i) continue;
            double dx = q[i] - q[j], dy = p[i] / v->gamma[i] - p[j] / v->gamma[j];
            double r2 = dx * dx + dy * dy;
            s += v->gamma[j] * (which == 0 ? v->gamma[i] * dx : dy) / r2;
        }
        out[i] = -s / (2 * PBI_PI);
    }
}

static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t;
    gradient(vortices_of(ctx), q, p, out, 0);
}

static void dHdp(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t;
    gradient(vortices_of(ctx), q, p, out, 1);
}

static const char *const names[] = { "linear-impulse-x", "linear-impulse-y", "angular-impulse" };

static double invariant(const vigen_problem *pb, size_t k, double t, const double *q, const double *p)
{
    (void)t;
    const vortices *v = pb->data;
    vigen_neumaier s = { 0, 0 };
    for (size_t i = 0; i < v->n; i++) {
        double y = p[i] / v->gamma[i];
        double term = k == 0 ? v->gamma[i] * q[i] : k == 1 ? p[i] : v->gamma[i] * (q[i] * q[i] + y * y);
        vigen_neumaier_add(&s, term);
    }
    return vigen_neumaier_result(&s);
}

/* Rigid rotation of the unperturbed polygon: z_k(t) = exp(i Omega t) z_k(0). */
static int reference(const vigen_problem *pb, double t, double *q, double *p)
{
    const vortices *v = pb->data;
    if (pb->param[1] != 0) return 0;
    double phase = remainder(v->omega * (t - pb->t0), 2 * PBI_PI), c = cos(phase), s = sin(phase);
    for (size_t i = 0; i < v->n; i++) {
        double x = pb->q0[i], y = pb->p0[i] / v->gamma[i];
        q[i] = c * x - s * y;
        p[i] = v->gamma[i] * (s * x + c * y);
    }
    return 1;
}

int vigen_pbi_point_vortices_setup(vigen_problem *pb)
{
    size_t n = (size_t)pb->param[0];
    vortices *v = malloc(sizeof *v + n * sizeof v->gamma[0]);
    if (v == NULL || vigen_pbi_set_dim(pb, n) != VIGEN_SUCCESS) {
        free(v);
        return VIGEN_ENOMEM;
    }
    pb->data = v;
    v->n = n;
    v->omega = (double)(n - 1) / (4 * PBI_PI);
    for (size_t i = 0; i < n; i++) {
        double angle = 2 * PBI_PI * (double)i / (double)n, radius = i == 0 ? 1 + pb->param[1] : 1;
        v->gamma[i] = 1;
        pb->q0[i] = radius * cos(angle);
        pb->p0[i] = v->gamma[i] * radius * sin(angle);
    }
    pb->ham = (vigen_hamiltonian){ .dHdq = dHdq, .dHdp = dHdp, .H = energy, .separable = 0 };
    pb->period = 2 * PBI_PI / v->omega;
    pb->default_time = 10 * pb->period;
    pb->ninvariants = 3;
    pb->invariant_names = names;
    pb->invariant = invariant;
    pb->reference = reference;
    return VIGEN_SUCCESS;
}
