/* nul.c — strings read from files refused when they hold a NUL byte
 * (support/nul.h). */
#include <string.h>
#include "support/nul.h"

int vigen_refuse_nul(const char *text, size_t len, const char *path, const char *entry, vigen_error *err)
{
    const char *nul = memchr(text, '\0', len);
    if (nul == NULL) return VIGEN_OK;
    return vigen_error_set(err, VIGEN_E_SPEC, "%s: %s contains a NUL byte (\\0 at byte %zu); remove it", path, entry,
                           (size_t)(nul - text) + 1);
}
