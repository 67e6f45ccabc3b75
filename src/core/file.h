/* file.h — output files written atomically.  vigen_write_file_atomic is part
 * of the public API and also declared in vigen/tableau.h (the command line
 * writes tableau files and emitted sources with it). */
#ifndef VIGEN_FILE_H
#define VIGEN_FILE_H

#include "vigen/error.h"

/* Writes text to path atomically (temporary file in the same directory, then
 * rename); "-" means standard output.  Failures are VIGEN_E_WRITE, with a
 * message naming the file. */
int vigen_write_file_atomic(const char *path, const char *text, vigen_error *err);

#endif
