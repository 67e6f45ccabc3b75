/* design_family.c — what each family of a design file is in terms of
 * unknowns: how many, which unknown each step of the written method is, and
 * its conditions (design_conditions.c). */
#include <string.h>
#include "design/design_internal.h"

int design_family_is_splitting(const vigen_design_spec *d)
{
    return strcmp(d->family, "splitting") == 0;
}

slong design_family_unknowns(const vigen_design_spec *d)
{
    if (design_family_is_splitting(d)) return design_splitting_unknowns(d->stages, d->symmetric);
    return d->symmetric ? (d->stages + 1) / 2 : d->stages;
}

slong design_family_nvalues(const vigen_design_spec *d)
{
    return design_family_is_splitting(d) ? 2 * (slong)d->stages + 1 : d->stages;
}

slong design_family_value_unknown(const vigen_design_spec *d, slong i)
{
    if (design_family_is_splitting(d)) return design_substep_unknown(i, d->stages, d->symmetric);
    return design_stage_unknown(i, d->stages, d->symmetric);
}

slong design_family_count(const vigen_design_spec *d, int q)
{
    if (design_family_is_splitting(d)) return design_splitting_count(d->symmetric, d->order);
    return design_composition_count(d->symmetric, q, d->order);
}

int design_family_conditions(design_system *sys, const vigen_design_spec *d, int q, vigen_error *err)
{
    if (design_family_is_splitting(d)) return design_splitting_conditions(sys, d->stages, d->symmetric, d->order, err);
    return design_composition_conditions(sys, d->stages, d->symmetric, q, d->order, err);
}
