/* run.c — vigen_check_run: load the files, check, print the report, and
 * give the exit status.
 */
#include "check/check_internal.h"

static int load_file(vigen_tableau *t, const char *path, const vigen_check_options *opt, vigen_error *err)
{
    if (opt->load) return opt->load(t, path, opt->spec_digits, err);
    return vigen_tableau_load(t, path, NULL, err);
}

int vigen_check_run(const vigen_check_options *opt, FILE *out, vigen_error *err)
{
    if (opt->path == NULL) return vigen_status_exit_code(vigen_error_set(err, VIGEN_E_USAGE, "no tableau file given"));
    vigen_tableau t, u;
    int rc = load_file(&t, opt->path, opt, err);
    if (rc != VIGEN_OK) return vigen_status_exit_code(rc);
    if (opt->against) {
        rc = load_file(&u, opt->against, opt, err);
        if (rc != VIGEN_OK) {
            vigen_tableau_clear(&t);
            return vigen_status_exit_code(rc);
        }
    }
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    rc = vigen_check_tableau(&rep, &t, opt->against ? &u : NULL, opt, err);
    int code;
    if (rc != VIGEN_OK) {
        vigen_error_prefix(err, "%s: ", opt->path);
        code = vigen_status_exit_code(rc);
    } else {
        if (opt->json) vigen_check_print_json(out, &rep);
        else vigen_check_print_text(out, &rep);
        code = rep.exit_code;
    }
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    if (opt->against) vigen_tableau_clear(&u);
    return code;
}
