/* nul.h — the one refusal of strings holding NUL bytes. */
#ifndef VIGEN_SUPPORT_NUL_H
#define VIGEN_SUPPORT_NUL_H

#include <stddef.h>
#include "vigen/error.h"

/* VIGEN_OK when the len bytes at text hold no NUL byte; otherwise records
 * VIGEN_E_SPEC with "PATH: ENTRY contains a NUL byte (\0 at byte K); remove
 * it" (K counted from 1) and returns it.  Strings read from files go through
 * this before they are used as C strings, which would end at the NUL. */
int vigen_refuse_nul(const char *text, size_t len, const char *path, const char *entry, vigen_error *err);

#endif
