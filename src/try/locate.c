/* locate.c — where `vigen try` finds what it compiles against and the
 * methods it knows by name.  A vigen run from its build tree uses the build
 * tree's runtime and problem libraries and the source tree's headers and
 * tableaux; an installed vigen uses those installed under its prefix, found
 * from its templates the way the emitter finds them (emit/template.h), so
 * that a moved prefix still works. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "emit/template.h"
#include "vigen/library.h"
#include "try/try_internal.h"
#include "support/strbuf.h"
#include "support/nearest.h"

static int is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

void try_paths_clear(try_paths *p)
{
    free(p->template_path);
    free(p->include_dir);
    free(p->problems_lib);
    free(p->runtime_lib);
    free(p->published_dir);
    memset(p, 0, sizeof *p);
}

int try_paths_find(try_paths *p, vigen_error *err)
{
    memset(p, 0, sizeof *p);
    char *dir = vigen_template_dir("try");
    p->template_path = vigen_strdup_printf("%s/driver.c.in", dir);
    char *root = vigen_strdup(dir);
    char *slash = strrchr(root, '/');
    if (slash) *slash = '\0';
    free(dir);
#if defined(VIGEN_SOURCE_DIR) && defined(VIGEN_TRY_BUILD_RUNTIME_LIB)
    int build_tree = strcmp(root, VIGEN_SOURCE_DIR "/templates") == 0;
#else
    int build_tree = 0;
#endif
    if (build_tree) {
#if defined(VIGEN_SOURCE_DIR) && defined(VIGEN_TRY_BUILD_RUNTIME_LIB)
        p->include_dir = vigen_strdup(VIGEN_TRY_BUILD_INCLUDE_DIR);
        p->runtime_lib = vigen_strdup(VIGEN_TRY_BUILD_RUNTIME_LIB);
        p->problems_lib = vigen_strdup(VIGEN_TRY_BUILD_PROBLEMS_LIB);
        p->published_dir = vigen_strdup(VIGEN_SOURCE_DIR "/tableaux/published");
#endif
    } else {
#if defined(VIGEN_TRY_INSTALL_INCLUDE_RELDIR)
        p->include_dir = vigen_strdup_printf("%s/%s", root, VIGEN_TRY_INSTALL_INCLUDE_RELDIR);
        p->runtime_lib = vigen_strdup_printf("%s/%s/libvigen_runtime.a", root, VIGEN_TRY_INSTALL_LIB_RELDIR);
        p->problems_lib = vigen_strdup_printf("%s/%s/libvigen_problems.a", root, VIGEN_TRY_INSTALL_LIB_RELDIR);
        p->published_dir = vigen_strdup_printf("%s/%s", root, VIGEN_TRY_INSTALL_TABLEAUX_RELDIR);
#else
        p->include_dir = vigen_strdup_printf("%s/../../../include", root);
        p->runtime_lib = vigen_strdup_printf("%s/../../../lib/libvigen_runtime.a", root);
        p->problems_lib = vigen_strdup_printf("%s/../../../lib/libvigen_problems.a", root);
        p->published_dir = vigen_strdup_printf("%s/../tableaux/published", root);
#endif
    }
    free(root);
    const char *missing = NULL;
    char *problems_h = vigen_strdup_printf("%s/vigen/problems.h", p->include_dir);
    if (!is_file(p->template_path)) missing = p->template_path;
    else if (!is_file(problems_h)) missing = problems_h;
    else if (!is_file(p->runtime_lib)) missing = p->runtime_lib;
    else if (!is_file(p->problems_lib)) missing = p->problems_lib;
    int rc = VIGEN_OK;
    if (missing)
        rc = vigen_error_set(err, VIGEN_E_TEMPLATE,
                             "%s is missing: %s (build the tree with cmake --build, or reinstall vigen)", missing,
                             build_tree ? "the build tree is incomplete" : "the installation is incomplete");
    free(problems_h);
    if (rc != VIGEN_OK) try_paths_clear(p);
    return rc;
}

int try_method_is_file(const char *path)
{
    return is_file(path);
}

char *try_method_label(const char *method)
{
    const char *base = strrchr(method, '/');
    base = base ? base + 1 : method;
    char *label = vigen_strdup(base);
    size_t n = strlen(label);
    if (n > 4 && strcmp(label + n - 4, ".lua") == 0) label[n - 4] = '\0';
    return label;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The stems of the published tableaux, NULL-terminated (for a hint). */
static char **published_names(const char *dir)
{
    char *dirs[2] = {(char *)dir, NULL};
    return vigen_library_names(dirs);
}

int try_method_resolve(char **path, const char *method, const try_paths *p, vigen_error *err)
{
    *path = NULL;
    if (is_file(method)) {
        *path = vigen_strdup(method);
        return VIGEN_OK;
    }
    if (strchr(method, '/') == NULL && *method != '\0') {
        char *cand = vigen_strdup_printf("%s/%s%s", p->published_dir, method,
                                         strstr(method, ".lua") ? "" : ".lua");
        if (is_file(cand)) {
            *path = cand;
            return VIGEN_OK;
        }
        free(cand);
    }
    char **names = published_names(p->published_dir);
    size_t n = 0;
    while (names && names[n]) n++;
    /* the built-in names are candidates for the hint too (not owned) */
    char **all = names ? realloc(names, (n + 8) * sizeof *names) : NULL;
    if (all) {
        names = all;
        size_t nb = 0;
        for (const char *b; nb < 7 && (b = try_lagrangian_name(nb)) != NULL; nb++) names[n + nb] = (char *)b;
        names[n + nb] = NULL;
    }
    const char *near = names ? vigen_nearest_name(method, (const char *const *)names, 3) : NULL;
    if (near)
        vigen_error_set(err, VIGEN_E_USAGE,
                        "%s: no such file or published method; did you mean '%s'? ('vigen try --list-methods' lists them)",
                        method, near);
    else
        vigen_error_set(err, VIGEN_E_USAGE,
                        "%s: no such file or published method (give a tableau or spec file, or a name that "
                        "'vigen try --list-methods' lists)",
                        method);
    for (size_t k = 0; names && k < n; k++) free(names[k]);
    free(names);
    return VIGEN_E_USAGE;
}

void vigen_try_print_methods(FILE *out)
{
    try_paths p;
    vigen_error err;
    vigen_error_init(&err);
    if (try_paths_find(&p, &err) != VIGEN_OK) {
        fprintf(out, "(%s)\n", err.message);
        vigen_error_clear(&err);
        return;
    }
    char **names = published_names(p.published_dir);
    size_t n = 0;
    while (names && names[n]) n++;
    if (n > 1) qsort(names, n, sizeof *names, by_name);
    for (size_t k = 0; k < n; k++) {
        fprintf(out, "%s\n", names[k]);
        free(names[k]);
    }
    free(names);
    try_lagrangian_print(out);
    try_paths_clear(&p);
}
