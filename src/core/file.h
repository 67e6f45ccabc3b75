/* file.h — input files read whole; output files written atomically
 * (vigen_write_file_atomic, public in vigen/file.h). */
#ifndef VIGEN_FILE_H
#define VIGEN_FILE_H

#include <stddef.h>
#include "vigen/error.h"
#include "vigen/file.h"

/* Reads the whole file at path into *data (malloc'd, NUL-terminated; *len
 * bytes without the NUL).  VIGEN_E_IO when it cannot be opened or read,
 * VIGEN_E_LIMIT when it is longer than max_len bytes (reading stops there),
 * VIGEN_E_MEMORY; the messages name the file. */
int vigen_read_file(char **data, size_t *len, const char *path, size_t max_len, vigen_error *err);


#endif
