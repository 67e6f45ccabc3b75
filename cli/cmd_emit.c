/* cmd_emit.c — `vigen emit`: parses the options, renders, audits, writes. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "vigen/emit.h"
#include "cli.h"

static const char usage_emit[] =
    "usage: vigen emit FILE --name NAME [--real double|long-double|float128] [-o DIR]\n"
    "                  [--allow-inexact] [-q]\n"
    "\n"
    "Compiles FILE into a C stepper: writes DIR/NAME.h and DIR/NAME.c (atomically), to be\n"
    "compiled with -std=c11 and linked against the vigen runtime.  FILE is a tableau file,\n"
    "or a spec file (nodes and basis, as for 'vigen generate'), which is generated first\n"
    "with 40 certified digits (60 for float128), enough to round every coefficient\n"
    "correctly; the header of the output says so.  Coefficients are correctly rounded\n"
    "from certified balls to the target type.\n"
    "\n"
    "  --name NAME      prefix of every emitted symbol (made a C identifier if needed)\n"
    "  --real TYPE      double (default), long-double (x87, 64-bit mantissa) or float128\n"
    "  -o DIR           output directory (default: the current directory)\n"
    "  --allow-inexact  an entry given as a decimal with too few digits to determine its\n"
    "                   correctly rounded value (a 16-digit textbook tableau, or a tableau\n"
    "                   generated with the default 34 digits emitted as float128) is\n"
    "                   refused; with this option it is rounded as written, and one\n"
    "                   warning says how many entries were.  The coefficients are then only\n"
    "                   as good as those decimals: use it when no more digits exist; for a\n"
    "                   generated tableau, regenerate with 'vigen generate SPEC --digits 40'\n"
    "                   (60 for float128) or emit the spec itself instead\n"
    "  -q, --quiet      no summary on standard error (warnings are still printed)\n"
    "\n"
    "The tableau is checked as 'vigen check' does (row sums, sum b = 1, symplecticity;\n"
    "not the order): when a condition certainly fails, a warning on standard error says\n"
    "which, and the stepper is still written (exit status 0).  Conditions that hold only\n"
    "within the precision of rounded entries, or are undecided, give no warning.\n"
    "\n"
    "Exit status: 0 success, 1 the tableau cannot be rounded (too few digits) or the spec\n"
    "cannot be generated, 2 unreadable input, usage or output error.\n";

int vigen_emit_main(int argc, char **argv)
{
    const char *file = NULL, *name = NULL, *dir = ".";
    int real = VIGEN_REAL_DOUBLE, quiet = 0, inexact = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) { fputs(usage_emit, stdout); return 0; }
        if ((strcmp(a, "--name") == 0 || strcmp(a, "--real") == 0 || strcmp(a, "-o") == 0) && i + 1 >= argc) {
            fprintf(stderr, "vigen emit: %s needs a value\n%s", a, usage_emit);
            return 2;
        }
        if (strcmp(a, "--name") == 0) name = argv[++i];
        else if (strcmp(a, "-o") == 0) dir = argv[++i];
        else if (strcmp(a, "--real") == 0) {
            const char *r = argv[++i];
            if (strcmp(r, "double") == 0) real = VIGEN_REAL_DOUBLE;
            else if (strcmp(r, "long-double") == 0) real = VIGEN_REAL_LONG_DOUBLE;
            else if (strcmp(r, "float128") == 0) real = VIGEN_REAL_FLOAT128;
            else {
                fprintf(stderr, "vigen emit: --real takes double, long-double or float128, not '%s'\n", r);
                return 2;
            }
        } else if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0) quiet = 1;
        else if (strcmp(a, "--allow-inexact") == 0) inexact = 1;
        else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "vigen emit: unknown option '%s'\n%s", a, usage_emit);
            return 2;
        } else if (file == NULL) file = a;
        else {
            fprintf(stderr, "vigen emit: more than one input file ('%s', '%s')\n", file, a);
            return 2;
        }
    }
    if (file == NULL || name == NULL) {
        fprintf(stderr, "vigen emit: FILE and --name are required\n%s", usage_emit);
        return 2;
    }
    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau t;
    const char *base = strrchr(file, '/');
    vigen_emit_options opt = { name, real, base ? base + 1 : file, inexact };
    char *h = NULL, *c = NULL, *ident = NULL;
    int loaded = 0;
    int rc = vigen_emit_load_render(&t, &loaded, file, &opt, &h, &c, &ident, &err);
    if (rc != VIGEN_OK && !loaded) {
        /* unreadable or malformed input; a spec whose method cannot be built
         * (singular M, b_i = 0, complex nodes) exits with 1 like vigen generate */
        fprintf(stderr, "vigen emit: %s\n", err.message ? err.message : vigen_status_name(rc));
        vigen_error_clear(&err);
        return (rc == VIGEN_E_MATH || rc == VIGEN_E_PRECISION) ? 1 : 2;
    }
    if (rc != VIGEN_OK && err.message) vigen_error_prefix(&err, "%s: ", file);
    if (rc == VIGEN_OK) {
        /* not silenced by -q: a stepper that is not what its user expects is
         * worth a line even in a quiet build */
        int nwarn = 0;
        vigen_error aerr;
        vigen_error_init(&aerr);
        if (vigen_emit_audit(&t, file, &nwarn, &aerr) != VIGEN_OK)
            vigen_warn("%s: could not check the tableau (%s); run 'vigen check %s'", file,
                       aerr.message ? aerr.message : vigen_status_name(aerr.code), file);
        vigen_error_clear(&aerr);
    }
    slong spec_digits = rc == VIGEN_OK && t.generated_now ? t.digits : 0;
    vigen_tableau_clear(&t);
    if (rc == VIGEN_OK) {
        if (strcmp(ident, name) != 0) vigen_warn("--name '%s' is not a C identifier; using '%s'", name, ident);
        /* -o DIR is created when missing (one level, like mkdir DIR) */
        if (mkdir(dir, 0777) != 0 && errno != EEXIST)
            rc = vigen_error_set(&err, VIGEN_E_IO, "cannot create the output directory %s: %s", dir, strerror(errno));
        size_t dl = strlen(dir);
        const char *sep = (dl > 0 && dir[dl - 1] == '/') ? "" : "/";
        char *hp = vigen_strdup_printf("%s%s%s.h", dir, sep, ident);
        char *cp = vigen_strdup_printf("%s%s%s.c", dir, sep, ident);
        if (rc == VIGEN_OK) rc = vigen_write_file_atomic(hp, h, &err);
        if (rc == VIGEN_OK) rc = vigen_write_file_atomic(cp, c, &err);
        if (rc == VIGEN_OK && !quiet) {
            if (spec_digits > 0)
                fprintf(stderr, "vigen emit: wrote %s and %s (tableau generated from the spec with %ld certified digits)\n",
                        hp, cp, (long)spec_digits);
            else fprintf(stderr, "vigen emit: wrote %s and %s\n", hp, cp);
        }
        free(hp);
        free(cp);
    }
    free(h);
    free(c);
    free(ident);
    if (rc != VIGEN_OK) {
        fprintf(stderr, "vigen emit: %s\n", err.message ? err.message : vigen_status_name(rc));
        vigen_error_clear(&err);
        return (rc == VIGEN_E_PRECISION || rc == VIGEN_E_DOMAIN || rc == VIGEN_E_MATH) ? 1 : 2;
    }
    return 0;
}
