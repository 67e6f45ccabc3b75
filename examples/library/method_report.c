/* method_report.c — libvigen from C: load a method file (a spec or a tableau
 * file), certify its order and symplecticity, and write its C stepper.
 *
 *   method_report FILE [OUTDIR]
 *
 * prints one line, "NAME: s stages; order P (any H), Q (separable H);
 * symplectic yes|no|undecided", and with OUTDIR writes OUTDIR/NAME.h and
 * OUTDIR/NAME.c, for a tableau file the same bytes `vigen emit FILE --name
 * NAME` writes (a spec is generated here at 34 digits, by vigen emit at 40).  The
 * exit status follows the command line's map (0, 1 a FAILED or NOT DECIDED
 * verdict, 2 bad input, 3 a resource or system failure). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/vigen.h>

#ifndef VIGEN_TEMPLATES
#define VIGEN_TEMPLATES NULL
#endif

static const char *tri(int v) { return v == VIGEN_CHECK_YES ? "yes" : v == VIGEN_CHECK_NO ? "no" : "undecided"; }

static int fail(const char *what, vigen_error *err)
{
    fprintf(stderr, "method_report: %s: %s\n", what, err->message ? err->message : vigen_status_name(err->code));
    int status = vigen_status_exit_code(err->code);
    vigen_error_clear(err);
    return status;
}

/* Writes text to path; VIGEN_E_WRITE with a message naming the file. */
static int write_text(const char *path, const char *text, vigen_error *err)
{
    FILE *f = fopen(path, "w");
    int ok = f != NULL && fputs(text, f) >= 0;
    if (f != NULL && fclose(f) != 0) ok = 0;
    return ok ? VIGEN_OK : vigen_error_set(err, VIGEN_E_WRITE, "%s: cannot write the file", path);
}

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: method_report FILE [OUTDIR]\n");
        return 2;
    }
    vigen_error err;
    vigen_error_init(&err);

    /* The file runs once; its tableau is asked for at 34 certified digits
     * (generated for a spec, evaluated for a tableau file). */
    vigen_method *m = NULL;
    if (vigen_method_load(&m, argv[1], NULL, &err) != VIGEN_OK) return fail(argv[1], &err);
    vigen_tableau t;
    int rc = vigen_method_tableau(&t, m, 34, &err);
    vigen_method_free(m);
    if (rc != VIGEN_OK) return fail(argv[1], &err);

    vigen_check_options opt;
    vigen_check_options_init(&opt);
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    if (vigen_check_tableau(&rep, &t, NULL, &opt, &err) != VIGEN_OK) {
        vigen_check_report_clear(&rep);
        vigen_tableau_clear(&t);
        return fail(argv[1], &err);
    }
    printf("%s: %ld stages; order %d (any H), %d (separable H); symplectic %s\n", rep.name, (long)rep.s,
           rep.orders[VIGEN_CHECK_GENERAL].level.value, rep.orders[VIGEN_CHECK_SEPARABLE].level.value,
           tri(rep.symplectic));
    int status = rep.exit_code;
    vigen_check_report_clear(&rep);

    if (argc == 3 && status == 0) {
        vigen_emit_options eo = { .name = t.name, .real = VIGEN_REAL_DOUBLE, .input_label = argv[1],
                                  .template_dir = VIGEN_TEMPLATES };
        const char *base = strrchr(argv[1], '/');
        if (base) eo.input_label = base + 1;
        char *h = NULL, *c = NULL, *ident = NULL;
        rc = vigen_emit_render(&t, &eo, &h, &c, &ident, &err);
        if (rc == VIGEN_OK) {
            char *hp = malloc(strlen(argv[2]) + strlen(ident) + 4), *cp = malloc(strlen(argv[2]) + strlen(ident) + 4);
            sprintf(hp, "%s/%s.h", argv[2], ident);
            sprintf(cp, "%s/%s.c", argv[2], ident);
            rc = write_text(hp, h, &err);
            if (rc == VIGEN_OK) rc = write_text(cp, c, &err);
            free(hp);
            free(cp);
        }
        free(h);
        free(c);
        free(ident);
        if (rc != VIGEN_OK) status = fail(argv[1], &err);
    }
    vigen_tableau_clear(&t);
    return status;
}
