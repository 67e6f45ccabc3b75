/* file.h — input files read whole, output files written atomically.
 * vigen_write_file_atomic is part of the public API and also declared in
 * vigen/tableau.h (the command line writes tableau files and emitted sources
 * with it). */
#ifndef VIGEN_FILE_H
#define VIGEN_FILE_H

#include <stddef.h>
#include "vigen/error.h"

/* Reads the whole file at path into *data (malloc'd, NUL-terminated; *len
 * bytes without the NUL).  VIGEN_E_IO when it cannot be opened or read,
 * VIGEN_E_LIMIT when it is longer than max_len bytes (reading stops there),
 * VIGEN_E_MEMORY; the messages name the file. */
int vigen_read_file(char **data, size_t *len, const char *path, size_t max_len, vigen_error *err);

/* Writes text to path atomically (temporary file in the same directory, then
 * rename); "-" means standard output.  Failures are VIGEN_E_WRITE, with a
 * message naming the file. */
int vigen_write_file_atomic(const char *path, const char *text, vigen_error *err);

#endif
