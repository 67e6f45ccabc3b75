/* numeric.c — the per-real-type numerics emitted steppers call
 * (numeric_real.h: finite-difference Jacobians, epsilon, compensated sums)
 * for double, long double and __float128. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <vigen/runtime.h>

#define VIGEN_REAL_TEMPLATE "numeric_real.h"
#include "real_instances.h"
