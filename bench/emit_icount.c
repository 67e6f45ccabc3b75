/* emit_icount.c — one stepper on one problem, for instruction counts under
 * valgrind's callgrind (bench/run_emit.sh), which are repeatable where wall
 * time on a shared machine is not:
 *
 *   valgrind --tool=callgrind --toggle-collect=stepping_loop_* emit_icount STEPPER PROBLEM STEPS
 *       counts the instructions of the stepping loop (steps after the first);
 *   valgrind --tool=callgrind --toggle-collect='grad_cb_*' ...
 *       counts those spent inside the gradient callbacks (the *_cb steppers).
 *
 * STEPPER: emit_g2_cb, hand_g2_cb, emit_g2_direct, hand_g2_direct,
 *          emit_sv_cb, hand_sv_cb, emit_sv_direct, hand_sv_direct,
 *          emit_sv_cb_nokahan, hand_sv_cb_nokahan
 * PROBLEM: kepler | fput
 * "cb": the gradients are called through out-of-line functions grad_cb_dq /
 * grad_cb_dp (the emitted stepper through the vigen_hamiltonian pointers,
 * the hand-written one by name); "direct": the emitted file compiled with
 * NAME_DIRECT_DHDQ/DHDP and the hand-written stepper both call the static
 * inline gradients, which the compiler may inline.  Built by
 * bench/emit_build.sh with the same flags as emit_bench. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/runtime.h>
#include "emit_problems.h"
#include "emit_g2.h"
#include "emit_sv.h"

#define EMIT_G2K_DIRECT_DHDQ kep_dq
#define EMIT_G2K_DIRECT_DHDP kep_dp
#include "emit_g2k.c"
#define EMIT_G2F_DIRECT_DHDQ fput_dq
#define EMIT_G2F_DIRECT_DHDP fput_dp
#include "emit_g2f.c"
#define EMIT_SVK_DIRECT_DHDQ kep_dq
#define EMIT_SVK_DIRECT_DHDP kep_dp
#include "emit_svk.c"
#define EMIT_SVF_DIRECT_DHDQ fput_dq
#define EMIT_SVF_DIRECT_DHDP fput_dp
#include "emit_svf.c"

/* the out-of-line gradients of the "cb" steppers */
static vigen_grad_fn cur_dq, cur_dp;
__attribute__((noinline)) static void grad_cb_dq(double t, const double *q, const double *p, double *o, void *c)
{
    cur_dq(t, q, p, o, c);
}
__attribute__((noinline)) static void grad_cb_dp(double t, const double *q, const double *p, double *o, void *c)
{
    cur_dp(t, q, p, o, c);
}

#define HG2_NAME hg2c
#define HG2_DQ grad_cb_dq
#define HG2_DP grad_cb_dp
#include "hand_gauss2.h"
#define HG2_NAME hg2k
#define HG2_DQ kep_dq
#define HG2_DP kep_dp
#include "hand_gauss2.h"
#define HG2_NAME hg2f
#define HG2_DQ fput_dq
#define HG2_DP fput_dp
#include "hand_gauss2.h"
#define HV_NAME hvc
#define HV_DQ grad_cb_dq
#define HV_DP grad_cb_dp
#include "hand_verlet.h"
#define HV_NAME hvk
#define HV_DQ kep_dq
#define HV_DP kep_dp
#include "hand_verlet.h"
#define HV_NAME hvf
#define HV_DQ fput_dq
#define HV_DP fput_dp
#include "hand_verlet.h"

/* one loop function per stepper, so that each step call is as a user writes it */
#define LOOP_EMITTED(N)                                                                                  \
    __attribute__((noinline)) static int stepping_loop_##N(void *w, double *t, double *q, double *p, double h, long n) \
    {                                                                                                    \
        int bad = 0;                                                                                     \
        for (long k = 0; k < n; k++) bad |= N##_step(w, t, q, p, h);                                     \
        return bad;                                                                                      \
    }
/* the hand-written step is a function called from the loop too, as the
 * emitted one is (left to itself the compiler would inline it here) */
#define LOOP_HAND(N)                                                                                     \
    __attribute__((noinline)) static int N##_call(void *w, double *t, double *q, double *p, double h)    \
    {                                                                                                    \
        return N##_step(w, t, q, p, h, NULL);                                                            \
    }                                                                                                    \
    __attribute__((noinline)) static int stepping_loop_##N(void *w, double *t, double *q, double *p, double h, long n) \
    {                                                                                                    \
        int bad = 0;                                                                                     \
        for (long k = 0; k < n; k++) bad |= N##_call(w, t, q, p, h);                                     \
        return bad;                                                                                      \
    }
LOOP_EMITTED(emit_g2)
LOOP_EMITTED(emit_g2k)
LOOP_EMITTED(emit_g2f)
LOOP_EMITTED(emit_sv)
LOOP_EMITTED(emit_svk)
LOOP_EMITTED(emit_svf)
LOOP_HAND(hg2c)
LOOP_HAND(hg2k)
LOOP_HAND(hg2f)
LOOP_HAND(hvc)
LOOP_HAND(hvk)
LOOP_HAND(hvf)

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: emit_icount STEPPER kepler|fput STEPS\n");
        return 2;
    }
    const char *who = argv[1];
    int fput = strcmp(argv[2], "fput") == 0;
    long steps = atol(argv[3]);
    size_t n = fput ? FPUT_N : 2;
    double *q = malloc(n * sizeof(double)), *p = malloc(n * sizeof(double)), t = 0, h = fput ? 0.05 : 0.01;
    if (fput) fput_init(q, p);
    else kep_init(0.6, q, p);
    cur_dq = fput ? fput_dq : kep_dq;
    cur_dp = fput ? fput_dp : kep_dp;
    vigen_hamiltonian cb = { n, grad_cb_dq, grad_cb_dp, fput ? fput_H : kep_H, NULL, 1, NULL };
    vigen_solver_options nk;
    vigen_solver_options_default(&nk);
    nk.kahan = 0;
    int kahan = strstr(who, "nokahan") == NULL;
    int bad = -1;

    /* the first step (start-up: no history, first gradient) runs outside the
     * counted loop */
#define RUN(alloc, loop, N, freefn)                                          \
    do {                                                                     \
        void *w = alloc;                                                     \
        bad = N##_step(w, &t, q, p, h) | loop(w, &t, q, p, h, steps - 1);    \
        freefn(w);                                                           \
    } while (0)
#define RUNH(alloc, loop, N, freefn)                                         \
    do {                                                                     \
        void *w = alloc;                                                     \
        bad = N##_step(w, &t, q, p, h, NULL) | loop(w, &t, q, p, h, steps - 1); \
        freefn(w);                                                           \
    } while (0)
    if (strcmp(who, "emit_g2_cb") == 0) RUN(emit_g2_alloc(&cb, NULL), stepping_loop_emit_g2, emit_g2, emit_g2_free);
    else if (strcmp(who, "hand_g2_cb") == 0) RUNH(hg2c_alloc(n), stepping_loop_hg2c, hg2c, hg2c_free);
    else if (strcmp(who, "emit_g2_direct") == 0 && !fput) RUN(emit_g2k_alloc(&cb, NULL), stepping_loop_emit_g2k, emit_g2k, emit_g2k_free);
    else if (strcmp(who, "emit_g2_direct") == 0) RUN(emit_g2f_alloc(&cb, NULL), stepping_loop_emit_g2f, emit_g2f, emit_g2f_free);
    else if (strcmp(who, "hand_g2_direct") == 0 && !fput) RUNH(hg2k_alloc(n), stepping_loop_hg2k, hg2k, hg2k_free);
    else if (strcmp(who, "hand_g2_direct") == 0) RUNH(hg2f_alloc(n), stepping_loop_hg2f, hg2f, hg2f_free);
    else if (strncmp(who, "emit_sv_cb", 10) == 0) RUN(emit_sv_alloc(&cb, kahan ? NULL : &nk), stepping_loop_emit_sv, emit_sv, emit_sv_free);
    else if (strncmp(who, "hand_sv_cb", 10) == 0) RUNH(hvc_alloc(n, kahan), stepping_loop_hvc, hvc, hvc_free);
    else if (strcmp(who, "emit_sv_direct") == 0 && !fput) RUN(emit_svk_alloc(&cb, NULL), stepping_loop_emit_svk, emit_svk, emit_svk_free);
    else if (strcmp(who, "emit_sv_direct") == 0) RUN(emit_svf_alloc(&cb, NULL), stepping_loop_emit_svf, emit_svf, emit_svf_free);
    else if (strcmp(who, "hand_sv_direct") == 0 && !fput) RUNH(hvk_alloc(n, 1), stepping_loop_hvk, hvk, hvk_free);
    else if (strcmp(who, "hand_sv_direct") == 0) RUNH(hvf_alloc(n, 1), stepping_loop_hvf, hvf, hvf_free);
    else {
        fprintf(stderr, "emit_icount: unknown stepper %s\n", who);
        return 2;
    }
    double H = fput ? fput_H(t, q, p, NULL) : kep_H(t, q, p, NULL);
    printf("%s %s %ld steps: t = %.6f, H = %.15g%s\n", who, argv[2], steps, t, H, bad ? " (a step failed)" : "");
    free(q);
    free(p);
    return bad != 0;
}
