/* vigen/diagnostics.h — checks of a problem before it is integrated: the
 * gradients against central differences of the function they differentiate,
 * a problem marked separable against its promise, the optional second
 * derivatives against differences of the gradients, and finiteness.
 *
 *     vigen_problem_report rep;
 *     if (vigen_problem_check(&sys, t, q, p, &rep) != VIGEN_SUCCESS) {
 *         fprintf(stderr, "%s\n", rep.message);     one sentence
 *         return 1;
 *     }
 *
 * How it decides.  Each component k of a gradient is compared with the
 * central difference D(h) of the function along that variable, with h chosen
 * for the variable's scale: h = eps^(1/3) max(|x_k|, largest |x_j| of its
 * part), or for a part that is all zero (p = 0 at rest) the distance at
 * which the function changes by its own size; other steps are tried when the
 * function is not finite there or round-off swamps the differences.  D is
 * taken at the steps 2h, h and h/2: the differences between them estimate
 * the truncation error of D(h/2) (Richardson), and the round-off of the
 * function values (eps times the largest of |f| and sum_j |x_j g_j|, the
 * size of the terms that a sum cancels, or the noise of f measured by
 * fourth differences when larger) divided by h bounds the rest.  A
 * component is flagged when |g_k - D(h/2)| exceeds 8 times that error
 * estimate, so that the tolerance follows the function's own scale: correct
 * gradients of badly scaled problems (coordinates near 1e8, masses near
 * 1e-12) pass, while a sign error or a factor 2 fails by many orders of
 * magnitude (and so does a relative error of 1e-6 in a component of a
 * smooth problem).  The checks run at the state given and at two points
 * nearby (each variable moved by up to 2^-10 of its scale, from a fixed
 * pseudo-random sequence: the same report every run), so that a term that
 * vanishes at the state is still checked.  Parts longer than 64 components
 * are compared at 64 of them (16 at the nearby points), spread over the
 * part, and the whole gradient along two random directions, so that a wrong
 * component outside the sample still shows; second derivatives are compared
 * up to dimension 1024.  The cost is about 6 evaluations of the function per
 * component compared and point, and 6 gradients per column of second
 * derivatives.
 *
 * All functions are for double problems; they call the callbacks only (no
 * state is kept) and are thread-safe when the callbacks are.
 */
#ifndef VIGEN_DIAGNOSTICS_H
#define VIGEN_DIAGNOSTICS_H

#include <stddef.h>
#include <vigen/runtime.h>
#include <vigen/lagrangian.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int status;              /* VIGEN_SUCCESS or the problem found: VIGEN_EINVAL (missing
                                callbacks, dim 0, NULL state), VIGEN_ENONFINITE (a value or
                                gradient NaN or infinite at the state), VIGEN_EGRADIENT,
                                VIGEN_ESEPARABLE, VIGEN_EHESSIAN, VIGEN_ENOMEM */
    double worst_rel_error;  /* largest relative mismatch of a gradient against its finite
                                difference (relative to the larger of the two and of the
                                part's largest component); on a failure, that of the entry
                                reported */
    int worst_part;          /* 0 = dH/dq, 1 = dH/dp (mechanical: 0 = the force; Lagrangian:
                                0 = dL/dq, 1 = dL/dv); for a second derivative, the part of
                                its row; -1 when nothing was compared, or for a mismatch
                                along a random direction (worst_index: which) */
    size_t worst_index;      /* its component */
    char message[256];       /* one sentence naming the component and the size of the mismatch,
                                or on success what was checked */
    /* fields beyond the documented shape */
    size_t worst_column;     /* a second derivative's column (variables (q, p), (q, v), or q:
                                0 .. 2 dim - 1), else (size_t)-1 */
    int gradient_checked;    /* 1 when the function (H, V, L) was given and compared */
    int second_checked;      /* 1 when second derivatives were given and compared */
    int points;              /* points at which the checks ran (the state and nearby ones) */
} vigen_problem_report;

/* Checks sys at (t, q, p): finiteness of H (when given) and of both
 * gradients, both gradients against central differences of H (skipped when
 * H is NULL: success, and the message says so), separability when
 * sys->separable (dH/dp unchanged when t and q move, dH/dq unchanged when p
 * moves, at the nearby points), and sys->hessian (when set) against
 * differences of the gradients.  Returns rep->status.  rep may not be NULL. */
int vigen_problem_check(const vigen_hamiltonian *sys, double t, const double *q, const double *p,
                        vigen_problem_report *rep);

/* Checks a mechanical problem at (t, q): inv_mass (when given) and the force
 * finite, and the force against -(central differences of V) when V is given
 * (worst_part 0). */
int vigen_mechanical_check(const vigen_mechanical *sys, double t, const double *q, vigen_problem_report *rep);

/* Checks a Lagrangian at (t, q, v): L (when given), dL/dq and dL/dv finite;
 * dL/dq and dL/dv against central differences of L (when given); d2Ldq2,
 * d2Ldv2 and d2Ldqdv (each when set) against differences of dL/dq and dL/dv
 * (VIGEN_EHESSIAN). */
int vigen_lagrangian_check(const vigen_lagrangian *lag, double t, const double *q, const double *v,
                           vigen_problem_report *rep);

/* For code that stops on a bad problem, e.g. a stepper compiled with
 * -DVIGEN_CHECK_PROBLEM: runs the check and, when it fails, writes
 * "WHO: MESSAGE" on standard error.  Returns the status. */
int vigen_problem_check_or_say(const char *who, const vigen_hamiltonian *sys, double t, const double *q,
                               const double *p);
int vigen_mechanical_check_or_say(const char *who, const vigen_mechanical *sys, double t, const double *q);

#ifdef __cplusplus
}
#endif

#endif
