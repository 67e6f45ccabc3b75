/* try_internal.h — the parts of `vigen try` shared between its files: the
 * private working directory, the compiled driver of a method, one run of it,
 * gnuplot, and the summary statistics. */
#ifndef VIGEN_TRY_INTERNAL_H
#define VIGEN_TRY_INTERNAL_H

#include <stddef.h>
#include <stdio.h>
#include "vigen/error.h"
#include "vigen/try.h"

/* ---- workdir.c: the private temporary directory ------------------------- */
/* One directory per process at a time, mode 0700, under $TMPDIR (else /tmp).
 * Every file made in it is registered first (try_workdir_file), so that the
 * handlers of SIGINT, SIGTERM, SIGHUP and SIGALRM, installed by
 * try_workdir_create and chained to those before them, can end the running
 * child and remove the files and the directory with async-signal-safe calls
 * before the process ends. */
int try_workdir_create(vigen_error *err);
/* The path of name inside the directory (heap string), registered. */
char *try_workdir_file(const char *name);
/* Writes text to the file name of the directory; *path receives its path
 * (heap string, also on failure). */
int try_workdir_write(char **path, const char *name, const char *text, vigen_error *err);
void try_workdir_remove(void);
/* The child being waited for (0: none), killed by the signal handlers. */
void try_workdir_set_child(long pid);

/* ---- process.c: running programs --------------------------------------- */
/* Runs argv (argv[0] looked up in PATH), standard output and error to
 * log_path (or inherited when NULL), standard input /dev/null; waits.
 * Returns the exit status, 128 + signal for a signal, or -1 with errno set
 * when the program could not be started (127 from the child means the same:
 * *not_found is set then). */
int try_process_run(char *const *argv, const char *log_path, int *not_found);
/* The first lines of a log file (at most max_lines, each cut to 200
 * characters) as one line joined by " | " (messages are one line), or NULL;
 * the first line that mentions an error (else the first line). */
char *try_log_head(const char *path, int max_lines);
char *try_log_first_error(const char *path);

/* ---- locate.c: where the runtime, the problems and tableaux are --------- */
/* Fills the include directory and the library paths the driver is compiled
 * with: those of the build tree when the templates come from the source
 * tree, those installed beside the templates otherwise (heap strings). */
typedef struct {
    char *template_path;     /* templates/try/driver.c.in */
    char *include_dir;       /* holds vigen/runtime.h and vigen/problems.h */
    char *problems_lib, *runtime_lib;
    char *published_dir;     /* tableaux/published */
} try_paths;
int try_paths_find(try_paths *p, vigen_error *err);
void try_paths_clear(try_paths *p);
/* A method as the user names it: an existing file is itself; otherwise a
 * published tableau of that stem.  VIGEN_E_USAGE naming the method (with the
 * nearest published name) when neither exists.  *path is a heap string. */
int try_method_resolve(char **path, const char *method, const try_paths *p, vigen_error *err);
/* Whether path names an existing regular file. */
int try_method_is_file(const char *path);
/* The label of a method: its file stem. */
char *try_method_label(const char *method);

/* ---- lagrangian.c: the built-in Lagrangian integrators ----------------- */
typedef struct {
    const char *name;        /* "hp-midpoint", as the user gives it */
    int kind;                /* the driver's KIND */
    int order;               /* the proven order */
    const char *description; /* one line */
} try_lagrangian_method;
/* The built-in method of that name, or NULL. */
const try_lagrangian_method *try_lagrangian_find(const char *name);
/* The name of built-in method k, NULL past the last. */
const char *try_lagrangian_name(size_t k);
/* One line each: name and description. */
void try_lagrangian_print(FILE *out);

/* ---- problem_check.c: the problem checked before a run ---------------- */
/* VIGEN_E_USAGE naming the method and the problem when one of the n methods
 * is built in and opt's problem has no Lagrangian (point vortices). */
int try_lagrangian_check(size_t n, const char *const *names, const vigen_try_options *opt, vigen_error *err);
/* The problem of opt (created already once by try_plan_make) checked at its
 * initial value with vigen_problem_check, and with vigen_lagrangian_check
 * when one of the n methods is a built-in Lagrangian integrator:
 * VIGEN_E_DOMAIN with the check's sentence when it fails. */
int try_problem_check(size_t n, const char *const *names, const vigen_try_options *opt, vigen_error *err);

/* ---- build.c: emit a stepper, render the driver, compile --------------- */
typedef struct {
    char *label;
    char *exe;               /* the driver program */
    int certified, certified_separable; /* orders, when asked for (check = 1) */
    int builtin;             /* a built-in Lagrangian method: certified is its proven order */
    char *flows;             /* a splitting stepper of named flows (the split variant): the flows'
                                names as a C initialiser ("\"kepler\", \"interaction\""); NULL
                                otherwise */
} try_build;
/* Builds method k of the run into the working directory.  With check, the
 * tableau's orders are certified too (vigen/check.h).  allow_inexact: a
 * method file's decimals with too few digits are rounded as written (the
 * emitter warns); a method of the library (a file of vigen_library_dirs,
 * as a name on the command line resolves) is taken with its published
 * digits in any case, with a warning that says so. */
int try_build_method(try_build *b, size_t k, const char *method, const try_paths *p, const char *cc, int check,
                     int allow_inexact, vigen_error *err);
void try_build_clear(try_build *b);

/* ---- run_record.c: one run of a driver --------------------------------- */
/* Runs the driver of b on the problem for steps steps of h, sampling every
 * `every` steps, and fills r (r->label is b's).  A failed step is a result
 * (r->failed); VIGEN_E_TEMPLATE when the driver cannot run or writes
 * nothing readable, VIGEN_E_USAGE when it refuses the problem or its
 * parameters (the problem library's message). */
int try_run_driver(vigen_try_result *r, const try_build *b, const vigen_try_options *opt, double h,
                   unsigned long steps, unsigned long every, vigen_error *err);
void try_result_clear(vigen_try_result *r);

/* ---- run_plan.c: the problem, h and the number of steps ---------------- */
typedef struct {
    double period, time, h;
    unsigned long steps;
    int has_reference;
} try_plan;
/* Checks the problem and its parameters (VIGEN_E_USAGE with the problem
 * library's message) and computes h and the steps from opt; spp overrides
 * opt->steps_per_period when > 0. */
int try_plan_make(try_plan *plan, const vigen_try_options *opt, long spp, vigen_error *err);

/* ---- gnuplot.c ---------------------------------------------------------- */
/* The files of the figures of one command, collected until all are drawn. */
#define TRY_MAX_FIGURE_FILES 12
typedef struct {
    size_t n;
    char *path[TRY_MAX_FIGURE_FILES], *data[TRY_MAX_FIGURE_FILES];
    size_t len[TRY_MAX_FIGURE_FILES];
    int binary[TRY_MAX_FIGURE_FILES];
} try_figures;
/* Runs script (gnuplot commands that read the data from the file named by
 * the variable `datafile` and draw one figure; the terminal and output are
 * set here) on csv, for an SVG and a PNG, and adds dir/stem.csv,
 * dir/stem.svg and dir/stem.png to figs. */
int try_plot_files(try_figures *figs, const char *dir, const char *stem, const char *csv, const char *script,
                   vigen_error *err);
/* Creates dir (one level) if missing and writes the collected files: the
 * texts as one atomic unit, then each PNG atomically. */
int try_figures_commit(try_figures *figs, const char *dir, vigen_error *err);
void try_figures_clear(try_figures *figs);
/* A title/label text safe inside a gnuplot double-quoted string. */
char *try_gnuplot_quote(const char *s);
/* VIGEN_E_WRITE when dir exists and is not a directory. */
int try_plot_dir(const char *dir, vigen_error *err);

/* ---- try.c -------------------------------------------------------------- */
/* The C compiler: opt->cc, else $CC, else "cc". */
const char *try_cc(const vigen_try_options *opt);

/* ---- summary.c ---------------------------------------------------------- */
/* A JSON number, or null when v is not finite. */
void try_json_number(FILE *out, double v);

/* ---- stats.c ------------------------------------------------------------ */
/* Least-squares slope of y against x (compensated sums); NaN for n < 2. */
double try_lsq_slope(const double *x, const double *y, size_t n);

#endif
