/* vigen_python.c — one call of the Python package's C interface, set up and
 * torn down: the lock, the result record, the warnings collected instead of
 * printed, the command line's messages, operands resolved as the command
 * line resolves them, captured output, and the caps (vigen_python.h). */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "python_internal.h"
#include "vigen/library.h"
#include "vigen/limits.h"
#include "vigen/method.h"
#include "vigen/vigen.h"
#include "support/printable.h"
#include "support/strbuf.h"

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
/* the command of the call in progress (under the lock) */
static const char *current_command;
static vigen_strbuf warnings;

void vigen_python_free(void *p)
{
    free(p);
}

void vigen_python_result_clear(vigen_python_result *r)
{
    if (r == NULL) return;
    free(r->text);
    free(r->extra);
    free(r->message);
    free(r->warnings);
    memset(r, 0, sizeof *r);
}

const char *vigen_python_version(void)
{
    return vigen_version();
}

const char *vigen_python_status_name(int status)
{
    return vigen_status_name(status);
}

/* the default hook prints "vigen: warning: ..." on stderr; here the same
 * line is kept for the caller */
static void collect_warning(const char *message, void *ctx)
{
    (void)ctx;
    char *shown = vigen_printable(message);
    vigen_strbuf_printf(&warnings, "vigen: warning: %s\n", shown);
    free(shown);
}

void pyn_begin(vigen_python_result *r, const char *command)
{
    pthread_mutex_lock(&lock);
    memset(r, 0, sizeof *r);
    current_command = command;
    vigen_strbuf_clear(&warnings);
    vigen_warning_set_handler(collect_warning, NULL);
    /* a composition's base named by a bare name is looked up in the library,
     * as the command line does */
    vigen_method_set_name_resolver(vigen_library_resolve);
}

int pyn_end(vigen_python_result *r, int status)
{
    r->status = status;
    if (status != VIGEN_OK) r->exit_status = vigen_status_exit_code(status);
    if (warnings.len > 0) r->warnings = vigen_strdup(warnings.data);
    vigen_strbuf_clear(&warnings);
    vigen_warning_set_handler(NULL, NULL);
    current_command = NULL;
    pthread_mutex_unlock(&lock);
    return status;
}

/* "vigen COMMAND: text", or "vigen: text" for the global options */
static char *prefixed(const char *text)
{
    const char *c = current_command ? current_command : "";
    return vigen_strdup_printf("vigen%s%s: %s", *c ? " " : "", c, text);
}

int pyn_fail(vigen_python_result *r, vigen_error *err)
{
    int code = err->code != VIGEN_OK ? err->code : VIGEN_E_MEMORY;
    free(r->message);
    char *shown = vigen_printable(err->message ? err->message : vigen_status_name(code));
    r->message = prefixed(shown);
    free(shown);
    vigen_error_clear(err);
    return code;
}

int pyn_usage(vigen_python_result *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *text = vigen_vstrdup_printf(fmt, ap);
    va_end(ap);
    free(r->message);
    /* usage messages name options and operands, which the caller gave: the
     * command line prints them as they are */
    r->message = prefixed(text);
    free(text);
    return VIGEN_E_USAGE;
}

int pyn_whole(vigen_python_result *r, long long *out, const char *option, const char *text, long long lo,
              long long hi)
{
    if (text == NULL) return VIGEN_OK;
    char *end = NULL;
    long long v = strtoll(text, &end, 10);
    if (end == text || *end != '\0' || v < lo || v > hi)
        return pyn_usage(r, "%s takes a whole number from %lld to %lld, not '%s'", option, lo, hi, text);
    *out = v;
    return VIGEN_OK;
}

int pyn_resolve(vigen_python_result *r, char **path, const char *operand)
{
    *path = NULL;
    struct stat st;
    /* a path (or anything that exists) goes to the loader, whose messages
     * say what is wrong with it; a bare word is a name of the library */
    int name = stat(operand, &st) != 0 &&
               (strchr(operand, '/') == NULL || strncmp(operand, "published/", 10) == 0 ||
                strncmp(operand, "generated/", 10) == 0);
    if (!name) {
        *path = vigen_strdup(operand);
        return VIGEN_OK;
    }
    vigen_error err;
    vigen_error_init(&err);
    if (vigen_library_resolve(path, operand, &err) != VIGEN_OK) return pyn_fail(r, &err);
    return VIGEN_OK;
}

int pyn_capture_open(pyn_capture *c, vigen_python_result *r)
{
    c->data = NULL;
    c->len = 0;
    c->f = open_memstream(&c->data, &c->len);
    if (c->f == NULL) {
        vigen_error err;
        vigen_error_init(&err);
        vigen_error_set(&err, VIGEN_E_MEMORY, "out of memory");
        return pyn_fail(r, &err);
    }
    return VIGEN_OK;
}

char *pyn_capture_close(pyn_capture *c)
{
    int bad = fclose(c->f) != 0;
    c->f = NULL;
    if (bad) {
        free(c->data);
        c->data = NULL;
    }
    return c->data;
}

int vigen_python_set_caps(vigen_python_result *r, const char *max_memory_mib, const char *max_instructions,
                          const char *max_prec)
{
    pyn_begin(r, "");
    long long memory = 0, instructions = 0, prec = 0;
    int rc = pyn_whole(r, &memory, "--max-memory", max_memory_mib, 1, 1048576);
    if (rc == VIGEN_OK) rc = pyn_whole(r, &instructions, "--max-instructions", max_instructions, 1, 1000000000000LL);
    if (rc == VIGEN_OK) rc = pyn_whole(r, &prec, "--max-prec", max_prec, 64, 1LL << 40);
    if (rc == VIGEN_OK) {
        /* fields left at 0 keep their value */
        vigen_sandbox_limits limits = { (size_t)memory << 20, (long)instructions };
        vigen_sandbox_limits_set_default(&limits);
        if (prec != 0) vigen_prec_limit_set((long)prec);
    }
    return pyn_end(r, rc);
}

int vigen_python_resolve(vigen_python_result *r, const char *command, const char *operand)
{
    pyn_begin(r, command);
    char *path = NULL;
    int rc = pyn_resolve(r, &path, operand);
    r->text = path;
    return pyn_end(r, rc);
}
