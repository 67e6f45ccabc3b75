/* vigen/library.h — the method library: tableau files known by name.
 *
 * A name (gauss_3, or gauss_3.lua) resolves to the first file found in
 *   1. the current directory,
 *   2. each directory of the environment variable VIGEN_PATH (separated by
 *      ':'), in order,
 *   3. the library installed with vigen: its published tableaux, then its
 *      generated ones (share/vigen/tableaux/{published,generated}; from a
 *      build tree, the source tree's tableaux/).
 * "published/NAME" and "generated/NAME" name a file of the installed
 * library directly (leok_zhang_ex4 exists in both: the published one is
 * found first).  Every command that takes a FILE, and vigen_add_stepper,
 * accept a name. */
#ifndef VIGEN_LIBRARY_H
#define VIGEN_LIBRARY_H

#include <stdio.h>
#include "vigen/error.h"

/* *path = a heap string: operand itself when it is a file, else the file the
 * name resolves to.  VIGEN_E_USAGE with a did-you-mean hint when nothing
 * matches; *path is NULL then. */
int vigen_library_resolve(char **path, const char *operand, vigen_error *err);

/* The directories of steps 2 and 3, NULL-terminated, heap strings (free each
 * and the array with vigen_library_dirs_free). */
char **vigen_library_dirs(void);
void vigen_library_dirs_free(char **dirs);

/* The stems of the .lua files of the folders dirs (NULL-terminated), in
 * folder order, unsorted within a folder: NULL-terminated heap strings (free
 * each and the array). */
char **vigen_library_names(char *const *dirs);

/* `vigen list`: every method of the directories of steps 2 and 3 (the first
 * of each name; later ones with the same name are listed as shadowed), with
 * its certified orders (general, separable and Nystrom H), stages, force
 * evaluations per step, symplecticity and source, as text or JSON.  Returns
 * VIGEN_OK, or an error when no directory can be read. */
int vigen_library_list(FILE *out, int json, vigen_error *err);

#endif
