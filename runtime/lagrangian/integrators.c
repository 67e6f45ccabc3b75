/* integrators.c — the Lagrangian integrators by number
 * (vigen_lagrangian_integrator_alloc): a workspace and its stepper type, so
 * that a caller that picks the method at run time (vigen try's driver)
 * drives all of them through the type alone. */
#include <vigen/lagrangian.h>

void *vigen_lagrangian_integrator_alloc(int method, const vigen_lagrangian *lag, vigen_lgrad_fn g,
                                        const vigen_solver_options *opt, const vigen_stepper_type **type)
{
    void *w = NULL;
    const vigen_stepper_type *T = NULL;
    switch (method) {
    case VIGEN_LAGRANGIAN_HP_TRAPEZOIDAL:
    case VIGEN_LAGRANGIAN_HP_MIDPOINT:
        w = vigen_hp_alloc(lag, method == VIGEN_LAGRANGIAN_HP_TRAPEZOIDAL ? VIGEN_HP_TRAPEZOIDAL : VIGEN_HP_MIDPOINT,
                           NULL, opt);
        T = &vigen_hp_type;
        break;
    case VIGEN_LAGRANGIAN_MIDPOINT_VI:
        w = g ? vigen_midpoint_vi_alloc(lag, g, opt) : NULL;
        T = &vigen_midpoint_vi_type;
        break;
    case VIGEN_LAGRANGIAN_TRAPEZOIDAL_VI:
        w = vigen_trapezoidal_vi_alloc(lag, opt);
        T = &vigen_trapezoidal_vi_type;
        break;
    default:
        break;
    }
    if (type) *type = w ? T : NULL;
    return w;
}
