/* resolve.c — where a method name leads (vigen/library.h): the current
 * directory, VIGEN_PATH, then the library installed with vigen, found
 * relative to its templates as the emitter finds them. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "emit/template.h"
#include "library/library_internal.h"
#include "support/strbuf.h"
#include "support/nearest.h"

static int is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* the installed library's folder holding published/ and generated/ */
static char *installed_root(void)
{
    char *dir = vigen_template_dir("prk");
    char *slash = strrchr(dir, '/');
    if (slash) *slash = '\0';                     /* the templates' root */
    char *root = NULL;
#ifdef VIGEN_SOURCE_DIR
    if (strcmp(dir, VIGEN_SOURCE_DIR "/templates") == 0) root = vigen_strdup(VIGEN_SOURCE_DIR "/tableaux");
#endif
#ifdef VIGEN_LIBRARY_TABLEAUX_RELDIR
    if (root == NULL) root = vigen_strdup_printf("%s/%s", dir, VIGEN_LIBRARY_TABLEAUX_RELDIR);
#endif
    if (root == NULL) root = vigen_strdup_printf("%s/../tableaux", dir);
    free(dir);
    return root;
}

static void push(char ***dirs, size_t *n, char *dir)
{
    char **more = realloc(*dirs, (*n + 2) * sizeof **dirs);
    if (more == NULL) {
        free(dir);
        return;
    }
    *dirs = more;
    (*dirs)[(*n)++] = dir;
    (*dirs)[*n] = NULL;
}

char **vigen_library_dirs(void)
{
    char **dirs = calloc(1, sizeof *dirs);
    size_t n = 0;
    if (dirs == NULL) return NULL;
    const char *env = getenv("VIGEN_PATH");
    if (env != NULL) {
        char *copy = vigen_strdup(env);
        for (char *p = copy; p != NULL;) {
            char *colon = strchr(p, ':');
            if (colon) *colon = '\0';
            if (*p != '\0') push(&dirs, &n, vigen_strdup(p));
            p = colon ? colon + 1 : NULL;
        }
        free(copy);
    }
    char *root = installed_root();
    for (size_t k = 0; k < 2; k++)
        push(&dirs, &n, vigen_strdup_printf("%s/%s", root, library_parts[k]));
    free(root);
    return dirs;
}

void vigen_library_dirs_free(char **dirs)
{
    for (size_t k = 0; dirs && dirs[k]; k++) free(dirs[k]);
    free(dirs);
}

/* dir/name, with ".lua" added when the name has none; NULL if no such file */
static char *candidate(const char *dir, const char *name)
{
    size_t n = strlen(name);
    int has_ext = n > 4 && strcmp(name + n - 4, ".lua") == 0;
    char *path = dir ? vigen_strdup_printf("%s/%s%s", dir, name, has_ext ? "" : ".lua")
                     : vigen_strdup_printf("%s%s", name, has_ext ? "" : ".lua");
    if (is_file(path)) return path;
    free(path);
    return NULL;
}

char **vigen_library_names(char *const *dirs)
{
    size_t n = 0, cap = 16;
    char **names = calloc(cap + 1, sizeof *names);
    for (size_t k = 0; names && dirs && dirs[k]; k++) {
        DIR *d = is_dir(dirs[k]) ? opendir(dirs[k]) : NULL;
        struct dirent *e;
        while (d && (e = readdir(d)) != NULL) {
            size_t len = strlen(e->d_name);
            if (len <= 4 || strcmp(e->d_name + len - 4, ".lua") != 0) continue;
            if (n == cap) {
                char **more = realloc(names, (2 * cap + 1) * sizeof *names);
                if (more == NULL) break;
                names = more;
                cap *= 2;
            }
            names[n] = vigen_strdup(e->d_name);
            names[n++][len - 4] = '\0';
            names[n] = NULL;
        }
        if (d) closedir(d);
    }
    return names;
}

int vigen_library_resolve(char **path, const char *operand, vigen_error *err)
{
    *path = NULL;
    if (is_file(operand)) {
        *path = vigen_strdup(operand);
        return VIGEN_OK;
    }
    char **dirs = vigen_library_dirs();
    const char *slash = strchr(operand, '/');
    if (slash == NULL && *operand != '\0') {
        *path = candidate(NULL, operand);
        for (size_t k = 0; *path == NULL && dirs && dirs[k]; k++) *path = candidate(dirs[k], operand);
    } else if (slash != NULL && strchr(slash + 1, '/') == NULL) {
        /* published/NAME or generated/NAME: a part of the installed library */
        char *root = installed_root();
        for (size_t k = 0; k < 2 && *path == NULL; k++)
            if (strncmp(operand, library_parts[k], (size_t)(slash - operand)) == 0 &&
                strlen(library_parts[k]) == (size_t)(slash - operand)) {
                char *dir = vigen_strdup_printf("%s/%s", root, library_parts[k]);
                *path = candidate(dir, slash + 1);
                free(dir);
            }
        free(root);
    }
    if (*path != NULL) {
        vigen_library_dirs_free(dirs);
        return VIGEN_OK;
    }
    char **names = vigen_library_names(dirs);
    const char *near = names && slash == NULL ? vigen_nearest_name(operand, (const char *const *)names, 3) : NULL;
    if (near)
        vigen_error_set(err, VIGEN_E_USAGE, "%s: no such file or method; did you mean '%s'? ('vigen list' lists the "
                        "methods known by name)", operand, near);
    else
        vigen_error_set(err, VIGEN_E_USAGE, "%s: no such file or method (give a tableau or spec file, or a name "
                        "that 'vigen list' lists)", operand);
    for (size_t k = 0; names && names[k]; k++) free(names[k]);
    free(names);
    vigen_library_dirs_free(dirs);
    return VIGEN_E_USAGE;
}
