/* error.c — error records, status names and exit statuses (status.def),
 * and the warning hook (whose default prints warnings escaped, printable.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/error.h"
#include "support/printable.h"
#include "support/strbuf.h"

void vigen_error_init(vigen_error *err) { err->code = VIGEN_OK; err->message = NULL; }

void vigen_error_clear(vigen_error *err)
{
    free(err->message);
    err->message = NULL;
    err->code = VIGEN_OK;
}

int vigen_error_setv(vigen_error *err, int code, const char *fmt, va_list ap)
{
    if (err == NULL) return code;
    char *msg = vigen_vstrdup_printf(fmt, ap);
    free(err->message);
    err->message = msg;
    err->code = code;
    return code;
}

int vigen_error_set(vigen_error *err, int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vigen_error_setv(err, code, fmt, ap);
    va_end(ap);
    return code;
}

int vigen_error_prefix(vigen_error *err, const char *fmt, ...)
{
    if (err == NULL) return VIGEN_OK;
    va_list ap;
    va_start(ap, fmt);
    char *pre = vigen_vstrdup_printf(fmt, ap);
    va_end(ap);
    const char *old = err->message ? err->message : "";
    char *msg = vigen_xrealloc(NULL, strlen(pre) + strlen(old) + 1);
    strcpy(msg, pre);
    strcat(msg, old);
    free(pre);
    free(err->message);
    err->message = msg;
    return err->code;
}

static const struct { const char *words; int exit_status; } status_table[] = {
#define X(name, exit_status, words) { words, exit_status },
#include "vigen/status.def"
#undef X
};

const char *vigen_status_name(int code)
{
    if (code < 0 || code >= VIGEN_STATUS_COUNT) return "unknown status";
    return status_table[code].words;
}

int vigen_status_exit_code(int code)
{
    if (code < 0 || code >= VIGEN_STATUS_COUNT) return 3;
    return status_table[code].exit_status;
}

static vigen_warning_fn warning_fn = NULL;
static void *warning_ctx = NULL;

void vigen_warning_set_handler(vigen_warning_fn fn, void *ctx)
{
    warning_fn = fn;
    warning_ctx = ctx;
}

void vigen_warn(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *msg = vigen_vstrdup_printf(fmt, ap);
    va_end(ap);
    if (warning_fn) warning_fn(msg, warning_ctx);
    else {
        /* warnings echo names and keys from files: no control character or
         * stray byte reaches the terminal */
        char *shown = vigen_printable(msg);
        fprintf(stderr, "vigen: warning: %s\n", shown);
        free(shown);
    }
    free(msg);
}

