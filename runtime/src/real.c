/* real.c — instantiates real_impl.h (the driver, finite differences, sums),
 * dense_impl.h (output at any time) and events_impl.h (events) for double,
 * long double and __float128. */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <vigen/runtime.h>

#define VIGEN_REAL double
#define VIGEN_SFX(name) name
#define VIGEN_EPS DBL_EPSILON
#define VIGEN_SQRT sqrt
#include "real_impl.h"
#include "dense_impl.h"
#include "events_impl.h"
#undef VIGEN_REAL
#undef VIGEN_SFX
#undef VIGEN_EPS
#undef VIGEN_SQRT

#define VIGEN_REAL long double
#define VIGEN_SFX(name) name##_ld
#define VIGEN_EPS LDBL_EPSILON
#define VIGEN_SQRT sqrtl
#include "real_impl.h"
#include "dense_impl.h"
#include "events_impl.h"
#undef VIGEN_REAL
#undef VIGEN_SFX
#undef VIGEN_EPS
#undef VIGEN_SQRT

#ifdef VIGEN_HAVE_FLOAT128
/* 2^-112; the square root 2^-56 is taken in long double, enough for a
 * finite-difference step. */
#define VIGEN_REAL vigen_float128
#define VIGEN_SFX(name) name##_q
#define VIGEN_EPS ((vigen_float128)1.925929944387235853055977942584927319e-34L)
#define VIGEN_SQRT(x) ((vigen_float128)sqrtl((long double)(x)))
#include "real_impl.h"
#include "dense_impl.h"
#include "events_impl.h"
#endif
