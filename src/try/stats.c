/* stats.c — the least-squares slope of the energy error against time (the
 * drift per unit time), with compensated sums: the sums of t and t^2 over
 * up to a thousand samples would otherwise lose the digits the slope of a
 * small drift needs. */
#include <math.h>
#include "vigen/runtime.h"
#include "try/try_internal.h"

double try_lsq_slope(const double *x, const double *y, size_t n)
{
    if (n < 2) return NAN;
    vigen_neumaier sx, sy;
    vigen_neumaier_init(&sx);
    vigen_neumaier_init(&sy);
    for (size_t i = 0; i < n; i++) {
        vigen_neumaier_add(&sx, x[i]);
        vigen_neumaier_add(&sy, y[i]);
    }
    double mx = vigen_neumaier_result(&sx) / (double)n, my = vigen_neumaier_result(&sy) / (double)n;
    vigen_neumaier sxy, sxx;
    vigen_neumaier_init(&sxy);
    vigen_neumaier_init(&sxx);
    for (size_t i = 0; i < n; i++) {
        double dx = x[i] - mx;
        vigen_neumaier_add(&sxy, dx * (y[i] - my));
        vigen_neumaier_add(&sxx, dx * dx);
    }
    double d = vigen_neumaier_result(&sxx);
    return d > 0 ? vigen_neumaier_result(&sxy) / d : NAN;
}
