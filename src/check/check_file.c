/* check_file.c — vigen_check_file: load FILE (and FILE2 of --against) and
 * check it.  Printing the report is the caller's (src/report).
 */
#include "check/check_internal.h"

static int load_file(vigen_tableau *t, const char *path, const vigen_check_options *opt, vigen_error *err)
{
    if (opt->load) return opt->load(t, path, opt->spec_digits, err);
    return vigen_tableau_load(t, path, NULL, err);
}

int vigen_check_file(vigen_check_report *rep, const vigen_check_options *opt, vigen_error *err)
{
    if (opt->path == NULL) return vigen_error_set(err, VIGEN_E_USAGE, "no tableau file given");
    vigen_tableau t, u;
    int rc = load_file(&t, opt->path, opt, err);
    if (rc != VIGEN_OK) return rc;
    if (opt->against) {
        rc = load_file(&u, opt->against, opt, err);
        if (rc != VIGEN_OK) {
            vigen_tableau_clear(&t);
            return rc;
        }
    }
    rc = vigen_check_tableau(rep, &t, opt->against ? &u : NULL, opt, err);
    if (rc != VIGEN_OK) vigen_error_prefix(err, "%s: ", opt->path);
    vigen_tableau_clear(&t);
    if (opt->against) vigen_tableau_clear(&u);
    return rc;
}
