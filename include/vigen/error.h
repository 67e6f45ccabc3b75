/* error.h — integer status codes and the error record every vigen function
 * fills, and the hook warnings go through.
 *
 * A function that can fail returns one of the VIGEN_* codes (VIGEN_OK = 0) and,
 * when it fails, writes a human-readable message into a vigen_error supplied by
 * the caller.  Messages say what is wrong and what to do; callers prepend
 * context ("spec.lua: nodes[2]: ") with vigen_error_prefix.
 */
#ifndef VIGEN_ERROR_H
#define VIGEN_ERROR_H

#include <stdarg.h>
#include <stddef.h>

/* VIGEN_OK, VIGEN_E_USAGE, ...: see status.def for each code and its exit status. */
enum {
#define X(name, exit_status, words) VIGEN_##name,
#include "vigen/status.def"
#undef X
    VIGEN_STATUS_COUNT
};

typedef struct {
    int code;       /* VIGEN_OK when no error has been recorded */
    char *message;  /* heap string or NULL; owned by the record */
} vigen_error;

/* An empty record (VIGEN_OK, no message). */
void vigen_error_init(vigen_error *err);
void vigen_error_clear(vigen_error *err);          /* frees the message, code = VIGEN_OK */
/* Records code and a printf-style message (replacing any earlier one); returns code. */
int vigen_error_set(vigen_error *err, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
int vigen_error_setv(vigen_error *err, int code, const char *fmt, va_list ap);
/* Prepends printf-style context to an existing message; returns err->code. */
int vigen_error_prefix(vigen_error *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
const char *vigen_status_name(int code);           /* "syntax error", ... */
/* The command-line exit status for a status code (status.def): 0, 2 or 3. */
int vigen_status_exit_code(int code);

/* Warnings (sum b != 1, nodes outside [0,1]) go through one hook so that tests
 * can capture them; the default prints "vigen: warning: ..." to stderr. */
typedef void (*vigen_warning_fn)(const char *message, void *ctx);
void vigen_warning_set_handler(vigen_warning_fn fn, void *ctx);
void vigen_warn(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

#endif
