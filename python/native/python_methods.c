/* python_methods.c — the method library and the checker for the Python
 * package: `vigen list --json`, `vigen check --json`, `vigen compare`
 * (vigen_python.h), each through the library functions the command line
 * calls, their printed output captured in memory. */
#include <stdlib.h>
#include <string.h>
#include "python_internal.h"
#include "vigen/check.h"
#include "vigen/compare.h"
#include "vigen/library.h"
#include "vigen/method.h"
#include "vigen/trees.h"
#include "support/strbuf.h"

int vigen_python_list(vigen_python_result *r)
{
    pyn_begin(r, "list");
    pyn_capture out;
    int rc = pyn_capture_open(&out, r);
    if (rc != VIGEN_OK) return pyn_end(r, rc);
    vigen_error err;
    vigen_error_init(&err);
    rc = vigen_library_list(out.f, 1, &err);
    char *text = pyn_capture_close(&out);
    if (rc == VIGEN_OK && text == NULL) rc = vigen_error_set(&err, VIGEN_E_MEMORY, "out of memory");
    if (rc != VIGEN_OK) {
        free(text);
        return pyn_end(r, pyn_fail(r, &err));
    }
    r->text = text;
    return pyn_end(r, VIGEN_OK);
}

int vigen_python_check(vigen_python_result *r, const char *file, const char *against, const char *max_order,
                       const char *prec)
{
    pyn_begin(r, "check");
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.load = vigen_source_load;
    long long order = opt.max_order, bits = 0;
    int rc = pyn_whole(r, &order, "--max-order", max_order, 1, VIGEN_TREE_MAX_ORDER);
    if (rc == VIGEN_OK) rc = pyn_whole(r, &bits, "--prec", prec, 16, 1000000);
    if (rc != VIGEN_OK) return pyn_end(r, rc);
    opt.max_order = (int)order;
    if (bits != 0) {
        opt.prec = (slong)bits;
        if (opt.max_prec < opt.prec) opt.max_prec = opt.prec;
    }
    char *path = NULL;
    if ((rc = pyn_resolve(r, &path, file)) != VIGEN_OK) return pyn_end(r, rc);
    /* --against takes a file as the command line gives it (no name lookup) */
    opt.path = path;
    opt.against = against;
    vigen_error err;
    vigen_error_init(&err);
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    rc = vigen_check_file(&rep, &opt, &err);
    if (rc == VIGEN_OK) {
        pyn_capture out;
        rc = pyn_capture_open(&out, r);
        if (rc == VIGEN_OK) {
            vigen_check_print_json(out.f, &rep);
            r->text = pyn_capture_close(&out);
            if (r->text == NULL) rc = vigen_error_set(&err, VIGEN_E_MEMORY, "out of memory");
        }
    }
    r->exit_status = rep.exit_code;
    vigen_check_report_clear(&rep);
    if (err.code != VIGEN_OK) rc = pyn_fail(r, &err);
    free(path);
    return pyn_end(r, rc);
}

enum { MAX_FILES = 64 };

int vigen_python_compare(vigen_python_result *r, const char *files, const char *format, const char *max_order)
{
    pyn_begin(r, "compare");
    int fmt = VIGEN_COMPARE_TEXT;
    if (format && strcmp(format, "latex") == 0) fmt = VIGEN_COMPARE_LATEX;
    else if (format && strcmp(format, "json") == 0) fmt = VIGEN_COMPARE_JSON;
    else if (format && strcmp(format, "text") != 0)
        return pyn_end(r, pyn_usage(r, "--format %s: choose text, latex or json", format));
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.load = vigen_source_load;
    long long order = opt.max_order;
    int rc = pyn_whole(r, &order, "--max-order", max_order, 1, VIGEN_TREE_MAX_ORDER);
    if (rc != VIGEN_OK) return pyn_end(r, rc);
    opt.max_order = (int)order;
    char *paths[MAX_FILES];
    size_t count = 0;
    for (const char *w = files; w != NULL && *w != '\0' && rc == VIGEN_OK;) {
        const char *nl = strchr(w, '\n');
        char *word = vigen_strdup(w);
        if (nl) word[nl - w] = '\0';
        if (count == MAX_FILES) rc = pyn_usage(r, "at most %d files at a time", MAX_FILES);
        else if ((rc = pyn_resolve(r, &paths[count], word)) == VIGEN_OK) count++;
        free(word);
        w = nl ? nl + 1 : NULL;
    }
    if (rc == VIGEN_OK && count == 0) rc = pyn_usage(r, "which methods? give tableau or spec files, e.g. "
                                                       "tableaux/published/yoshida_4.lua tableaux/published/suzuki_4.lua");
    if (rc == VIGEN_OK) {
        pyn_capture out;
        if ((rc = pyn_capture_open(&out, r)) == VIGEN_OK) {
            vigen_error err;
            vigen_error_init(&err);
            rc = vigen_compare_run((const char *const *)paths, count, &opt, fmt, out.f, &err);
            char *text = pyn_capture_close(&out);
            if (rc == VIGEN_OK && text == NULL) rc = vigen_error_set(&err, VIGEN_E_MEMORY, "out of memory");
            if (rc == VIGEN_OK) r->text = text;
            else {
                free(text);
                rc = pyn_fail(r, &err);
            }
        }
    }
    for (size_t k = 0; k < count; k++) free(paths[k]);
    return pyn_end(r, rc);
}
