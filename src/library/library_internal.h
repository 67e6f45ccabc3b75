/* library_internal.h — shared by the files of src/library/.  Not installed. */
#ifndef VIGEN_LIBRARY_INTERNAL_H
#define VIGEN_LIBRARY_INTERNAL_H

#include "vigen/library.h"

/* the two parts of the installed library, in search order */
static const char *const library_parts[2] = {"published", "generated"};

#endif
