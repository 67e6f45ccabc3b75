/* validate.c — whether a Lagrangian problem and a velocity map can be
 * integrated (vigen_lagrangian_validate), with a one-line reason. */
#include <stddef.h>
#include <vigen/lagrangian.h>

int vigen_lagrangian_validate(const vigen_lagrangian *lag, const vigen_velocity_map *phi,
                              const char **why)
{
    const char *r = NULL;
    if (lag == NULL) r = "no Lagrangian given (NULL): pass a vigen_lagrangian";
    else if (lag->dim == 0) r = "the Lagrangian's dim is 0: set it to the number of coordinates";
    else if (lag->dLdq == NULL) r = "the Lagrangian's dLdq is NULL: give dL/dq(t, q, v)";
    else if (lag->dLdv == NULL) r = "the Lagrangian's dLdv is NULL: give dL/dv(t, q, v)";
    else if (phi != NULL) {
        if (phi->dim != lag->dim) r = "the velocity map's dim differs from the Lagrangian's";
        else if (phi->phi == NULL) r = "the velocity map's phi is NULL: give phi_h(q0, q1; a), or pass NULL for the trivial map";
        else if (phi->D1phi == NULL || phi->D2phi == NULL)
            r = "the velocity map's D1phi or D2phi is NULL: give both derivatives";
        else if (phi->nparams > 0 && phi->Daphi == NULL)
            r = "the velocity map has parameters (nparams > 0) but Daphi is NULL: give d phi / d a";
    }
    if (why) *why = r;
    return r ? VIGEN_EINVAL : VIGEN_SUCCESS;
}
