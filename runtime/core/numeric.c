/* numeric.c — the per-real-type numerics emitted steppers call
 * (numeric_real.h: finite-difference Jacobians, epsilon, compensated sums;
 * prk_field_real.h: the flow of an emitted workspace's problem) for double,
 * long double and __float128. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <vigen/runtime.h>

#define VIGEN_REAL_TEMPLATE "numeric_real.h"
#include "real_instances.h"
#define VIGEN_REAL_TEMPLATE "prk_field_real.h"
#include "real_instances.h"
