/* python_internal.h — what the files of libvigen_python share: one call's
 * set-up and tear-down (the lock, the warnings, the result), the messages of
 * the command line, operands resolved as the command line resolves them.
 * Private to python/native (prefix pyn_). */
#ifndef VIGEN_PYTHON_INTERNAL_H
#define VIGEN_PYTHON_INTERNAL_H

#include <stdio.h>
#include "vigen/error.h"
#include "vigen_python.h"

/* Starts a call for `vigen command`: takes the lock, clears r, routes the
 * library's warnings into r.  Every entry point starts with it and ends
 * with pyn_end. */
void pyn_begin(vigen_python_result *r, const char *command);
/* Ends the call: r->status = status, r->exit_status from it (a success
 * keeps the exit status already set), the warnings into r; releases the
 * lock.  Returns status. */
int pyn_end(vigen_python_result *r, int status);

/* A failure of the library: r->message = "vigen COMMAND: " and the message
 * of err, escaped as the command line prints it; clears err.  Returns its
 * code. */
int pyn_fail(vigen_python_result *r, vigen_error *err);
/* A usage error with a printf-style message ("vigen COMMAND: ..."):
 * VIGEN_E_USAGE. */
int pyn_usage(vigen_python_result *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* *out = the whole number of an option's text (NULL: *out is left as it
 * is) in [lo, hi], checked as the command line checks it: VIGEN_OK, or a
 * usage error naming the option. */
int pyn_whole(vigen_python_result *r, long long *out, const char *option, const char *text, long long lo,
              long long hi);

/* *path = operand resolved as the command line resolves its FILE and SPEC
 * operands (a path, or a name of the method library); VIGEN_OK, or the
 * failure recorded in r. */
int pyn_resolve(vigen_python_result *r, char **path, const char *operand);

/* Text written to a FILE * (the library's printers) into a heap string:
 * pyn_capture_open gives the stream, pyn_capture_close the text (NULL when
 * memory ran out). */
typedef struct {
    FILE *f;
    char *data;
    size_t len;
} pyn_capture;
int pyn_capture_open(pyn_capture *c, vigen_python_result *r);
char *pyn_capture_close(pyn_capture *c);

#endif
