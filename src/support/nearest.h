/* nearest.h — "did you mean" hints. */
#ifndef VIGEN_SUPPORT_NEAREST_H
#define VIGEN_SUPPORT_NEAREST_H

#include <stddef.h>

/* The name in the NULL-terminated list names closest to key (case first,
 * then Levenshtein distance), when at most max_edits away and closer than
 * the key's length; NULL otherwise. */
const char *vigen_nearest_name(const char *key, const char *const *names, size_t max_edits);

#endif
