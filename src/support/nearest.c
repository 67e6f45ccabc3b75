/* nearest.c — "did you mean" hints: the known name nearest to a misspelt
 * one (case first, then Levenshtein distance). */
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "vigen/error.h"
#include "support/nearest.h"

static size_t edit_distance(const char *a, const char *b)
{
    size_t na = strlen(a), nb = strlen(b);
    size_t *row = calloc(nb + 1, sizeof *row);
    if (row == NULL) return (size_t)-1;
    for (size_t j = 0; j <= nb; j++) row[j] = j;
    for (size_t i = 1; i <= na; i++) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= nb; j++) {
            size_t up = row[j];
            size_t best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best) best = up + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    size_t d = row[nb];
    free(row);
    return d;
}

const char *vigen_nearest_name(const char *key, const char *const *names, size_t max_edits)
{
    const char *near = NULL;
    size_t nearest = max_edits + 1;
    /* a different case is the likeliest typo ("AT" for "At", not "A") */
    for (int i = 0; names[i]; i++)
        if (strcasecmp(key, names[i]) == 0) return names[i];
    for (int i = 0; names[i]; i++) {
        size_t d = edit_distance(key, names[i]);
        if (d < nearest && d < strlen(key)) {
            nearest = d;
            near = names[i];
        }
    }
    return near;
}
