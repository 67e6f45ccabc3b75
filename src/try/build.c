/* build.c — one method made into a program: the stepper emitted
 * (vigen/emit.h) for double, the driver rendered from templates/try/
 * driver.c.in, both compiled with the system C compiler against the runtime
 * and the problem library, in the private working directory.  For `vigen
 * order` the tableau's orders are also certified (vigen/check.h). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "emit/names.h"
#include "emit/template.h"
#include "vigen/check.h"
#include "vigen/emit.h"
#include "vigen/library.h"
#include "support/progress.h"
#include "try/try_internal.h"
#include "support/strbuf.h"

#ifndef VIGEN_TRY_LINK_LIBS
#define VIGEN_TRY_LINK_LIBS "-lgsl -lgslcblas -lm"
#endif

void try_build_clear(try_build *b)
{
    free(b->label);
    free(b->exe);
    free(b->flows);
    memset(b, 0, sizeof *b);
}

/* Certified orders of the tableau, for `vigen order`. */
static int certify(try_build *b, vigen_tableau *t, const char *label, vigen_error *err)
{
    vigen_check_options co;
    vigen_check_options_init(&co);
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    int rc = vigen_check_tableau(&rep, t, NULL, &co, err);
    if (rc == VIGEN_OK) {
        b->certified = rep.orders[VIGEN_CHECK_GENERAL].level.value;
        b->certified_separable = rep.orders[VIGEN_CHECK_SEPARABLE].level.value;
    } else vigen_error_prefix(err, "%s: ", label);
    vigen_check_report_clear(&rep);
    return rc;
}

/* allow_inexact: 1 rounds decimals with too few digits as written (the
 * user's --allow-inexact), 2 does so after saying that the library's method
 * is published with those digits (a method given by name). */
static int emit(try_build *b, size_t k, const char *file, int check, int allow_inexact, char **hpath, char **cpath,
                vigen_error *err)
{
    char name[32];
    snprintf(name, sizeof name, "m%zu", k);
    const char *base = strrchr(file, '/');
    vigen_emit_options eo = { .name = name, .real = VIGEN_REAL_DOUBLE, .input_label = base ? base + 1 : file };
    vigen_tableau t;
    int loaded = 0;
    char *h = NULL, *c = NULL, *ident = NULL;
    vigen_progress_set("%s: emitting the stepper", b->label);
    eo.allow_inexact = allow_inexact == 1;
    int rc = vigen_emit_load_render(&t, &loaded, file, &eo, &h, &c, &ident, err);
    if (rc == VIGEN_E_INEXACT && allow_inexact == 2) {
        vigen_error_clear(err);
        vigen_warn("%s: a method of the library published with decimals too short to round correctly to "
                   "double: its coefficients are those decimals as written (as with --allow-inexact)", b->label);
        eo.allow_inexact = 1;
        rc = vigen_emit_load_render(&t, &loaded, file, &eo, &h, &c, &ident, err);
    }
    if (rc == VIGEN_OK && check) rc = certify(b, &t, b->label, err);
    if (rc == VIGEN_OK && strcmp(vigen_emit_variant_chosen(&t, NULL), "split") == 0 && t.flows) {
        /* the driver maps the method's flows to the problem's by name (a
         * name made safe for a string literal no longer matches, and is
         * refused there as a flow the problem lacks) */
        vigen_strbuf fl;
        vigen_strbuf_init(&fl);
        vigen_strbuf_append(&fl, "");
        for (slong j = 0; j < t.flows->nflows; j++) {
            char *safe = vigen_emit_safe_text(t.flows->names[j], 60);
            vigen_strbuf_printf(&fl, "%s\"%s\"", j ? ", " : "", safe);
            free(safe);
        }
        b->flows = fl.data;
    }
    if (loaded) vigen_tableau_clear(&t);
    char fname[48];
    if (rc == VIGEN_OK) {
        snprintf(fname, sizeof fname, "%s.h", ident);
        rc = try_workdir_write(hpath, fname, h, err);
    }
    if (rc == VIGEN_OK) {
        snprintf(fname, sizeof fname, "%s.c", ident);
        rc = try_workdir_write(cpath, fname, c, err);
    }
    free(h);
    free(c);
    free(ident);
    return rc;
}

/* lm: the built-in Lagrangian method, or NULL for an emitted stepper. */
static int render_driver(char **path, size_t k, const char *label, const try_lagrangian_method *lm,
                         const char *flows, const try_paths *p, vigen_error *err)
{
    vigen_slots slots;
    vigen_slots_init(&slots);
    vigen_slots_textf(&slots, "NAME", "m%zu", k);
    vigen_slots_flag(&slots, "LAGRANGIAN", lm != NULL);
    vigen_slots_flag(&slots, "SPLIT", flows != NULL);
    vigen_slots_text(&slots, "FLOWS", flows ? flows : "");
    vigen_slots_textf(&slots, "KIND", "%d", lm ? lm->kind : 0);
    vigen_slots_text(&slots, "METHOD", label);
    char *text = NULL;
    int rc = vigen_template_render_file(&text, p->template_path, &slots, NULL, err);
    vigen_slots_clear(&slots);
    if (rc != VIGEN_OK) return rc;
    char fname[48];
    snprintf(fname, sizeof fname, "m%zu_driver.c", k);
    rc = try_workdir_write(path, fname, text, err);
    free(text);
    return rc;
}

/* stepper: the emitted stepper's source, or NULL (a built-in method). */
static int compile(try_build *b, size_t k, const char *cc, const char *driver, const char *stepper,
                   const try_paths *p, vigen_error *err)
{
    char fname[48];
    snprintf(fname, sizeof fname, "m%zu_driver", k);
    b->exe = try_workdir_file(fname);
    snprintf(fname, sizeof fname, "m%zu_cc.log", k);
    char *log = try_workdir_file(fname);
    char *incdir = vigen_strdup_printf("-I%s", p->include_dir);
    char *stepdir = vigen_strdup(stepper ? stepper : driver);
    char *slash = strrchr(stepdir, '/');
    if (slash) *slash = '\0';
    char *incwork = vigen_strdup_printf("-I%s", stepdir);
    char *libs = vigen_strdup(VIGEN_TRY_LINK_LIBS);
    /* CC may carry flags ("gcc -m64"), as make and CMake take it */
    char *ccw = vigen_strdup(cc);
    char *argv[96];
    int n = 0;
    for (char *tok = strtok(ccw, " \t"); tok && n < 32; tok = strtok(NULL, " \t")) argv[n++] = tok;
    if (n == 0) argv[n++] = (char *)"cc";
    argv[n++] = "-std=c11";
    argv[n++] = "-O2";
    argv[n++] = incwork;
    argv[n++] = incdir;
    argv[n++] = (char *)driver;
    if (stepper) argv[n++] = (char *)stepper;
    argv[n++] = p->problems_lib;
    argv[n++] = p->runtime_lib;
    for (char *tok = strtok(libs, " "); tok && n < 90; tok = strtok(NULL, " ")) argv[n++] = tok;
    argv[n++] = "-o";
    argv[n++] = b->exe;
    argv[n] = NULL;
    vigen_progress_set("%s: compiling", b->label);
    int not_found = 0;
    int status = try_process_run(argv, log, &not_found);
    int rc = VIGEN_OK;
    if (status < 0 || not_found)
        rc = vigen_error_set(err, VIGEN_E_TEMPLATE,
                             "%s: cannot run the C compiler '%s' (install one, or set CC to a C compiler, e.g. CC=gcc)",
                             b->label, cc);
    else if (status != 0) {
        char *head = try_log_first_error(log);
        rc = vigen_error_set(err, VIGEN_E_TEMPLATE, "%s: the C compiler '%s' failed (status %d): %s", b->label, cc,
                             status, head ? head : "(no output)");
        free(head);
    }
    free(log);
    free(incdir);
    free(incwork);
    free(stepdir);
    free(libs);
    free(ccw);
    return rc;
}

/* Whether file is a method of the library (`vigen list`: a file of one of
 * its folders, which is how the command line resolves a name). */
static int in_library(const char *file)
{
    char *dir = vigen_strdup(file);
    char *slash = strrchr(dir, '/');
    if (slash) *slash = '\0';
    struct stat fs, ds;
    int found = 0;
    if (stat(slash ? dir : ".", &fs) == 0) {
        char **dirs = vigen_library_dirs();
        for (size_t k = 0; dirs && dirs[k] && !found; k++)
            found = stat(dirs[k], &ds) == 0 && ds.st_dev == fs.st_dev && ds.st_ino == fs.st_ino;
        vigen_library_dirs_free(dirs);
    }
    free(dir);
    return found;
}

int try_build_method(try_build *b, size_t k, const char *method, const try_paths *p, const char *cc, int check,
                     int allow_inexact, vigen_error *err)
{
    memset(b, 0, sizeof *b);
    b->label = try_method_label(method);
    char *file = NULL, *hpath = NULL, *cpath = NULL, *dpath = NULL;
    /* a file of that name is the user's: it wins over a built-in name */
    const try_lagrangian_method *lm = try_method_is_file(method) ? NULL : try_lagrangian_find(method);
    int rc = VIGEN_OK;
    if (lm) {
        b->builtin = 1;
        b->certified = b->certified_separable = lm->order;
    } else {
        rc = try_method_resolve(&file, method, p, err);
        const int library = rc == VIGEN_OK && in_library(file);
        if (rc == VIGEN_OK)
            rc = emit(b, k, file, check, allow_inexact ? 1 : library ? 2 : 0, &hpath, &cpath, err);
    }
    if (rc == VIGEN_OK) rc = render_driver(&dpath, k, b->label, lm, b->flows, p, err);
    if (rc == VIGEN_OK) rc = compile(b, k, cc, dpath, cpath, p, err);
    free(file);
    free(hpath);
    free(cpath);
    free(dpath);
    return rc;
}
