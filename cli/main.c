/* main.c — the vigen command line: parses arguments and dispatches to the
 * modules.  Nothing here computes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/check.h"
#include "cli.h"
#include "vigen/emit.h"
#include "vigen/show.h"
#include "vigen/method.h"
#include "vigen/tableau.h"

#define DEFAULT_DIGITS 34

static const char *usage_main =
    "usage: vigen COMMAND [OPTIONS]\n"
    "\n"
    "Certified symplectic partitioned Runge-Kutta methods.\n"
    "\n"
    "commands:\n"
    "  generate SPEC [--digits N] [-o FILE]   tableau of the Galerkin variational integrator of a spec\n"
    "  show FILE [--format text|latex|json|lua] [--digits N]\n"
    "                                         print a tableau (or the tableau of a spec)\n"
    "  check FILE [--against FILE2] [--max-order P] [--prec BITS] [--json]\n"
    "                                         certify order, symplecticity and consistency\n"
    "  emit FILE --name NAME [--real double|long-double|float128] [-o DIR] [-q]\n"
    "       [--allow-inexact]                 compile a tableau (or a spec) into a C stepper\n"
    "\n"
    "Options for every command (spec and tableau files run in a Lua sandbox):\n"
    "  --max-memory MIB        memory cap of the sandbox (default 256)\n"
    "  --max-instructions N    Lua instructions per call (default 50000000)\n"
    "\n"
    "Run 'vigen COMMAND --help' for the options of a command.\n";

static const char *usage_generate =
    "usage: vigen generate SPEC [--digits N] [-o FILE]\n"
    "\n"
    "Computes the tableau (c, A, b; ct, At) of the symplectic PRK method of Leok & Zhang\n"
    "(Theorem 3) for the basis functions and nodes of the spec file SPEC, in ball\n"
    "arithmetic, raising the working precision until every printed digit is certified.\n"
    "\n"
    "  --digits N   significant digits of every entry (default 34, up to 100000)\n"
    "  -o FILE      write the tableau file to FILE (atomically); default: standard output\n"
    "  -q, --quiet  do not print the summary on standard error\n"
    "\n"
    "Exit status: 0 success, 1 the method cannot be built (singular M, b_i = 0, complex\n"
    "nodes, digits that cannot be certified), 2 unusable input (unreadable or malformed\n"
    "file, an expression outside its domain, a complex basis value) or usage error.\n";

static const char *usage_show =
    "usage: vigen show FILE [--format text|latex|json|lua] [--digits N]\n"
    "\n"
    "Prints the tableau in FILE (a tableau file, or a spec file, which is generated first).\n"
    "  --format text   Butcher arrays, row sums and the symplecticity residual (default)\n"
    "  --format latex  the pair of Butcher arrays as LaTeX\n"
    "  --format json   {\"name\", \"s\", \"c\", \"A\", \"b\", \"At\", \"ct\"} with decimal strings\n"
    "  --format lua    the tableau file\n"
    "  --digits N      digits for entries given as exact expressions (default 34); decimal\n"
    "                  entries are printed as they are in the file\n";

/* 1: the mathematics fails (singular M, b_i = 0, complex nodes, a digit that
 * cannot be certified); 2: the input is unusable (unreadable, malformed, an
 * expression outside its domain such as log(-1) or a complex basis value). */
static int exit_code_for(int status)
{
    if (status == VIGEN_OK) return 0;
    if (status == VIGEN_E_MATH || status == VIGEN_E_PRECISION) return 1;
    return 2;
}

/* "vigen COMMAND: message" on standard error, the exit status for the error. */
static int fail(const char *command, vigen_error *err)
{
    fprintf(stderr, "vigen %s: %s\n", command, err->message ? err->message : vigen_status_name(err->code));
    int code = exit_code_for(err->code);
    vigen_error_clear(err);
    return code;
}

static int parse_digits(const char *text, slong *digits)
{
    char *end = NULL;
    long v = strtol(text, &end, 10);
    if (end == text || *end != '\0' || v < 1 || v > 100000) {
        fprintf(stderr, "vigen: --digits takes a whole number from 1 to 100000, not '%s'\n", text);
        return 0;
    }
    *digits = v;
    return 1;
}

static int is_help(const char *arg) { return strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0; }

/* An unknown option: the message, with the closest known option as a hint. */
static int unknown_option(const char *cmd, const char *arg, const char *const *known, const char *usage)
{
    const char *near = vigen_nearest_name(arg, known, 2);
    if (near) fprintf(stderr, "vigen %s: unknown or incomplete option '%s'; did you mean '%s'?\n\n%s", cmd, arg, near, usage);
    else fprintf(stderr, "vigen %s: unknown or incomplete option '%s'\n\n%s", cmd, arg, usage);
    return 2;
}

static int cmd_generate(int argc, char **argv)
{
    static const char cmd[] = "generate";
    static const char *const known[] = { "--digits", "-o", "-q", "--quiet", "--help", NULL };
    const char *spec_path = NULL, *out_path = NULL;
    slong digits = DEFAULT_DIGITS;
    int quiet = 0;
    for (int i = 0; i < argc; i++) {
        if (is_help(argv[i])) { fputs(usage_generate, stdout); return 0; }
        if (strcmp(argv[i], "--digits") == 0 && i + 1 < argc) {
            if (!parse_digits(argv[++i], &digits)) return 2;
        } else if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) out_path = argv[++i];
        else if (strcmp(argv[i], "-q") == 0 || strcmp(argv[i], "--quiet") == 0) quiet = 1;
        else if (argv[i][0] == '-' && argv[i][1] != '\0') return unknown_option(cmd, argv[i], known, usage_generate);
        else if (spec_path == NULL) spec_path = argv[i];
        else { fprintf(stderr, "vigen generate: one spec file at a time\n"); return 2; }
    }
    if (spec_path == NULL) {
        fprintf(stderr, "vigen generate: which spec file? (for example tableaux/specs/gauss_legendre_s2.lua)\n\n%s",
                usage_generate);
        return 2;
    }

    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau t;
    int rc = vigen_generate_file(&t, spec_path, digits, &err);
    if (rc != VIGEN_OK) return fail(cmd, &err);

    char *text = vigen_tableau_to_lua(&t);
    rc = vigen_write_file_atomic(out_path ? out_path : "-", text, &err);
    free(text);
    if (rc == VIGEN_OK && !quiet) {
        arb_t res;
        arb_init(res);
        vigen_tableau_symplectic_residual(res, &t, t.prec);
        char *r = arb_get_str(res, 5, 0);
        fprintf(stderr, "vigen: %s: %ld stages, %ld certified digits (working precision %ld bits); "
                        "symplecticity residual %s\n",
                t.name, (long)t.s, (long)digits, (long)t.prec, r);
        flint_free(r);
        arb_clear(res);
    }
    vigen_tableau_clear(&t);
    if (rc != VIGEN_OK) return fail(cmd, &err);
    return 0;
}

static int cmd_show(int argc, char **argv)
{
    static const char cmd[] = "show";
    static const char *const known[] = { "--format", "--digits", "--help", NULL };
    const char *path = NULL, *format = "text";
    slong digits = DEFAULT_DIGITS;
    for (int i = 0; i < argc; i++) {
        if (is_help(argv[i])) { fputs(usage_show, stdout); return 0; }
        if (strcmp(argv[i], "--format") == 0 && i + 1 < argc) format = argv[++i];
        else if (strcmp(argv[i], "--digits") == 0 && i + 1 < argc) {
            if (!parse_digits(argv[++i], &digits)) return 2;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') return unknown_option(cmd, argv[i], known, usage_show);
        else if (path == NULL) path = argv[i];
        else { fprintf(stderr, "vigen show: one file at a time\n"); return 2; }
    }
    if (path == NULL) {
        fprintf(stderr, "vigen show: which file? (a tableau file or a spec file)\n\n%s", usage_show);
        return 2;
    }
    vigen_show_format fmt;
    if (!vigen_show_parse_format(&fmt, format)) {
        fprintf(stderr, "vigen show: unknown format '%s' (use text, latex, json or lua)\n", format);
        return 2;
    }
    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau t;
    if (vigen_source_load(&t, path, digits, &err) != VIGEN_OK) return fail(cmd, &err);
    char *text = NULL;
    int rc = vigen_show_render(&text, &t, fmt, digits, &err);
    vigen_tableau_clear(&t);
    if (rc != VIGEN_OK) return fail(cmd, &err);
    fputs(text, stdout);
    free(text);
    return 0;
}

/* Removes the sandbox options from argv (they apply to every command);
 * returns 0 after printing a message when one is malformed. */
static int take_sandbox_options(int *argc, char **argv)
{
    vigen_sandbox_limits limits = {0, 0};
    int out = 1;
    for (int i = 1; i < *argc; i++) {
        int mem = strcmp(argv[i], "--max-memory") == 0, ins = strcmp(argv[i], "--max-instructions") == 0;
        if (!mem && !ins) { argv[out++] = argv[i]; continue; }
        char *end = NULL;
        long long v = i + 1 < *argc ? strtoll(argv[i + 1], &end, 10) : 0;
        if (i + 1 >= *argc || end == argv[i + 1] || *end != '\0' || v < 1 || (mem && v > 1048576)) {
            fprintf(stderr, "vigen: %s takes a positive whole number%s\n", argv[i], mem ? " of MiB (at most 1048576)" : "");
            return 0;
        }
        if (mem) limits.memory_limit = (size_t)v << 20;
        else limits.instruction_limit = (long)v;
        i++;
    }
    *argc = out;
    argv[out] = NULL;
    vigen_sandbox_limits_set_default(&limits);
    return 1;
}

int main(int argc, char **argv)
{
    if (!take_sandbox_options(&argc, argv)) return 2;
    if (argc < 2 || is_help(argv[1])) {
        fputs(usage_main, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (strcmp(argv[1], "--version") == 0) { printf("vigen %s\n", VIGEN_VERSION); return 0; }
    int rc;
    if (strcmp(argv[1], "generate") == 0) rc = cmd_generate(argc - 2, argv + 2);
    else if (strcmp(argv[1], "show") == 0) rc = cmd_show(argc - 2, argv + 2);
    else if (strcmp(argv[1], "emit") == 0) rc = vigen_emit_main(argc - 1, argv + 1);
    else if (strcmp(argv[1], "check") == 0) rc = vigen_check_main(argc - 2, argv + 2, vigen_source_load);
    else {
        fprintf(stderr, "vigen: unknown command '%s'\n\n%s", argv[1], usage_main);
        rc = 2;
    }
    flint_cleanup();
    return rc;
}
