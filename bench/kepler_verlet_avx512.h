/* kepler_verlet_avx512.h — a hand-written velocity Störmer–Verlet for
 * Kepler ensembles with AVX-512 intrinsics: the limit the batched stepper
 * is measured against (bench/ensemble_bench.c).  Eight orbits per vector;
 * each group of eight is stepped to the end with its state, compensation and
 * force in registers (no memory traffic per step), the force reused from
 * the step before (first same as last).  The operations per orbit are those
 * of the emitted stepper with compensated sums (kick h/2 f, drift h p added
 * to q with vigen_twosum_next, force, kick, p updated the same way; t with
 * vigen_twosum_update), in the same order, so that the result has the same
 * bits; what it leaves out is the emitted stepper's per-orbit bookkeeping:
 * the finiteness test, the status and the restart test.  Header-only, for
 * the benchmark alone. */
#ifndef VIGEN_BENCH_KEPLER_VERLET_AVX512_H
#define VIGEN_BENCH_KEPLER_VERLET_AVX512_H

#include <stddef.h>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>
#define KV512_AVAILABLE 1

/* f = -q / |q|^3 for eight orbits */
__attribute__((target("avx512f"))) static inline void kv512_force(__m512d x, __m512d y, __m512d *fx, __m512d *fy)
{
    const __m512d r2 = _mm512_add_pd(_mm512_mul_pd(x, x), _mm512_mul_pd(y, y));
    const __m512d r3 = _mm512_mul_pd(r2, _mm512_sqrt_pd(r2));
    const __m512d zero = _mm512_setzero_pd();
    *fx = _mm512_div_pd(_mm512_sub_pd(zero, x), r3);
    *fy = _mm512_div_pd(_mm512_sub_pd(zero, y), r3);
}

/* x + d with the carried compensation c (vigen_twosum_next's operations) */
__attribute__((target("avx512f"))) static inline __m512d kv512_twosum(__m512d x, __m512d d, __m512d *c)
{
    const __m512d e = _mm512_add_pd(d, *c);
    const __m512d s = _mm512_add_pd(x, e);
    const __m512d bb = _mm512_sub_pd(s, x);
    *c = _mm512_add_pd(_mm512_sub_pd(x, _mm512_sub_pd(s, bb)), _mm512_sub_pd(e, bb));
    return s;
}

/* n orbits (n a multiple of 8) in structure-of-arrays layout: t[j],
 * q[j] and q[n + j] (x, y), p likewise; `steps` steps of size h each from
 * a fresh start (no compensation, force evaluated at the start). */
__attribute__((target("avx512f"))) static void kv512_run(size_t n, double *t, double *q, double *p, double h,
                                                         size_t steps)
{
    const __m512d hh = _mm512_set1_pd(0x1p-1 * h), hv = _mm512_set1_pd(h), one = _mm512_set1_pd(1);
    for (size_t j = 0; j < n; j += 8) {
        __m512d tt = _mm512_loadu_pd(t + j), x = _mm512_loadu_pd(q + j), y = _mm512_loadu_pd(q + n + j);
        __m512d px = _mm512_loadu_pd(p + j), py = _mm512_loadu_pd(p + n + j);
        __m512d ct = _mm512_setzero_pd(), cx = ct, cy = ct, cpx = ct, cpy = ct, fx, fy;
        kv512_force(x, y, &fx, &fy);
        for (size_t s = 0; s < steps; s++) {
            tt = kv512_twosum(tt, hv, &ct);
            const __m512d dpx = _mm512_mul_pd(hh, fx), dpy = _mm512_mul_pd(hh, fy);
            /* the drift h M^-1 (p + dp) with M^-1 = 1, as the emitted step */
            const __m512d dqx = _mm512_mul_pd(hv, _mm512_mul_pd(one, _mm512_add_pd(px, dpx)));
            const __m512d dqy = _mm512_mul_pd(hv, _mm512_mul_pd(one, _mm512_add_pd(py, dpy)));
            x = kv512_twosum(x, dqx, &cx);
            y = kv512_twosum(y, dqy, &cy);
            kv512_force(x, y, &fx, &fy);
            px = kv512_twosum(px, _mm512_add_pd(dpx, _mm512_mul_pd(hh, fx)), &cpx);
            py = kv512_twosum(py, _mm512_add_pd(dpy, _mm512_mul_pd(hh, fy)), &cpy);
        }
        _mm512_storeu_pd(t + j, tt);
        _mm512_storeu_pd(q + j, x);
        _mm512_storeu_pd(q + n + j, y);
        _mm512_storeu_pd(p + j, px);
        _mm512_storeu_pd(p + n + j, py);
    }
}
#else
#define KV512_AVAILABLE 0
#endif

#endif
