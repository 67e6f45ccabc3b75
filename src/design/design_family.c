/* design_family.c — what each family of a design file is in terms of
 * unknowns: how many, which unknown each step of the written method is, and
 * its conditions (design_conditions.c, design_quotient.c). */
#include <string.h>
#include "design/design_internal.h"

int design_family_is_splitting(const vigen_design_spec *d)
{
    return d->base == NULL;
}

unsigned design_family_mods(const vigen_design_spec *d)
{
    return (d->nystrom ? DESIGN_MOD_NYSTROM : 0) | (d->processed ? DESIGN_MOD_PROCESSED : 0);
}

slong design_family_unknowns(const vigen_design_spec *d)
{
    if (design_family_is_splitting(d)) return design_splitting_unknowns(d->stages, d->symmetric);
    return d->symmetric ? (d->stages + 1) / 2 : d->stages;
}

/* a processed method's values: the kernel's substeps, then the corrector's */
slong design_family_nvalues(const vigen_design_spec *d)
{
    if (d->processed) return 2 * (slong)d->stages + 1 + DESIGN_CORRECTOR_UNKNOWNS;
    return design_family_is_splitting(d) ? 2 * (slong)d->stages + 1 : d->stages;
}

slong design_family_value_unknown(const vigen_design_spec *d, slong i)
{
    slong n = 2 * (slong)d->stages + 1;
    if (d->processed && i >= n) return design_splitting_unknowns(d->stages, d->symmetric) + (i - n);
    if (design_family_is_splitting(d)) return design_substep_unknown(i, d->stages, d->symmetric);
    return design_stage_unknown(i, d->stages, d->symmetric);
}

slong design_family_count(const vigen_design_spec *d, int q)
{
    if (design_family_mods(d)) return design_quotient_count(d->order, d->symmetric, design_family_mods(d));
    if (design_family_is_splitting(d)) return design_splitting_count(d->symmetric, d->order);
    return design_composition_count(d->symmetric, q, d->order);
}

int design_family_conditions(design_system *sys, const vigen_design_spec *d, int q, vigen_error *err)
{
    if (d->ngeneralized > 0) return design_flows_conditions(sys, d->stages, d->symmetric, d->generalized,
                                                            d->ngeneralized, err);
    if (design_family_is_splitting(d)) return design_splitting_conditions(sys, d->stages, d->symmetric, d->order,
                                                                      design_family_mods(d), err);
    return design_composition_conditions(sys, d->stages, d->symmetric, q, d->order, err);
}
