/* option_parser.c — the tables of commands.def as arrays, and the one option
 * parser every command uses: --opt VALUE, --opt=VALUE, -o VALUE, flags, the
 * global options anywhere on the line, did-you-mean for mistyped options. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "cli.h"
#include "support/printable.h"
#include "support/strbuf.h"
#include "support/nearest.h"

const vigen_cli_command vigen_cli_commands[VIGEN_CMD_COUNT] = {
#define COMMAND(name, operand, ask, summary, help) { #name, operand, ask, summary, help },
#include "commands.def"
};

const vigen_cli_option vigen_cli_options[VIGEN_OPT_COUNT] = {
#define OPTION(command, id, long_name, short_name, metavar, required, description) \
    { VIGEN_CMD_##command, long_name, short_name, metavar, required, description },
#include "commands.def"
};

const char *vigen_cli_option_name(int option)
{
    const vigen_cli_option *o = &vigen_cli_options[option];
    return o->long_name ? o->long_name : o->short_name;
}

static void print_prefix(int command)
{
    if (command == VIGEN_CMD_global) fputs("vigen: ", stderr);
    else fprintf(stderr, "vigen %s: ", vigen_cli_commands[command].name);
}

int vigen_cli_usage_error(int command, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    print_prefix(command);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    /* the help of help would not help with its operand */
    if (command == VIGEN_CMD_global || command == VIGEN_CMD_help) fputs("\nsee 'vigen help'\n", stderr);
    else fprintf(stderr, "\nsee 'vigen help %s'\n", vigen_cli_commands[command].name);
    return 2;
}

/* Messages echo names, entries and Lua errors from files: printed escaped, so
 * that no control character or stray byte reaches the terminal. */
int vigen_cli_fail(int command, vigen_error *err)
{
    print_prefix(command);
    char *shown = vigen_printable(err->message ? err->message : vigen_status_name(err->code));
    fprintf(stderr, "%s\n", shown);
    free(shown);
    int status = vigen_status_exit_code(err->code);
    vigen_error_clear(err);
    return status;
}

int vigen_cli_whole(long long *out, const vigen_cli_args *args, int option, long long lo, long long hi)
{
    const char *text = args->value[option];
    char *end = NULL;
    long long v = strtoll(text, &end, 10);
    if (end == text || *end != '\0' || v < lo || v > hi)
        return vigen_cli_usage_error(args->command, "%s takes a whole number from %lld to %lld, not '%s'",
                                     vigen_cli_option_name(option), lo, hi, text);
    *out = v;
    return -1;
}

/* The option of command (or a global one) called name, which is the whole
 * word or, for long names, the part before '='; -1 when there is none. */
static int find_option(int command, const char *word, size_t len)
{
    for (int k = 0; k < VIGEN_OPT_COUNT; k++) {
        const vigen_cli_option *o = &vigen_cli_options[k];
        if (o->command != command && o->command != VIGEN_CMD_global) continue;
        if (o->long_name && strlen(o->long_name) == len && strncmp(o->long_name, word, len) == 0) return k;
        if (o->short_name && strcmp(o->short_name, word) == 0) return k;
    }
    return -1;
}

/* The commands other than command that have an option called key, as
 * "generate and emit" into buf; returns how many there are. */
static int other_owners(char *buf, size_t size, int command, const char *key)
{
    int owners[VIGEN_CMD_COUNT], n = 0;
    for (int c = 0; c < VIGEN_CMD_COUNT; c++) {
        if (c == command) continue;
        for (int k = 0; k < VIGEN_OPT_COUNT; k++) {
            const vigen_cli_option *o = &vigen_cli_options[k];
            if (o->command != c) continue;
            if ((o->long_name && strcmp(o->long_name, key) == 0) || (o->short_name && strcmp(o->short_name, key) == 0)) {
                owners[n++] = c;
                break;
            }
        }
    }
    buf[0] = '\0';
    for (int i = 0, used = 0; i < n && (size_t)used < size; i++)
        used += snprintf(buf + used, size - (size_t)used, "%s%s", i == 0 ? "" : i + 1 < n ? ", " : " and ",
                         vigen_cli_commands[owners[i]].name);
    return n;
}

/* An option of another command is named as such; a mistyped long option
 * gets the nearest name; a one-letter option only a name that differs from
 * it in case (any other one letter is as near as a guess). */
static int owns(int c, const char *key)
{
    for (int k = 0; k < VIGEN_OPT_COUNT; k++) {
        const vigen_cli_option *o = &vigen_cli_options[k];
        if (o->command == c && ((o->long_name && strcmp(o->long_name, key) == 0) ||
                                (o->short_name && strcmp(o->short_name, key) == 0)))
            return 1;
    }
    return 0;
}

/* An option before the command: when the command that follows (next, or -1)
 * has it, that command is the one to name. */
static int unknown_option(int command, const char *word, int next)
{
    char *key = vigen_strdup(word);
    char *eq = strchr(key, '=');
    if (eq) *eq = '\0';
    char owners[256];
    int rc;
    if (command == VIGEN_CMD_global && next >= 0 && owns(next, key)) {
        rc = vigen_cli_usage_error(command, "%s is an option of %s: put it after the command", key,
                                   vigen_cli_commands[next].name);
        free(key);
        return rc;
    }
    if (other_owners(owners, sizeof owners, command, key) > 0) {
        if (command == VIGEN_CMD_global)
            rc = vigen_cli_usage_error(command, "%s is an option of %s: put it after the command", key, owners);
        else
            rc = vigen_cli_usage_error(command, "%s is an option of %s, not of %s", key, owners,
                                       vigen_cli_commands[command].name);
        free(key);
        return rc;
    }
    const char *names[2 * VIGEN_OPT_COUNT + 1];
    size_t n = 0;
    for (int k = 0; k < VIGEN_OPT_COUNT; k++) {
        const vigen_cli_option *o = &vigen_cli_options[k];
        if (o->command != command && o->command != VIGEN_CMD_global) continue;
        if (o->long_name) names[n++] = o->long_name;
        if (o->short_name) names[n++] = o->short_name;
    }
    names[n] = NULL;
    const char *near = NULL;
    if (key[0] == '-' && key[1] != '-' && key[1] != '\0' && key[2] == '\0') {
        for (size_t i = 0; i < n && near == NULL; i++)
            if (strcasecmp(names[i], key) == 0) near = names[i];
    } else near = vigen_nearest_name(key, names, 2);
    free(key);
    if (near) return vigen_cli_usage_error(command, "unknown option '%s'; did you mean '%s'?", word, near);
    return vigen_cli_usage_error(command, "unknown option '%s'", word);
}

static int is_option_word(const char *word) { return word[0] == '-' && word[1] != '\0'; }

/* "METHOD..." (an operand kind) and "K=V..." (a metavar) may be repeated. */
static int repeats(const char *kind)
{
    size_t n = strlen(kind);
    return n > 3 && strstr(kind, "...") != NULL;
}

/* A repeatable operand or option collects its words, one per line, in a
 * string that lives as long as the process (the parsed arguments hold
 * pointers into argv otherwise), kept here; a word with a newline cannot be
 * one of them. */
static char *collected[VIGEN_OPT_COUNT + 1]; /* per option, and the operand last */

static int collect(const char **slot, int index, const char *word, int command, const char *what)
{
    if (strchr(word, '\n'))
        return vigen_cli_usage_error(command, "%s cannot contain a newline", what);
    char *joined = *slot ? vigen_strdup_printf("%s\n%s", *slot, word) : vigen_strdup(word);
    free(collected[index]);
    collected[index] = joined;
    *slot = joined;
    return -1;
}

int vigen_cli_parse(vigen_cli_args *args, int command, int argc, char **argv, int *stop)
{
    const char *operand_kind = command == VIGEN_CMD_global ? "" : vigen_cli_commands[command].operand;
    int options_end = 0;
    for (int i = 0; i < argc; i++) {
        const char *word = argv[i];
        if (options_end || !is_option_word(word)) {
            if (command == VIGEN_CMD_global) { *stop = i; return -1; }
            if (operand_kind[0] == '\0')
                return vigen_cli_usage_error(command, "takes no operand, not '%s'", word);
            if (repeats(operand_kind)) {
                int rc = collect(&args->operand, VIGEN_OPT_COUNT, word, command, operand_kind);
                if (rc >= 0) return rc;
                continue;
            }
            if (args->operand != NULL)
                return vigen_cli_usage_error(command, "one %s at a time, not '%s' and '%s'",
                                             operand_kind[0] == '[' ? "COMMAND" : operand_kind, args->operand, word);
            args->operand = word;
            continue;
        }
        if (strcmp(word, "--") == 0) { options_end = 1; continue; }
        const char *eq = word[1] == '-' ? strchr(word, '=') : NULL;
        int k = find_option(command, word, eq ? (size_t)(eq - word) : strlen(word));
        if (k < 0) {
            int next = -1;
            for (int j = i + 1; command == VIGEN_CMD_global && j < argc && next < 0; j++)
                if (!is_option_word(argv[j])) next = vigen_cli_command_index(argv[j]);
            return unknown_option(command, word, next);
        }
        const vigen_cli_option *o = &vigen_cli_options[k];
        if (o->metavar == NULL) {
            if (eq) return vigen_cli_usage_error(command, "%s takes no value, not '%s'", vigen_cli_option_name(k), eq + 1);
            args->value[k] = "";
        } else if (repeats(o->metavar) && (eq || i + 1 < argc)) {
            int rc = collect(&args->value[k], k, eq ? eq + 1 : argv[++i], command, o->metavar);
            if (rc >= 0) return rc;
        } else if (eq) args->value[k] = eq + 1;
        else if (i + 1 < argc) args->value[k] = argv[++i];
        else return vigen_cli_usage_error(command, "%s needs a value: %s %s", word, word, o->metavar);
    }
    if (stop) *stop = argc;
    return -1;
}

int vigen_cli_command_index(const char *name)
{
    for (int c = 0; c < VIGEN_CMD_COUNT; c++)
        if (strcmp(name, vigen_cli_commands[c].name) == 0) return c;
    return -1;
}

int vigen_cli_unknown_command(int command, const char *name)
{
    /* after `vigen help`, the help topics are candidates too */
    const char *names[VIGEN_CMD_COUNT + 8];
    int n = 0;
    for (int c = 0; c < VIGEN_CMD_COUNT; c++) names[n++] = vigen_cli_commands[c].name;
    if (command == VIGEN_CMD_help) {
#define TOPIC(topic, summary) names[n++] = #topic;
#include "commands.def"
    }
    names[n] = NULL;
    /* a unique prefix ("gen") is most likely an abbreviation */
    const char *near = NULL;
    size_t len = strlen(name);
    for (int i = 0; i < n && len > 0; i++) {
        if (strncmp(names[i], name, len) != 0) continue;
        if (near) {
            near = NULL;
            break;
        }
        near = names[i];
    }
    if (near == NULL) near = vigen_nearest_name(name, names, 2);
    const char *what = command == VIGEN_CMD_help ? "command or help topic" : "command";
    if (near) return vigen_cli_usage_error(command, "unknown %s '%s'; did you mean '%s'?", what, name, near);
    return vigen_cli_usage_error(command, "unknown %s '%s'", what, name);
}
