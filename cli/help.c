/* help.c — usage lines, `vigen help`, `vigen help COMMAND` and
 * `vigen version`, all rendered from the tables of commands.def and, for the
 * exit statuses, of status.def. */
#include <stdlib.h>
#include <string.h>
#include "vigen/vigen.h"
#include "cli.h"

/* What each exit status means; the status codes that give it are listed
 * from status.def after the words. */
static const char *const exit_meaning[] = {
    "success",
    "a verdict: check found something FAILED or NOT DECIDED, or entries differ\n"
    "     from --against",
    "bad input or usage",
    "a resource or system failure",
};
enum { EXIT_STATUS_COUNT = sizeof exit_meaning / sizeof exit_meaning[0] };

static int applies(const vigen_cli_option *o, int command) { return o->command == command; }

/* Help fits a terminal of this many columns. */
#define HELP_COLUMNS 80

/* Columns of n bytes of UTF-8 text (every character one column). */
static int columns(const char *s, size_t n)
{
    int c = 0;
    for (size_t i = 0; i < n; i++) c += ((unsigned char)s[i] & 0xC0) != 0x80;
    return c;
}

/* text written from column col, broken at spaces before HELP_COLUMNS and at
 * each '\n', every further line starting at column indent. */
static void put_wrapped(FILE *out, const char *text, int col, int indent)
{
    const char *p = text;
    while (*p) {
        const char *gap = p;
        while (*p == ' ') p++;
        if (*p == '\n') {
            fprintf(out, "\n%*s", indent, "");
            col = indent;
            p++;
            continue;
        }
        if (*p == '\0') break;
        const char *word = p;
        while (*p && *p != ' ' && *p != '\n') p++;
        int g = (int)(word - gap), w = columns(word, (size_t)(p - word));
        if (col > indent && col + g + w > HELP_COLUMNS) {
            fprintf(out, "\n%*s", indent, "");
            col = indent;
            g = 0;
        }
        fprintf(out, "%*s%.*s", g, "", (int)(p - word), word);
        col += g + w;
    }
}

/* "-q, --quiet", "--digits N", "-o FILE": the left column of an option. */
static void option_label(char *buf, size_t size, const vigen_cli_option *o)
{
    snprintf(buf, size, "%s%s%s%s%s", o->short_name && o->long_name ? o->short_name : "",
             o->short_name && o->long_name ? ", " : "", o->long_name ? o->long_name : o->short_name,
             o->metavar ? " " : "", o->metavar ? o->metavar : "");
}

static void print_options(FILE *out, int command)
{
    char label[96];
    size_t width = 0;
    for (int k = 0; k < VIGEN_OPT_COUNT; k++) {
        if (!applies(&vigen_cli_options[k], command)) continue;
        option_label(label, sizeof label, &vigen_cli_options[k]);
        if (strlen(label) > width) width = strlen(label);
    }
    for (int k = 0; k < VIGEN_OPT_COUNT; k++) {
        const vigen_cli_option *o = &vigen_cli_options[k];
        if (!applies(o, command)) continue;
        option_label(label, sizeof label, o);
        fprintf(out, "  %-*s  ", (int)width, label);
        put_wrapped(out, o->description, 4 + (int)width, 4 + (int)width);
        fputc('\n', out);
    }
}

void vigen_cli_print_usage(FILE *out, int command)
{
    const vigen_cli_command *c = &vigen_cli_commands[command];
    int indent = fprintf(out, "usage: vigen %s", c->name) + 1, col = indent - 1;
    if (c->operand[0]) col += fprintf(out, " %s", c->operand);
    for (int k = 0; k < VIGEN_OPT_COUNT; k++) {
        const vigen_cli_option *o = &vigen_cli_options[k];
        if (!applies(o, command)) continue;
        char item[96];
        int n = snprintf(item, sizeof item, "%s%s%s%s%s", o->required ? "" : "[", vigen_cli_option_name(k),
                         o->metavar ? " " : "", o->metavar ? o->metavar : "", o->required ? "" : "]");
        /* further lines of options start under the first word after the command */
        if (col + 1 + n > HELP_COLUMNS) col = fprintf(out, "\n%*s%s", indent, "", item) - 1;
        else col += fprintf(out, " %s", item);
    }
    fputc('\n', out);
}

static void print_exit_statuses(FILE *out)
{
    fputs("exit status (every command):\n", out);
    for (int e = 0; e < EXIT_STATUS_COUNT; e++) {
        int col = fprintf(out, "  %d  %s", e, exit_meaning[e]);
        if (e >= 2) {
            /* the status codes of this exit status, wrapped under the words */
            const char *sep = ":";
            for (int code = 1; code < VIGEN_STATUS_COUNT; code++) {
                if (vigen_status_exit_code(code) != e) continue;
                const char *words = vigen_status_name(code);
                /* further lines start under the words, at column 5 */
                if (col + 3 + (int)strlen(words) > HELP_COLUMNS) col = fprintf(out, "%s\n     %s", sep, words) - 2;
                else col += fprintf(out, "%s %s", sep, words);
                sep = ",";
            }
        }
        fputc('\n', out);
    }
}

/* "  vigen help NAME  summary", names padded to the longest topic, the
 * summary's further lines indented under its first. */
static void print_topic(FILE *out, const char *name, const char *summary)
{
    int width = 0;
#define TOPIC(topic, text) if ((int)strlen(#topic) > width) width = (int)strlen(#topic);
#include "commands.def"
    int col = fprintf(out, "  vigen help %-*s  ", width, name);
    put_wrapped(out, summary, col, col);
    fputc('\n', out);
}

/* A topic's text comes from the library's tables. */
static int print_owned(char *text)
{
    fputs(text, stdout);
    free(text);
    return 0;
}

static int vigen_topic_spec(void) { return print_owned(vigen_method_vocabulary_text()); }
static int vigen_topic_checks(void) { return print_owned(vigen_check_list_text()); }

void vigen_cli_print_help(FILE *out)
{
    fputs("usage: vigen COMMAND [OPTIONS]\n"
          "\n"
          "Certified symplectic partitioned Runge-Kutta methods.\n"
          "\n"
          "commands:\n", out);
    size_t width = 0;
    for (int c = 0; c < VIGEN_CMD_COUNT; c++) {
        size_t n = strlen(vigen_cli_commands[c].name) + 1 + strlen(vigen_cli_commands[c].operand);
        if (n > width) width = n;
    }
    for (int c = 0; c < VIGEN_CMD_COUNT; c++) {
        char label[64];
        snprintf(label, sizeof label, "%s %s", vigen_cli_commands[c].name, vigen_cli_commands[c].operand);
        fprintf(out, "  %-*s  %s\n", (int)width, label, vigen_cli_commands[c].summary);
    }
    fputs("\noptions for every command, anywhere on the line (spec and tableau files run in\n"
          "a Lua sandbox):\n", out);
    print_options(out, VIGEN_CMD_global);
    fputc('\n', out);
    print_exit_statuses(out);
    fputs("\nhelp topics:\n", out);
#define TOPIC(name, summary) print_topic(out, #name, summary);
#include "commands.def"
    fputs("\nRun 'vigen help COMMAND' (or 'vigen COMMAND --help') for the options of a\n"
          "command.\n", out);
}

void vigen_cli_print_command_help(FILE *out, int command)
{
    vigen_cli_print_usage(out, command);
    fprintf(out, "\n%s", vigen_cli_commands[command].help);
    int any = 0;
    for (int k = 0; k < VIGEN_OPT_COUNT; k++) any |= applies(&vigen_cli_options[k], command);
    if (any) {
        fputs("\noptions:\n", out);
        print_options(out, command);
    }
    int col = fprintf(out, "\noptions for every command:") - 1;
    const char *sep = " ";
    for (int k = 0; k < VIGEN_OPT_COUNT; k++) {
        const vigen_cli_option *o = &vigen_cli_options[k];
        if (!applies(o, VIGEN_CMD_global)) continue;
        char item[96];
        int n = snprintf(item, sizeof item, "%s%s%s", vigen_cli_option_name(k), o->metavar ? " " : "",
                         o->metavar ? o->metavar : "");
        /* an option and its value are not parted by a line break */
        if (col + (int)strlen(sep) + n + 1 > HELP_COLUMNS) col = fprintf(out, ",\n  %s", item) - 2;
        else col += fprintf(out, "%s%s", sep, item);
        sep = ", ";
    }
    fputs("\nexit status: 0 success, 1 a verdict of check, 2 bad input or usage, 3 a resource\n"
          "or system failure; the exit statuses are explained in 'vigen help'.\n", out);
}

int vigen_cmd_help(const vigen_cli_args *args)
{
    if (args->operand == NULL) {
        vigen_cli_print_help(stdout);
        return 0;
    }
#define TOPIC(name, summary) if (strcmp(args->operand, #name) == 0) return vigen_topic_##name();
#include "commands.def"
    int c = vigen_cli_command_index(args->operand);
    if (c < 0) return vigen_cli_unknown_command(VIGEN_CMD_help, args->operand);
    vigen_cli_print_command_help(stdout, c);
    return 0;
}

int vigen_cmd_version(const vigen_cli_args *args)
{
    (void)args;
    printf("vigen %s\n", vigen_version());
    return 0;
}
