/* integrate.c — the drivers of a stepper type for double, long double and
 * __float128: vigen_integrate (integrate_real.h), output at any time
 * (dense_real.h) and events (events_real.h).  They reach the integrator
 * only through its vigen_stepper_type. */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <vigen/runtime.h>

#define VIGEN_REAL_TEMPLATE "../drive/integrate_real.h"
#include "../core/real_instances.h"
#define VIGEN_REAL_TEMPLATE "../drive/dense_real.h"
#include "../core/real_instances.h"
#define VIGEN_REAL_TEMPLATE "../drive/events_real.h"
#include "../core/real_instances.h"
