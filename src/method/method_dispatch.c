/* method_dispatch.c — a loaded method asked through its kind (methods.h):
 * its tableau, whether it is generated, and its release.  Apart from the
 * registry (registry.c), which loads methods, so that a kind holding other
 * methods (a composition's base) needs only this file. */
#include <stdlib.h>
#include "method/methods.h"

void vigen_method_free(vigen_method *m)
{
    if (m == NULL) return;
    m->kind->release(m->state);
    free(m);
}

int vigen_method_is_generated(const vigen_method *m) { return m->kind->generated; }

int vigen_method_tableau(vigen_tableau *t, vigen_method *m, slong digits, vigen_error *err)
{
    return m->kind->tableau(t, m->state, digits, err);
}
