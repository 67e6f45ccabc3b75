/* prk_field_real.h — the flow of the problem an emitted PRK workspace
 * begins with (vigen_prk_vector_field, the vector field of every emitted
 * NAME_type), repeated for each real type (instantiated by numeric.c
 * through real_instances.h). */

/* The first members of every emitted workspace (templates/prk keeps them
 * first and in this order). */
typedef struct {
    VIGEN_SFX(vigen_hamiltonian) sys;   /* the problem of NAME_alloc (dHdq NULL otherwise) */
    VIGEN_SFX(vigen_mechanical) mech;   /* the problem of NAME_alloc_mechanical */
    VIGEN_REAL *im;                     /* its diagonal of M^-1 */
} VIGEN_SFX(vigen_prk_head);

int VIGEN_SFX(vigen_prk_vector_field)(void *w, VIGEN_REAL t, const VIGEN_REAL *q, const VIGEN_REAL *p,
                                      VIGEN_REAL *dq, VIGEN_REAL *dp)
{
    const VIGEN_SFX(vigen_prk_head) *head = w;
    if (head->sys.dHdq && head->sys.dHdp) {
        head->sys.dHdp(t, q, p, dq, head->sys.ctx);
        head->sys.dHdq(t, q, p, dp, head->sys.ctx);
        for (size_t k = 0; k < head->sys.dim; k++) dp[k] = -dp[k];
        return VIGEN_SUCCESS;
    }
    if (head->mech.force == NULL || head->im == NULL) return VIGEN_EINVAL;
    head->mech.force(t, q, dp, head->mech.ctx);
    for (size_t k = 0; k < head->mech.dim; k++) dq[k] = head->im[k] * p[k];
    return VIGEN_SUCCESS;
}
