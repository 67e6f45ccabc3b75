/* gnuplot.c — figures drawn by gnuplot ($GNUPLOT, else gnuplot), run as a
 * program on a script in the private working directory.  The data (CSV)
 * and the SVG are written into the plot directory as one atomic unit
 * (support/file.h); the PNG, binary, is copied to a temporary file beside its
 * target, synced and renamed over it, so that it too appears whole or not
 * at all (its temporary file is removed by the guards if the process is
 * ended meanwhile). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "support/file.h"
#include "support/guard.h"
#include "try/try_internal.h"
#include "support/strbuf.h"

/* A PNG is a few hundred kilobytes; more is not one of ours. */
#define TRY_MAX_IMAGE (64u << 20)

char *try_gnuplot_quote(const char *s)
{
    char *q = vigen_strdup(s);
    for (char *c = q; *c; c++)
        if (*c == '"' || *c == ',' || *c == '\\' || (unsigned char)*c < 0x20 || (unsigned char)*c >= 0x7f) *c = '_';
    return q;
}

int try_plot_dir(const char *dir, vigen_error *err)
{
    struct stat st;
    if (stat(dir, &st) == 0 && !S_ISDIR(st.st_mode))
        return vigen_error_set(err, VIGEN_E_WRITE, "%s is not a directory (give --plot a directory)", dir);
    return VIGEN_OK;
}

/* Copies len bytes to path: a temporary file beside it, synced, renamed. */
static int write_binary_atomic(const char *path, const char *data, size_t len, vigen_error *err)
{
    char *tmp = vigen_strdup_printf("%s.tmp-XXXXXX", path);
    sigset_t old;
    vigen_guard_block(&old);
    int fd = mkstemp(tmp);
    int slot = fd >= 0 ? vigen_guard_temp_add(tmp) : -1;
    vigen_guard_unblock(&old);
    int ok = fd >= 0;
    for (size_t done = 0; ok && done < len;) {
        ssize_t w = write(fd, data + done, len - done);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) ok = 0;
        else done += (size_t)w;
    }
    if (ok && (fchmod(fd, 0644) != 0 || fsync(fd) != 0)) ok = 0;
    if (fd >= 0 && close(fd) != 0) ok = 0;
    int saved = errno;
    vigen_guard_block(&old);
    if (ok && rename(tmp, path) != 0) {
        ok = 0;
        saved = errno;
    }
    if (!ok && fd >= 0) unlink(tmp);
    vigen_guard_temp_drop(slot);
    vigen_guard_unblock(&old);
    free(tmp);
    if (!ok) return vigen_error_set(err, VIGEN_E_WRITE, "cannot write %s: %s", path, strerror(saved));
    return VIGEN_OK;
}

static int run_gnuplot(const char *script_path, const char *stem, vigen_error *err)
{
    const char *gp = getenv("GNUPLOT");
    if (gp == NULL || *gp == '\0') gp = "gnuplot";
    char *log_name = vigen_strdup_printf("%s_gnuplot.log", stem);
    char *log = try_workdir_file(log_name);
    free(log_name);
    char *argv[] = { (char *)gp, (char *)script_path, NULL };
    int nf = 0, rc = VIGEN_OK;
    int status = try_process_run(argv, log, &nf);
    if (status < 0 || nf)
        rc = vigen_error_set(err, VIGEN_E_TEMPLATE,
                             "cannot run gnuplot '%s' for the plots (install gnuplot-nox, e.g. ./setup.sh does, or "
                             "set GNUPLOT)", gp);
    else if (status != 0) {
        char *head = try_log_first_error(log);
        rc = vigen_error_set(err, VIGEN_E_TEMPLATE, "gnuplot failed on %s (status %d): %s", stem, status,
                             head ? head : "(no output)");
        free(head);
    }
    free(log);
    return rc;
}

void try_figures_clear(try_figures *f)
{
    for (size_t i = 0; i < f->n; i++) {
        free(f->path[i]);
        free(f->data[i]);
    }
    memset(f, 0, sizeof *f);
}

/* Takes path and data (heap) into f. */
static void add_file(try_figures *f, char *path, char *data, size_t len, int binary)
{
    if (f->n >= TRY_MAX_FIGURE_FILES) {
        free(path);
        free(data);
        return;
    }
    f->path[f->n] = path;
    f->data[f->n] = data;
    f->len[f->n] = len;
    f->binary[f->n++] = binary;
}

int try_plot_files(try_figures *figs, const char *dir, const char *stem, const char *csv, const char *script,
                   vigen_error *err)
{
    char *names[4];
    const char *ext[4] = { "csv", "gp", "svg", "png" };
    char *work[4] = { NULL, NULL, NULL, NULL };
    for (int i = 0; i < 4; i++) {
        names[i] = vigen_strdup_printf("%s.%s", stem, ext[i]);
        if (i >= 2) work[i] = try_workdir_file(names[i]);
    }
    int rc = try_workdir_write(&work[0], names[0], csv, err);
    char *svg = try_gnuplot_quote(work[2]), *png = try_gnuplot_quote(work[3]), *data = try_gnuplot_quote(work[0]);
    char *full = vigen_strdup_printf(
        "datafile = \"%s\"\n"
        "set datafile separator \",\"\n"
        "set datafile columnheaders\n"
        "set terminal svg size 800,560 noenhanced font \"sans,12\" background rgb \"white\"\n"
        "set output \"%s\"\n"
        "%s"
        "set output\n"
        "set terminal pngcairo size 800,560 noenhanced font \"sans,10\" background rgb \"white\"\n"
        "set output \"%s\"\n"
        "replot\n"
        "set output\n",
        data, svg, script, png);
    if (rc == VIGEN_OK) rc = try_workdir_write(&work[1], names[1], full, err);
    if (rc == VIGEN_OK) rc = run_gnuplot(work[1], stem, err);
    char *svg_text = NULL, *png_data = NULL;
    size_t svg_len = 0, png_len = 0;
    if (rc == VIGEN_OK) rc = vigen_read_file(&svg_text, &svg_len, work[2], TRY_MAX_IMAGE, err);
    if (rc == VIGEN_OK) rc = vigen_read_file(&png_data, &png_len, work[3], TRY_MAX_IMAGE, err);
    if (rc != VIGEN_OK && err->code == VIGEN_E_IO) {
        err->code = VIGEN_E_TEMPLATE;
        vigen_error_prefix(err, "gnuplot wrote no figure: ");
    }
    if (rc == VIGEN_OK) {
        add_file(figs, vigen_strdup_printf("%s/%s", dir, names[0]), vigen_strdup(csv), strlen(csv), 0);
        add_file(figs, vigen_strdup_printf("%s/%s", dir, names[2]), svg_text, svg_len, 0);
        add_file(figs, vigen_strdup_printf("%s/%s", dir, names[3]), png_data, png_len, 1);
        svg_text = png_data = NULL;
    }
    free(svg_text);
    free(png_data);
    free(full);
    free(svg);
    free(png);
    free(data);
    for (int i = 0; i < 4; i++) {
        if (work[i]) remove(work[i]);
        free(work[i]);
        free(names[i]);
    }
    return rc;
}

int try_figures_commit(try_figures *f, const char *dir, vigen_error *err)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return vigen_error_set(err, VIGEN_E_WRITE, "cannot create the plot directory %s: %s", dir, strerror(errno));
    const char *paths[TRY_MAX_FIGURE_FILES], *texts[TRY_MAX_FIGURE_FILES];
    size_t nt = 0;
    for (size_t i = 0; i < f->n; i++)
        if (!f->binary[i]) {
            paths[nt] = f->path[i];
            texts[nt++] = f->data[i];
        }
    /* the data and the SVG figures as one unit, then each PNG */
    int rc = vigen_write_files_atomic(nt, paths, texts, err);
    for (size_t i = 0; i < f->n && rc == VIGEN_OK; i++)
        if (f->binary[i]) rc = write_binary_atomic(f->path[i], f->data[i], f->len[i], err);
    return rc;
}
