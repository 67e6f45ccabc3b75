/* spec.h — nothing: the spec reader is method/spec.h.  This name stays only
 * while src/emit/emit.c and tests/unit/test_emit.c still include it; both
 * include method/galerkin.h first, which brings method/spec.h.  It includes
 * nothing itself, so that src/lua needs nothing of src/method. */
