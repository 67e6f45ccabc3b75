/* file.h — output files written atomically: a reader of the file sees the
 * old contents or the new, never a part. */
#ifndef VIGEN_PUBLIC_FILE_H
#define VIGEN_PUBLIC_FILE_H

#include "vigen/error.h"

/* Writes text to path atomically (temporary file in the same directory, then
 * rename); "-" means standard output.  Failures are VIGEN_E_WRITE (exit
 * status 3), with a message naming the file. */
int vigen_write_file_atomic(const char *path, const char *text, vigen_error *err);

#endif
