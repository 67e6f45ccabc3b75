/* file.h — input files read whole; output files written atomically: a
 * reader of the file sees the old contents or the new, never a part. */
#ifndef VIGEN_SUPPORT_FILE_H
#define VIGEN_SUPPORT_FILE_H

#include <stddef.h>
#include "vigen/error.h"

/* Reads the whole file at path into *data (malloc'd, NUL-terminated; *len
 * bytes without the NUL).  VIGEN_E_IO when it cannot be opened or read,
 * VIGEN_E_LIMIT when it is longer than max_len bytes (reading stops there),
 * VIGEN_E_MEMORY; the messages name the file. */
int vigen_read_file(char **data, size_t *len, const char *path, size_t max_len, vigen_error *err);

/* Writes text to path atomically (temporary file in the same directory, then
 * rename); "-" means standard output.  Failures are VIGEN_E_WRITE (exit
 * status 3), with a message naming the file. */
int vigen_write_file_atomic(const char *path, const char *text, vigen_error *err);

/* Writes texts[k] to paths[k] for k < n as a unit: after a failure at any
 * step (a full disk, an I/O error, a failed rename) every file is as it was,
 * after success every file is new, and no temporary file is left (nor when a
 * signal or a cap of support/guard.h ends the process).  Each text is written
 * to a temporary file next to its target and synced; then, with SIGINT,
 * SIGTERM, SIGHUP and SIGALRM held back, the old files are linked aside, the
 * new ones renamed into place and the directories synced, the old files
 * being put back if any step fails (src/support/file.c describes the scheme).
 * Links, devices and "-" as in vigen_write_file_atomic (devices and standard
 * output are written in place, outside the unit).  VIGEN_E_WRITE, with a
 * message naming the file. */
int vigen_write_files_atomic(size_t n, const char *const *paths, const char *const *texts, vigen_error *err);

#endif
