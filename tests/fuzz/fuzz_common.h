/* fuzz_common.h — what every libFuzzer harness of tests/fuzz/ shares: the
 * input as a NUL-terminated string, silenced warnings, and a check that
 * aborts (a finding) when a property of the library fails. */
#ifndef VIGEN_FUZZ_COMMON_H
#define VIGEN_FUZZ_COMMON_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/error.h"

/* The input as a C string (bytes after a NUL are not seen by the string
 * APIs fuzzed here); free() it. */
static inline char *fuzz_cstring(const uint8_t *data, size_t size)
{
    char *s = malloc(size + 1);
    if (s == NULL) abort();
    if (size) memcpy(s, data, size);
    s[size] = '\0';
    return s;
}

static void fuzz_ignore_warning(const char *message, void *ctx)
{
    (void)message;
    (void)ctx;
}

/* Once per process: warnings (e.g. unknown spec fields) are not printed. */
static inline void fuzz_quiet(void)
{
    static int done;
    if (!done) vigen_warning_set_handler(fuzz_ignore_warning, NULL);
    done = 1;
}

/* A property of the library that must hold for every input. */
#define FUZZ_ASSERT(cond)                                                                                    \
    do {                                                                                                     \
        if (!(cond)) {                                                                                       \
            fprintf(stderr, "%s:%d: property failed: %s\n", __FILE__, __LINE__, #cond);                      \
            abort();                                                                                         \
        }                                                                                                    \
    } while (0)

#endif
