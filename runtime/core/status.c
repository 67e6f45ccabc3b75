/* status.c — status messages, option defaults, naive sums. */
#include <vigen/runtime.h>

static const char *const vigen_status_messages[VIGEN_STATUS_MAX] = {
    "success",
    "invalid argument (NULL pointer, zero dimension, t or h not finite, or t + h overflows)",
    "out of memory",
    "stage iteration did not converge (increment stopped decreasing above the tolerance)",
    "stage iteration reached the iteration cap (raise max_iter, reduce h or use Newton)",
    "Newton iteration matrix is singular (reduce h)",
    "a gradient, stage value or the new state is NaN or infinite",
    "option not supported by this stepper",
    "stopped by the observer",
    "a gradient disagrees with central differences of H (a sign or a factor is wrong)",
    "the problem is marked separable but dH/dp depends on q or dH/dq on p",
    "the Hessian disagrees with differences of the gradients",
    "the saved state belongs to another stepper, dimension or runtime version",
};

const char *vigen_strerror(int status)
{
    if (status < 0 || status >= VIGEN_STATUS_MAX) return "unknown vigen status";
    return vigen_status_messages[status];
}

void vigen_solver_options_default(vigen_solver_options *opt)
{
    opt->solver = VIGEN_SOLVER_FIXED_POINT;
    opt->max_iter = 50;
    opt->tol = 0.0;
    opt->kahan = 1;
    opt->extrapolate = 1;
    opt->fd_step = 0.0;
    opt->start_force = 0;
}

double vigen_sum_naive(const double *x, size_t n)
{
    double s = 0.0;
    for (size_t i = 0; i < n; i++) s += x[i];
    return s;
}
