/* main.c — the vigen command line: finds the command, parses its arguments
 * with the tables of commands.def, applies the global options, dispatches to
 * the command's handler and makes sure standard output was written.  Nothing
 * here computes. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "cli.h"
#include "vigen/library.h"
#include "vigen/method.h"
#include "support/guard.h"
#include "vigen/limits.h"
#include "vigen/tableau.h"
#include "support/strbuf.h"

typedef int (*handler_fn)(const vigen_cli_args *args);

static const handler_fn handlers[VIGEN_CMD_COUNT] = {
#define COMMAND(name, operand, ask, summary, help) vigen_cmd_##name,
#include "commands.def"
};

/* --max-memory and --max-instructions become the caps of every Lua state,
 * --max-prec the cap on working precision. */
static int apply_sandbox_options(const vigen_cli_args *args)
{
    vigen_sandbox_limits limits = {0, 0};
    long long v;
    int rc;
    if (args->value[VIGEN_OPT_global_max_memory]) {
        if ((rc = vigen_cli_whole(&v, args, VIGEN_OPT_global_max_memory, 1, 1048576)) >= 0) return rc;
        limits.memory_limit = (size_t)v << 20;
    }
    if (args->value[VIGEN_OPT_global_max_instructions]) {
        if ((rc = vigen_cli_whole(&v, args, VIGEN_OPT_global_max_instructions, 1, 1000000000000LL)) >= 0) return rc;
        limits.instruction_limit = (long)v;
    }
    vigen_sandbox_limits_set_default(&limits);
    if (args->value[VIGEN_OPT_global_max_prec]) {
        if ((rc = vigen_cli_whole(&v, args, VIGEN_OPT_global_max_prec, 64, 1LL << 40)) >= 0) return rc;
        vigen_prec_limit_set((long)v);
    }
    return -1;
}

/* Caps of the process (support/guard.h): --max-seconds, and the arithmetic's
 * memory, VIGEN_CLI_ARITH_FACTOR times --max-memory.  The time cap is finite
 * because vigen runs at build time on files from elsewhere: a build step
 * that hangs is worse than one that fails.  The specs of tableaux/ generate
 * in well under a second each and emit in a few; a Lua basis (certified
 * quadrature) at --digits 10000 takes about two minutes, so 600 s leaves
 * room for slower machines and heavy requests, and a user who means a longer
 * run says so.  The arithmetic of those runs holds a few tens of MiB, far
 * below 4 x 256 MiB. */
enum { VIGEN_CLI_MAX_SECONDS = 600, VIGEN_CLI_ARITH_FACTOR = 4 };

static int apply_caps(const vigen_cli_args *args, int command)
{
    long long seconds = VIGEN_CLI_MAX_SECONDS;
    int rc;
    if (args->value[VIGEN_OPT_global_max_seconds] &&
        (rc = vigen_cli_whole(&seconds, args, VIGEN_OPT_global_max_seconds, 1, 31536000)) >= 0)
        return rc;
    vigen_sandbox_limits limits; /* --max-memory is there already */
    vigen_sandbox_limits_default(&limits);
    char program[64];
    snprintf(program, sizeof program, "vigen %s", vigen_cli_commands[command].name);
    vigen_guard_caps caps = { program, (unsigned long)seconds, limits.memory_limit * VIGEN_CLI_ARITH_FACTOR };
    vigen_guard_set_caps(&caps);
    return -1;
}

/* A write error on standard output (a full disk, a closed pipe) is a failure
 * of the command, not a success with a truncated result. */
static int finish_output(int command, int status)
{
    int failed = fflush(stdout) != 0 || ferror(stdout);
    int saved = errno;
    if (fclose(stdout) != 0 && !failed) {
        failed = 1;
        saved = errno;
    }
    if (!failed) return status;
    /* a command that failed has said so already, most likely for this cause */
    if (status >= 2) return 3;
    vigen_error err;
    vigen_error_init(&err);
    vigen_error_set(&err, VIGEN_E_WRITE, "cannot write the standard output: %s", strerror(saved));
    return vigen_cli_fail(command, &err);
}

/* Method names in operands become files (vigen/library.h): a FILE or SPEC
 * operand must resolve; a METHOD (try, order) may also be a built-in name,
 * which the command knows, so it is left as it is when nothing matches.
 * Repeated operands hold one word a line. */
static int resolve_operands(vigen_cli_args *args, int command)
{
    const char *kind = vigen_cli_commands[command].operand;
    int files = strncmp(kind, "FILE", 4) == 0 || strncmp(kind, "SPEC", 4) == 0;
    int methods = strstr(kind, "METHOD") != NULL;
    if (args->operand == NULL || (!files && !methods)) return -1;
    static char *resolved;   /* lives as long as the process, like the parsed arguments */
    vigen_strbuf out;
    vigen_strbuf_init(&out);
    int rc = -1;
    for (const char *w = args->operand; w != NULL && rc < 0;) {
        const char *nl = strchr(w, '\n');
        char *word = vigen_strdup(w);
        if (nl) word[nl - w] = '\0';
        char *path = NULL;
        vigen_error err;
        vigen_error_init(&err);
        /* a path (or anything that exists) goes to the loader, whose
         * messages say what is wrong with it */
        struct stat st;
        int name = stat(word, &st) != 0 && (strchr(word, '/') == NULL || strncmp(word, "published/", 10) == 0 ||
                                            strncmp(word, "generated/", 10) == 0);
        if (!name) vigen_strbuf_printf(&out, "%s%s", out.len ? "\n" : "", word);
        else if (vigen_library_resolve(&path, word, &err) == VIGEN_OK)
            vigen_strbuf_printf(&out, "%s%s", out.len ? "\n" : "", path);
        else if (methods) vigen_strbuf_printf(&out, "%s%s", out.len ? "\n" : "", word);
        else rc = vigen_cli_fail(command, &err);
        vigen_error_clear(&err);
        free(path);
        free(word);
        w = nl ? nl + 1 : NULL;
    }
    if (rc < 0) {
        free(resolved);
        resolved = vigen_strdup(out.data ? out.data : "");
        args->operand = resolved;
    }
    vigen_strbuf_clear(&out);
    return rc;
}

static int run(int *command_out, int argc, char **argv)
{
    vigen_cli_args args;
    memset(&args, 0, sizeof args);
    args.command = VIGEN_CMD_global;
    int at = 0, rc;
    if ((rc = vigen_cli_parse(&args, VIGEN_CMD_global, argc, argv, &at)) >= 0) return rc;
    if (at == argc) {
        if (args.value[VIGEN_OPT_global_version]) return vigen_cmd_version(&args);
        if (args.value[VIGEN_OPT_global_help]) return vigen_cmd_help(&args);
        fputs("vigen: which command?", stderr);
        for (int c = 0; c < VIGEN_CMD_COUNT; c++)
            fprintf(stderr, "%s%s", c == 0 ? " " : c + 1 < VIGEN_CMD_COUNT ? ", " : " or ", vigen_cli_commands[c].name);
        fputs("\nsee 'vigen help'\n", stderr);
        return 2;
    }
    int command = vigen_cli_command_index(argv[at]);
    if (command < 0) return vigen_cli_unknown_command(VIGEN_CMD_global, argv[at]);
    args.command = command;
    *command_out = command;
    if ((rc = vigen_cli_parse(&args, command, argc - at - 1, argv + at + 1, NULL)) >= 0) return rc;
    if (args.value[VIGEN_OPT_global_help]) {
        vigen_cli_print_command_help(stdout, command);
        return 0;
    }
    if (args.value[VIGEN_OPT_global_version]) return vigen_cmd_version(&args);
    if ((rc = apply_sandbox_options(&args)) >= 0) return rc;
    if ((rc = apply_caps(&args, command)) >= 0) return rc;
    const char *operand = vigen_cli_commands[command].operand;
    if (operand[0] != '\0' && operand[0] != '[' && args.operand == NULL)
        return vigen_cli_usage_error(command, "%s", vigen_cli_commands[command].ask);
    for (int k = 0; k < VIGEN_OPT_COUNT; k++)
        if (vigen_cli_options[k].command == command && vigen_cli_options[k].required && args.value[k] == NULL)
            return vigen_cli_usage_error(command, "%s is required: %s %s (%s)", vigen_cli_option_name(k),
                                         vigen_cli_option_name(k), vigen_cli_options[k].metavar,
                                         vigen_cli_options[k].description);
    if ((rc = resolve_operands(&args, command)) >= 0) return rc;
    return handlers[command](&args);
}

int main(int argc, char **argv)
{
    vigen_guard_install();
    vigen_method_set_name_resolver(vigen_library_resolve);
    int command = VIGEN_CMD_global;
    int rc = run(&command, argc - 1, argv + 1);
    rc = finish_output(command, rc);
    flint_cleanup();
    return rc;
}
