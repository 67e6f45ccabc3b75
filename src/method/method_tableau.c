/* method_tableau.c — the "tableau" row of methods.def: a tableau file, read
 * once; every tableau asked for is a copy of its texts, evaluated at a
 * precision adequate for the digits asked for (or not at all for digits 0).
 * Also vigen_tableau_load of vigen/tableau.h, a tableau file read directly. */
#include <stdlib.h>
#include <string.h>
#include "method/galerkin.h"
#include "method/methods.h"
#include "method/method_tableau.h"
#include "method/vocabulary.h"
#include "support/strbuf.h"

typedef struct {
    char *path;
    vigen_tableau read;     /* texts and metadata as the file states them */
} tableau_state;

int vigen_method_tableau_read(void **state, vigen_sandbox *sb, const char *path, vigen_method_loader load,
                                vigen_error *err)
{
    *state = NULL;
    tableau_state *st = calloc(1, sizeof *st);
    if (st == NULL) {
        vigen_sandbox_free(sb);
        return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    }
    int rc = vigen_tableau_from_table(&st->read, sb, path, err);
    vigen_sandbox_free(sb);
    if (rc != VIGEN_OK) {
        free(st);
        return rc;
    }
    st->path = vigen_strdup(path);
    *state = st;
    return VIGEN_OK;
}

int vigen_method_tableau_adopt(void **state, vigen_tableau *t, const char *path, vigen_error *err)
{
    *state = NULL;
    tableau_state *st = calloc(1, sizeof *st);
    if (st == NULL) {
        vigen_tableau_clear(t);
        return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    }
    st->read = *t;
    memset(t, 0, sizeof *t);
    st->path = vigen_strdup(path);
    *state = st;
    return VIGEN_OK;
}

slong vigen_method_tableau_prec(slong digits, slong s) { return vigen_galerkin_initial_prec(digits, s); }

int vigen_method_tableau_tableau(vigen_tableau *t, void *state, slong digits, vigen_error *err)
{
    tableau_state *st = state;
    vigen_tableau_copy(t, &st->read);
    if (digits <= 0) return VIGEN_OK;   /* as stated: texts only */
    int rc = vigen_tableau_evaluate(t, vigen_method_tableau_prec(digits, t->s), err);
    if (rc != VIGEN_OK) {
        vigen_error_prefix(err, "%s: ", st->path);
        vigen_tableau_clear(t);
    }
    return rc;
}

void vigen_method_tableau_release(void *state)
{
    tableau_state *st = state;
    if (st == NULL) return;
    vigen_tableau_clear(&st->read);
    free(st->path);
    free(st);
}

int vigen_tableau_load(vigen_tableau *t, const char *path, const vigen_sandbox_limits *limits, vigen_error *err)
{
    vigen_sandbox *sb = NULL;
    int rc = vigen_vocabulary_run_file(&sb, path, limits, err);
    if (rc == VIGEN_OK) rc = vigen_tableau_from_table(t, sb, path, err);
    vigen_sandbox_free(sb);
    return rc;
}
