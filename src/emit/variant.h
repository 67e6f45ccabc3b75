/* variant.h — the emitted variants (variants.def): each is a template
 * directory under templates/ and a slot builder that fills the template's
 * slots from a tableau. */
#ifndef VIGEN_EMIT_VARIANT_H
#define VIGEN_EMIT_VARIANT_H

#include "emit/literals.h"
#include "emit/template.h"

/* Fills S with every slot of the variant's templates for the tableau of E
 * at E->prec bits.  VIGEN_E_PRECISION: a coefficient cannot be rounded at
 * this precision (the driver retries higher). */
typedef int (*vigen_emit_slot_builder)(vigen_slots *S, emit_ctx *E, const vigen_emit_options *opt, const char *ident);

typedef struct {
    const char *name;        /* how options and messages call it; its folder templates/<name>/ */
    const char *description;
    vigen_emit_slot_builder build;
} vigen_emit_variant;

#define X(name, description, builder) \
    int builder(vigen_slots *S, emit_ctx *E, const vigen_emit_options *opt, const char *ident);
#include "emit/variants.def"
#undef X

/* The variant of that name (NULL: the first row, the default), or NULL when
 * there is none of that name. */
const vigen_emit_variant *vigen_emit_variant_find(const char *name);

#endif
