/* stepper_drive.c — the runtime's drivers for vigen.Stepper (stepper.h):
 * one foreign call per run, the steps in C. */
#include <string.h>
#include <vigen/ensemble.h>
#include <vigen/runtime.h>
#include "vigen_python.h"
#include "stepper.h"

#define VIGEN_SFX_OF(name) VPY_SFX(name)

#define VPY_REAL double
#define VPY_SFX(name) name
#include "stepper_real.h"
#undef VPY_REAL
#undef VPY_SFX

#define VPY_REAL long double
#define VPY_SFX(name) name##_ld
#include "stepper_real.h"
#undef VPY_REAL
#undef VPY_SFX

int vigen_python_integrate_ensemble(const void *type, const void *prototype, size_t dim, int threads,
                                    size_t ntraj, double *t, double *q, double *p, double h,
                                    unsigned long nsteps, int *status, unsigned long *steps)
{
    vigen_ensemble e = { .type = type, .dim = dim, .threads = threads, .prototype = prototype };
    return vigen_integrate_ensemble(&e, ntraj, t, q, p, h, nsteps, status, steps);
}

int vigen_python_ensemble_threads(void)
{
    return vigen_ensemble_max_threads();
}

const char *vigen_python_strerror(int status)
{
    return vigen_strerror(status);
}
