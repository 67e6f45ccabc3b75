/* real_instances.h — instantiates a per-real-type template once for each
 * real type of the runtime: double (no suffix), long double (_ld) and, where
 * the compiler has it, __float128 (_q).
 *
 * The including file defines VIGEN_REAL_TEMPLATE, the template's path
 * relative to this folder (runtime/core), and includes this header; the
 * template sees VIGEN_REAL (the type), VIGEN_SFX(name) (the name with the
 * type's suffix), VIGEN_EPS (its machine epsilon) and VIGEN_SQRT (a square
 * root good to the type's precision, or to long double's for __float128,
 * enough for a finite-difference step).  The including file has included
 * <float.h>, <math.h> and <vigen/runtime.h>.  No include guard: included
 * once per template. */
#ifndef VIGEN_REAL_TEMPLATE
#error "define VIGEN_REAL_TEMPLATE before including real_instances.h"
#endif

#define VIGEN_REAL double
#define VIGEN_SFX(name) name
#define VIGEN_EPS DBL_EPSILON
#define VIGEN_SQRT sqrt
#include VIGEN_REAL_TEMPLATE
#undef VIGEN_REAL
#undef VIGEN_SFX
#undef VIGEN_EPS
#undef VIGEN_SQRT

#define VIGEN_REAL long double
#define VIGEN_SFX(name) name##_ld
#define VIGEN_EPS LDBL_EPSILON
#define VIGEN_SQRT sqrtl
#include VIGEN_REAL_TEMPLATE
#undef VIGEN_REAL
#undef VIGEN_SFX
#undef VIGEN_EPS
#undef VIGEN_SQRT

#ifdef VIGEN_HAVE_FLOAT128
/* 2^-112 */
#define VIGEN_REAL vigen_float128
#define VIGEN_SFX(name) name##_q
#define VIGEN_EPS ((vigen_float128)1.925929944387235853055977942584927319e-34L)
#define VIGEN_SQRT(x) ((vigen_float128)sqrtl((long double)(x)))
#include VIGEN_REAL_TEMPLATE
#undef VIGEN_REAL
#undef VIGEN_SFX
#undef VIGEN_EPS
#undef VIGEN_SQRT
#endif

#undef VIGEN_REAL_TEMPLATE
