/* method_galerkin.c — the "galerkin" row of methods.def: a spec file, whose
 * tableau the Galerkin generator computes at the digits asked for. */
#include "method/galerkin.h"
#include "method/methods.h"

int vigen_method_galerkin_read(void **state, vigen_sandbox *sb, const char *path, vigen_method_loader load,
                                vigen_error *err)
{
    vigen_spec *spec = NULL;
    int rc = vigen_spec_from_table(&spec, sb, path, err);
    *state = spec;
    return rc;
}

int vigen_method_galerkin_tableau(vigen_tableau *t, void *state, slong digits, vigen_error *err)
{
    return vigen_galerkin_generate(t, state, digits, err);   /* its messages name the file */
}

void vigen_method_galerkin_release(void *state) { vigen_spec_free(state); }
