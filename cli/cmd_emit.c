/* cmd_emit.c — `vigen emit FILE --name NAME`: renders the C stepper of a
 * tableau (or of a spec), audits the tableau, writes NAME.h and NAME.c. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "cli.h"
#include "vigen/emit.h"
#include "support/file.h"
#include "support/strbuf.h"

/* A stepper that is not what its user expects is worth a warning even with
 * -q: the conditions that certainly fail. */
static void audit(vigen_tableau *t, const char *file)
{
    int nwarn = 0;
    vigen_error aerr;
    vigen_error_init(&aerr);
    if (vigen_emit_audit(t, file, &nwarn, &aerr) != VIGEN_OK)
        vigen_warn("%s: could not check the tableau (%s); run 'vigen check %s'", file,
                   aerr.message ? aerr.message : vigen_status_name(aerr.code), file);
    vigen_error_clear(&aerr);
}

/* DIR/IDENT.h and DIR/IDENT.c, DIR created when missing (one level, like
 * mkdir DIR); the summary unless quiet. */
static int write_stepper(const char *dir, const char *ident, const char *h, const char *c, int quiet,
                         slong spec_digits, vigen_error *err)
{
    int rc = VIGEN_OK;
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        rc = vigen_error_set(err, VIGEN_E_WRITE, "cannot create the output directory %s: %s", dir, strerror(errno));
    size_t dl = strlen(dir);
    const char *sep = (dl > 0 && dir[dl - 1] == '/') ? "" : "/";
    char *hp = vigen_strdup_printf("%s%s%s.h", dir, sep, ident);
    char *cp = vigen_strdup_printf("%s%s%s.c", dir, sep, ident);
    /* both files or neither: a build sees the old pair or the new, never a mix */
    const char *paths[2] = { hp, cp }, *texts[2] = { h, c };
    if (rc == VIGEN_OK) rc = vigen_write_files_atomic(2, paths, texts, err);
    if (rc == VIGEN_OK && !quiet) {
        if (spec_digits > 0)
            fprintf(stderr, "vigen emit: wrote %s and %s (tableau generated from the spec with %ld certified digits)\n",
                    hp, cp, (long)spec_digits);
        else fprintf(stderr, "vigen emit: wrote %s and %s\n", hp, cp);
    }
    free(hp);
    free(cp);
    return rc;
}

int vigen_cmd_emit(const vigen_cli_args *args)
{
    const char *file = args->operand, *name = args->value[VIGEN_OPT_emit_name];
    const char *dir = args->value[VIGEN_OPT_emit_output] ? args->value[VIGEN_OPT_emit_output] : ".";
    int real = VIGEN_REAL_DOUBLE;
    if (args->value[VIGEN_OPT_emit_real]) {
        const char *r = args->value[VIGEN_OPT_emit_real];
        if (vigen_emit_real_parse(&real, r) != VIGEN_OK)
            return vigen_cli_usage_error(args->command, "--real takes %s, not '%s'", vigen_emit_real_names(), r);
    }
    size_t dim = 0;
    if (args->value[VIGEN_OPT_emit_dim]) {
        const char *d = args->value[VIGEN_OPT_emit_dim];
        char *end = NULL;
        errno = 0;
        unsigned long long v = (d[0] >= '0' && d[0] <= '9') ? strtoull(d, &end, 10) : 0;
        if (end == NULL || *end != '\0' || errno != 0 || v < 1 || v > VIGEN_EMIT_MAX_DIM)
            return vigen_cli_usage_error(args->command, "--dim takes a dimension from 1 to %d, not '%s'",
                                         VIGEN_EMIT_MAX_DIM, d);
        dim = (size_t)v;
    }
    const char *base = strrchr(file, '/');
    vigen_emit_options opt = { .name = name, .real = real, .input_label = base ? base + 1 : file,
                               .allow_inexact = args->value[VIGEN_OPT_emit_allow_inexact] != NULL,
                               .variant = args->value[VIGEN_OPT_emit_variant], .dim = dim,
                               .batch = args->value[VIGEN_OPT_emit_batch] != NULL };

    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau t;
    char *h = NULL, *c = NULL, *ident = NULL;
    int loaded = 0;
    int rc = vigen_emit_load_render(&t, &loaded, file, &opt, &h, &c, &ident, &err);
    if (rc == VIGEN_OK) audit(&t, file);
    slong spec_digits = rc == VIGEN_OK && t.generated_now ? t.digits : 0;
    if (loaded) vigen_tableau_clear(&t);
    if (rc == VIGEN_OK) {
        if (strcmp(ident, name) != 0) vigen_warn("--name '%s' is not a C identifier; using '%s'", name, ident);
        rc = write_stepper(dir, ident, h, c, args->value[VIGEN_OPT_emit_quiet] != NULL, spec_digits, &err);
    }
    free(h);
    free(c);
    free(ident);
    if (rc != VIGEN_OK) return vigen_cli_fail(args->command, &err);
    return 0;
}
