/* cli.h — the vigen command line: the command and option tables of
 * commands.def as C arrays, the parsed arguments, the parser, the help
 * renderer and one handler per command.  Only public headers of libvigen
 * (include/vigen/) are used here. */
#ifndef VIGEN_CLI_H
#define VIGEN_CLI_H

#include <stdio.h>
#include "vigen/error.h"

enum {
#define COMMAND(name, operand, ask, summary, help) VIGEN_CMD_##name,
#include "commands.def"
    VIGEN_CMD_COUNT
};
#define VIGEN_CMD_global (-1)

enum {
#define OPTION(command, id, long_name, short_name, metavar, required, description) VIGEN_OPT_##command##_##id,
#include "commands.def"
    VIGEN_OPT_COUNT
};

/* Digits of the tableau of a spec, and of exact entries shown (--digits). */
#define VIGEN_CLI_DEFAULT_DIGITS 34

typedef struct {
    const char *name, *operand, *ask, *summary, *help;
} vigen_cli_command;

typedef struct {
    int command;  /* VIGEN_CMD_*, or VIGEN_CMD_global */
    const char *long_name, *short_name, *metavar;
    int required;
    const char *description;
} vigen_cli_option;

extern const vigen_cli_command vigen_cli_commands[VIGEN_CMD_COUNT];
extern const vigen_cli_option vigen_cli_options[VIGEN_OPT_COUNT];

/* One command line, parsed: the operand (FILE, SPEC, COMMAND) and the value
 * of each option (NULL when absent, "" for a flag that is present). */
typedef struct {
    int command;
    const char *operand;
    const char *value[VIGEN_OPT_COUNT];
} vigen_cli_args;

/* Parses argv[0..argc) for command (VIGEN_CMD_*, or VIGEN_CMD_global for the
 * words before the command: parsing then stops at the first operand, whose
 * index goes to *stop).  Returns -1 when the arguments are good, otherwise
 * the exit status after printing a one-line message. */
int vigen_cli_parse(vigen_cli_args *args, int command, int argc, char **argv, int *stop);

/* The name of an option as the user sees it: "--digits" or "-o". */
const char *vigen_cli_option_name(int option);

/* "vigen COMMAND: message" and "see 'vigen help COMMAND'" ("see 'vigen
 * help'" for the global words and for help itself) on standard error;
 * returns 2 (a usage error).  command: VIGEN_CMD_* or VIGEN_CMD_global. */
int vigen_cli_usage_error(int command, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* "vigen COMMAND: message" for a failure of the library; returns the exit
 * status of its code (status.def) and clears err. */
int vigen_cli_fail(int command, vigen_error *err);
/* The value of a whole-number option in [lo, hi] into *out; returns -1, or 2
 * after a usage error naming the option. */
int vigen_cli_whole(long long *out, const vigen_cli_args *args, int option, long long lo, long long hi);

/* The command called name (VIGEN_CMD_*), or -1. */
int vigen_cli_command_index(const char *name);
/* "unknown command 'chek'; did you mean 'check'?" as a usage error of
 * command (VIGEN_CMD_global or VIGEN_CMD_help); returns 2. */
int vigen_cli_unknown_command(int command, const char *name);

/* help.c */
void vigen_cli_print_help(FILE *out);                 /* vigen help */
void vigen_cli_print_command_help(FILE *out, int command); /* vigen help COMMAND */
void vigen_cli_print_usage(FILE *out, int command);   /* the usage line */

/* The handlers, one file each; each returns the exit status. */
#define COMMAND(name, operand, ask, summary, help) int vigen_cmd_##name(const vigen_cli_args *args);
#include "commands.def"

#endif
