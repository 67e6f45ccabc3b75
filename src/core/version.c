/* version.c — the library's version, fixed at build time. */
#include "vigen/vigen.h"

#ifndef VIGEN_VERSION
#define VIGEN_VERSION "unknown"
#endif

const char *vigen_version(void) { return VIGEN_VERSION; }
