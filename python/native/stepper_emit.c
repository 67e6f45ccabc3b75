/* stepper_emit.c — `vigen emit` in-process for vigen.Stepper: the C text of
 * one method's stepper, which python/vigen/_cache.py compiles into a
 * stepper module. */
#include <stdlib.h>
#include <string.h>
#include "vigen/emit.h"
#include "python_internal.h"
#include "stepper.h"

int vigen_python_stepper_emit(vigen_python_result *r, const char *method, int real, int batch, int allow_inexact,
                              const char *template_dir)
{
    pyn_begin(r, "emit");
    if (real != VIGEN_REAL_DOUBLE && real != VIGEN_REAL_LONG_DOUBLE)
        return pyn_end(r, pyn_usage(r, "--real takes double or long-double here"));
    char *path = NULL;
    int rc = pyn_resolve(r, &path, method);
    if (rc != VIGEN_OK) return pyn_end(r, rc);
    const char *base = strrchr(path, '/');
    vigen_emit_options opt = { .name = "vstep", .real = real, .input_label = base ? base + 1 : path,
                               .template_dir = template_dir, .batch = batch != 0,
                               .allow_inexact = allow_inexact != 0 };
    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau t;
    int loaded = 0;
    char *h = NULL, *c = NULL, *ident = NULL;
    rc = vigen_emit_load_render(&t, &loaded, path, &opt, &h, &c, &ident, &err);
    if (rc == VIGEN_OK) {
        /* the warnings `vigen emit` gives on a tableau certainly not consistent or not symplectic */
        int nwarn = 0;
        vigen_error aerr;
        vigen_error_init(&aerr);
        if (vigen_emit_audit(&t, path, &nwarn, &aerr) != VIGEN_OK)
            vigen_warn("%s: could not check the tableau (%s); run 'vigen check %s'", path,
                       aerr.message ? aerr.message : vigen_status_name(aerr.code), path);
        vigen_error_clear(&aerr);
    }
    if (loaded) vigen_tableau_clear(&t);
    if (rc == VIGEN_OK) {
        r->text = c;
        r->extra = h;
        c = h = NULL;
    } else pyn_fail(r, &err);
    free(h);
    free(c);
    free(ident);
    free(path);
    return pyn_end(r, rc);
}
