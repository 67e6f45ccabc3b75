/* template.c — the template engine (slot declaration, inline and block
 * slots, flag sections, included files; see template.h), the slot sets it
 * renders with, and the one lookup of the templates directory. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#if defined(__linux__)
#include <unistd.h>
#endif
#include "support/file.h"
#include "emit/template.h"
#include "support/strbuf.h"

/* ------------------------------------------------------------- slot sets */

void vigen_slots_init(vigen_slots *s) { memset(s, 0, sizeof *s); }

static void slot_free(vigen_slot *v)
{
    free(v->name);
    free(v->text);
    for (size_t k = 0; k < v->nlines; k++) free(v->lines[k]);
    free(v->lines);
    memset(v, 0, sizeof *v);
}

void vigen_slots_clear(vigen_slots *s)
{
    for (size_t k = 0; k < s->n; k++) {
        slot_free(s->v[k]);
        free(s->v[k]);
    }
    free(s->v);
    memset(s, 0, sizeof *s);
}

const vigen_slot *vigen_slots_find(const vigen_slots *s, const char *name)
{
    for (size_t k = 0; k < s->n; k++)
        if (strcmp(s->v[k]->name, name) == 0) return s->v[k];
    return NULL;
}

/* A fresh slot of that name (an earlier one of the name is replaced). */
static vigen_slot *slot_new(vigen_slots *s, const char *name, int kind)
{
    vigen_slot *v = (vigen_slot *)vigen_slots_find(s, name);
    if (v) {
        slot_free(v);
    } else {
        if (s->n == s->cap) {
            s->cap = s->cap ? 2 * s->cap : 32;
            s->v = realloc(s->v, s->cap * sizeof *s->v);
            if (s->v == NULL) abort();
        }
        v = calloc(1, sizeof *v);
        if (v == NULL) abort();
        s->v[s->n++] = v;
    }
    v->name = vigen_strdup(name);
    v->kind = kind;
    return v;
}

void vigen_slots_text(vigen_slots *s, const char *name, const char *text)
{
    slot_new(s, name, VIGEN_SLOT_TEXT)->text = vigen_strdup(text);
}

/* The formatted text (heap). */
static char *vformat(const char *fmt, va_list ap)
{
    va_list aq;
    va_copy(aq, ap);
    int n = vsnprintf(NULL, 0, fmt, aq);
    va_end(aq);
    char *s = malloc((size_t)(n > 0 ? n : 0) + 1);
    if (s == NULL) abort();
    vsnprintf(s, (size_t)(n > 0 ? n : 0) + 1, fmt, ap);
    return s;
}

void vigen_slots_textf(vigen_slots *s, const char *name, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *text = vformat(fmt, ap);
    va_end(ap);
    slot_new(s, name, VIGEN_SLOT_TEXT)->text = text;
}

void vigen_slots_flag(vigen_slots *s, const char *name, int on) { slot_new(s, name, VIGEN_SLOT_FLAG)->on = on != 0; }

vigen_slot *vigen_slots_lines(vigen_slots *s, const char *name) { return slot_new(s, name, VIGEN_SLOT_LINES); }

void vigen_slot_line(vigen_slot *slot, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *line = vformat(fmt, ap);
    va_end(ap);
    if (slot->nlines == slot->cap) {
        slot->cap = slot->cap ? 2 * slot->cap : 16;
        slot->lines = realloc(slot->lines, slot->cap * sizeof *slot->lines);
        if (slot->lines == NULL) abort();
    }
    slot->lines[slot->nlines++] = line;
}

/* ------------------------------------------------------------- rendering */

static const char decl_opener[] = "/* vigen-template slots:";

/* Included files nest at most this deep: deeper is taken for a cycle. */
enum { MAX_INCLUDE_DEPTH = 8 };

typedef struct {
    const char *file;
    const char *dir;     /* the folder includes resolve in; NULL: no includes (text rendering) */
    int depth;           /* of includes above this file */
    const vigen_slots *slots;
    char **declared;     /* names in the declaration */
    long *decl_used;     /* line of the first use, 0: unused */
    size_t ndeclared;
    vigen_error *err;
} render_ctx;

static int is_name_start(char c) { return c >= 'A' && c <= 'Z'; }
static int is_name_char(char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

static int fail(render_ctx *R, long line, const char *fmt, const char *name)
{
    char *what = vigen_strdup_printf(fmt, name);
    vigen_error_set(R->err, VIGEN_E_TEMPLATE, "template %s:%ld: %s", R->file, line, what);
    free(what);
    return VIGEN_E_TEMPLATE;
}

/* The slot a mark names, checked against the declaration and the kind the
 * mark needs. */
static int lookup(const vigen_slot **out, render_ctx *R, long line, const char *name, int kind)
{
    static const char *const kinds[] = { "an inline @NAME@ text", "a block @@NAME@@", "an @if flag" };
    size_t d = 0;
    while (d < R->ndeclared && strcmp(R->declared[d], name) != 0) d++;
    if (d == R->ndeclared) return fail(R, line, "slot %s is used but not declared in the first-line slots comment", name);
    if (R->decl_used[d] == 0) R->decl_used[d] = line;
    const vigen_slot *v = vigen_slots_find(R->slots, name);
    if (v == NULL) return fail(R, line, "slot %s is missing: the emitter supplies no value for it", name);
    if (v->kind != kind) {
        char *msg = vigen_strdup_printf("slot %%s is used as %s, but the emitter supplies %s", kinds[kind], kinds[v->kind]);
        fail(R, line, msg, name);
        free(msg);
        return VIGEN_E_TEMPLATE;
    }
    *out = v;
    return VIGEN_OK;
}

/* Reads the declaration comment; *end points after it (and its newline);
 * *lines counts the lines it spans. */
static int read_declaration(render_ctx *R, const char *text, const char **end, long *lines)
{
    if (strncmp(text, decl_opener, sizeof decl_opener - 1) != 0)
        return fail(R, 1, "%s: the template must open with the comment /* vigen-template slots: NAME ... */",
                    "no slot declaration");
    const char *p = text + sizeof decl_opener - 1;
    const char *close = strstr(p, "*/");
    if (close == NULL) return fail(R, 1, "%s: the slot declaration comment is not closed", "malformed mark");
    *lines = 1;
    while (p < close) {
        if (*p == '\n') { (*lines)++; p++; continue; }
        if (*p == ' ' || *p == '\t' || *p == '*') { p++; continue; }
        const char *q = p;
        while (q < close && !(*q == ' ' || *q == '\t' || *q == '\n' || *q == '*')) q++;
        const char *r = p;
        while (r < q && is_name_char(*r)) r++;
        if (r != q || !is_name_start(*p)) {
            char *bad = vigen_strdup_printf("%.*s", (int)(q - p), p);
            fail(R, *lines, "malformed slot name '%s' in the slot declaration (names are [A-Z][A-Z0-9_]*)", bad);
            free(bad);
            return VIGEN_E_TEMPLATE;
        }
        R->declared = realloc(R->declared, (R->ndeclared + 1) * sizeof *R->declared);
        R->decl_used = realloc(R->decl_used, (R->ndeclared + 1) * sizeof *R->decl_used);
        if (R->declared == NULL || R->decl_used == NULL) abort();
        R->declared[R->ndeclared] = vigen_strdup_printf("%.*s", (int)(q - p), p);
        R->decl_used[R->ndeclared++] = 0;
        p = q;
    }
    p = close + 2;
    if (*p == '\n') p++;
    *end = p;
    return VIGEN_OK;
}

/* A line that is only a section mark: kind 1 @if, 2 @else@, 3 @end@ (0: not
 * one); for @if, the name and negation. */
static int section_mark(const char *line, size_t len, char *name, size_t cap, int *negate)
{
    size_t a = 0, b = len;
    while (a < b && (line[a] == ' ' || line[a] == '\t')) a++;
    while (b > a && (line[b - 1] == ' ' || line[b - 1] == '\t')) b--;
    size_t n = b - a;
    const char *m = line + a;
    if (n == 6 && memcmp(m, "@else@", 6) == 0) return 2;
    if (n == 5 && memcmp(m, "@end@", 5) == 0) return 3;
    if (n > 5 && memcmp(m, "@if ", 4) == 0 && m[n - 1] == '@') {
        size_t i = 4;
        *negate = m[i] == '!';
        if (*negate) i++;
        size_t k = n - 1 - i;
        if (k >= cap) k = cap - 1;
        memcpy(name, m + i, k);
        name[k] = 0;
        return 1;
    }
    return 0;
}

/* Whether a line is only an include mark, `@include FILE@` (blanks around
 * allowed); *name, *n: the FILE between the marks. */
static int include_mark(const char *line, size_t len, const char **name, size_t *n)
{
    size_t a = 0, b = len;
    while (a < b && (line[a] == ' ' || line[a] == '\t')) a++;
    while (b > a && (line[b - 1] == ' ' || line[b - 1] == '\t')) b--;
    if (b - a < 11 || memcmp(line + a, "@include ", 9) != 0 || line[b - 1] != '@') return 0;
    *name = line + a + 9;
    *n = b - 1 - (a + 9);
    return 1;
}

/* A file name of the template's own folder: [A-Za-z0-9_][A-Za-z0-9_.-]*, so
 * that no name (no "/", no leading ".") reaches outside that folder. */
static int valid_include(const char *s, size_t n)
{
    if (n == 0 || s[0] == '.' || s[0] == '-') return 0;
    for (size_t k = 0; k < n; k++)
        if (!((s[k] >= 'a' && s[k] <= 'z') || (s[k] >= 'A' && s[k] <= 'Z') || (s[k] >= '0' && s[k] <= '9') ||
              s[k] == '_' || s[k] == '.' || s[k] == '-'))
            return 0;
    return 1;
}

static int render_path(char **out, const char *path, int depth, const vigen_slots *slots, unsigned char *declared,
                       vigen_error *err);

/* An include line: the named file of the template's folder, rendered as a
 * template of its own (its declaration, its contract) with the same slots;
 * its output stands for the line.  Rendered and checked in a section that
 * is off too (out NULL), like every other line. */
static int render_include(vigen_strbuf *out, render_ctx *R, long lineno, const char *name, size_t n,
                          unsigned char *declared)
{
    char *shown = vigen_strdup_printf("%.*s", (int)n, name);
    int rc = VIGEN_OK;
    if (R->dir == NULL)
        rc = fail(R, lineno, "@include %s@: only a template file can include another (of its folder)", shown);
    else if (!valid_include(name, n))
        rc = fail(R, lineno,
                  "malformed mark '@include %s@' (a file of the template's own folder: [A-Za-z0-9_][A-Za-z0-9_.-]*)",
                  shown);
    else if (R->depth >= MAX_INCLUDE_DEPTH)
        rc = fail(R, lineno, "@include %s@: includes nested deeper than 8 (does a file include itself?)", shown);
    if (rc == VIGEN_OK) {
        char *path = vigen_strdup_printf("%s/%s", R->dir, shown), *text = NULL;
        rc = render_path(&text, path, R->depth + 1, R->slots, declared, R->err);
        if (rc == VIGEN_OK && out) vigen_strbuf_append(out, text);
        free(text);
        free(path);
    }
    free(shown);
    return rc;
}

static int valid_name(const char *s)
{
    if (!is_name_start(*s)) return 0;
    for (; *s; s++)
        if (!is_name_char(*s)) return 0;
    return 1;
}

/* One ordinary line: inline slots, and a block slot when it ends the line.
 * A line of a section that is off is checked all the same (output NULL):
 * the contract must not depend on the flags of one rendering. */
static int render_line(vigen_strbuf *out, render_ctx *R, long lineno, const char *line, size_t len, int newline)
{
    size_t i = 0, start = 0;
    while (i < len) {
        if (line[i] != '@') { i++; continue; }
        int block = i + 1 < len && line[i + 1] == '@';
        size_t n0 = i + (block ? 2 : 1), j = n0;
        while (j < len && is_name_char(line[j])) j++;
        char name[64];
        size_t k = j - n0 < sizeof name - 1 ? j - n0 : sizeof name - 1;
        memcpy(name, line + n0, k);
        name[k] = 0;
        int closed = j < len && line[j] == '@' && (!block || (j + 1 < len && line[j + 1] == '@'));
        if (!closed || k == 0 || !is_name_start(name[0])) {
            char *shown = vigen_strdup_printf("%.*s", (int)((j < len ? j + 1 : len) - i), line + i);
            fail(R, lineno, "malformed mark '%s' (slots are @NAME@ or a line ending in @@NAME@@, NAME in [A-Z][A-Z0-9_]*)",
                 shown);
            free(shown);
            return VIGEN_E_TEMPLATE;
        }
        const vigen_slot *v;
        if (block) {
            if (j + 2 != len)
                return fail(R, lineno, "block slot @@%s@@ must end its line", name);
            if (lookup(&v, R, lineno, name, VIGEN_SLOT_LINES) != VIGEN_OK) return VIGEN_E_TEMPLATE;
            for (size_t l = 0; out && l < v->nlines; l++) {
                vigen_strbuf_appendn(out, line, i);
                vigen_strbuf_append(out, v->lines[l]);
                vigen_strbuf_append(out, "\n");
            }
            return VIGEN_OK;
        }
        if (lookup(&v, R, lineno, name, VIGEN_SLOT_TEXT) != VIGEN_OK) return VIGEN_E_TEMPLATE;
        if (out) {
            vigen_strbuf_appendn(out, line + start, i - start);
            vigen_strbuf_append(out, v->text);
        }
        i = start = j + 1;
    }
    if (out == NULL) return VIGEN_OK;
    vigen_strbuf_appendn(out, line + start, len - start);
    if (newline) vigen_strbuf_append(out, "\n");
    return VIGEN_OK;
}

static int render_text(char **out, const char *text, const char *file, const char *dir, int includes,
                       const vigen_slots *slots, unsigned char *declared, vigen_error *err)
{
    *out = NULL;
    render_ctx R = { file, dir, includes, slots, NULL, NULL, 0, err };
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "");
    const char *p;
    long lineno;
    int rc = read_declaration(&R, text, &p, &lineno);
    /* sections: a stack of (active, seen else, line) */
    enum { MAXDEPTH = 32 };
    int active[MAXDEPTH + 1], had_else[MAXDEPTH + 1];
    long opened[MAXDEPTH + 1];
    int depth = 0;
    active[0] = 1;
    while (rc == VIGEN_OK && *p) {
        lineno++;
        const char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t)(nl - p) : strlen(p);
        char name[64];
        int negate = 0;
        const char *inc;
        size_t ninc;
        int mark = section_mark(p, len, name, sizeof name, &negate);
        if (mark == 0 && include_mark(p, len, &inc, &ninc)) {
            rc = render_include(active[depth] ? &sb : NULL, &R, lineno, inc, ninc, declared);
        } else if (mark == 1) {
            const vigen_slot *v;
            if (!valid_name(name)) rc = fail(&R, lineno, "malformed mark '@if %s@' (a flag name in [A-Z][A-Z0-9_]*)", name);
            else if (depth == MAXDEPTH) rc = fail(&R, lineno, "sections nested deeper than %s", "32");
            else if (lookup(&v, &R, lineno, name, VIGEN_SLOT_FLAG) == VIGEN_OK) {
                depth++;
                active[depth] = active[depth - 1] && (v->on != negate);
                had_else[depth] = 0;
                opened[depth] = lineno;
            } else rc = VIGEN_E_TEMPLATE;
        } else if (mark == 2) {
            if (depth == 0 || had_else[depth]) rc = fail(&R, lineno, "malformed mark '%s' (no open @if)", "@else@");
            else {
                had_else[depth] = 1;
                active[depth] = active[depth - 1] && !active[depth];
            }
        } else if (mark == 3) {
            if (depth == 0) rc = fail(&R, lineno, "malformed mark '%s' (no open @if)", "@end@");
            else depth--;
        } else {
            rc = render_line(active[depth] ? &sb : NULL, &R, lineno, p, len, nl != NULL);
        }
        if (nl == NULL) break;
        p = nl + 1;
    }
    if (rc == VIGEN_OK && depth > 0) {
        char num[32];
        snprintf(num, sizeof num, "%ld", opened[depth]);
        rc = fail(&R, lineno, "malformed mark: the @if of line %s has no @end@", num);
    }
    /* every declared slot must exist: a declaration the emitter cannot fill
     * is as wrong as a mark it cannot fill */
    for (size_t d = 0; d < R.ndeclared && rc == VIGEN_OK; d++)
        if (vigen_slots_find(slots, R.declared[d]) == NULL)
            rc = fail(&R, 1, "slot %s is declared but unknown: the emitter supplies no such slot", R.declared[d]);
    /* and the declaration lists what the template uses, nothing more */
    for (size_t d = 0; d < R.ndeclared && rc == VIGEN_OK; d++)
        if (R.decl_used[d] == 0) rc = fail(&R, 1, "slot %s is declared but never used", R.declared[d]);
    for (size_t k = 0; declared && rc == VIGEN_OK && k < slots->n; k++)
        for (size_t d = 0; d < R.ndeclared; d++)
            if (strcmp(slots->v[k]->name, R.declared[d]) == 0) declared[k] = 1;
    for (size_t d = 0; d < R.ndeclared; d++) free(R.declared[d]);
    free(R.declared);
    free(R.decl_used);
    if (rc != VIGEN_OK) { vigen_strbuf_clear(&sb); return rc; }
    *out = sb.data;
    return VIGEN_OK;
}

int vigen_template_render(char **out, const char *text, const char *file, const vigen_slots *slots,
                          unsigned char *declared, vigen_error *err)
{
    return render_text(out, text, file, NULL, 0, slots, declared, err);
}

/* A template that cannot be read is a broken installation, whatever the
 * input: hence VIGEN_E_TEMPLATE (exit status 3), not an input error. */
static int render_path(char **out, const char *path, int depth, const vigen_slots *slots, unsigned char *declared,
                       vigen_error *err)
{
    *out = NULL;
    char *text = NULL;
    size_t len;
    int rc = vigen_read_file(&text, &len, path, (size_t)1 << 20, err);
    if (rc == VIGEN_E_IO || rc == VIGEN_E_LIMIT) {
        char *why = vigen_strdup(err->message ? err->message : path);
        vigen_error_set(err, VIGEN_E_TEMPLATE,
                        "template %s; vigen's templates are missing or damaged: reinstall vigen, or set "
                        "VIGEN_TEMPLATE_DIR to a copy of its templates/ directory", why);
        free(why);
        return VIGEN_E_TEMPLATE;
    }
    if (rc != VIGEN_OK) return rc;
    const char *slash = strrchr(path, '/');
    char *dir = slash ? vigen_strdup_printf("%.*s", (int)(slash - path), path) : vigen_strdup(".");
    rc = render_text(out, text, path, dir, depth, slots, declared, err);
    free(dir);
    free(text);
    return rc;
}

int vigen_template_render_file(char **out, const char *path, const vigen_slots *slots, unsigned char *declared,
                               vigen_error *err)
{
    return render_path(out, path, 0, slots, declared, err);
}

/* ------------------------------------------------------- template lookup */

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

#if defined(__linux__)
/* The directory of the running executable (heap string), or NULL. */
static char *exe_dir(void)
{
    size_t cap = 256;
    for (;;) {
        char *buf = malloc(cap);
        if (buf == NULL) return NULL;
        ssize_t n = readlink("/proc/self/exe", buf, cap);
        if (n < 0) { free(buf); return NULL; }
        if ((size_t)n < cap) {
            buf[n] = '\0';
            char *slash = strrchr(buf, '/');
            if (slash == NULL) { free(buf); return NULL; }
            if (slash == buf) slash[1] = '\0';
            else *slash = '\0';
            return buf;
        }
        free(buf);
        cap *= 2;
    }
}

static int same_dir(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/* Whether directory dir (an absolute path) is top or lies below it. */
static int within_dir(const char *dir, const char *top)
{
    char *d = vigen_strdup(dir);
    int found = 0;
    for (;;) {
        if (same_dir(d, top)) { found = 1; break; }
        char *slash = strrchr(d, '/');
        if (slash == NULL || slash == d) break;
        *slash = '\0';
    }
    free(d);
    return found;
}
#endif

/* The tests built in the build directory must never read an installed copy,
 * and a relocated install prefix must still find its own templates: hence
 * the executable's location decides before the configured prefix. */
char *vigen_template_dir(const char *variant)
{
    const char *env = getenv("VIGEN_TEMPLATE_DIR");
    if (env && *env) return vigen_strdup_printf("%s/%s", env, variant);
#if defined(__linux__) && defined(VIGEN_TEMPLATE_INSTALL_RELDIR)
    char *exe = exe_dir();
    int in_build_tree = 0;
#if defined(VIGEN_BINARY_DIR)
    in_build_tree = exe != NULL && within_dir(exe, VIGEN_BINARY_DIR);
#endif
    if (exe != NULL && !in_build_tree) {
        char *dir = vigen_strdup_printf("%s/%s/%s", exe, VIGEN_TEMPLATE_INSTALL_RELDIR, variant);
        if (is_dir(dir)) { free(exe); return dir; }
        free(dir);
    }
    free(exe);
#if defined(VIGEN_TEMPLATE_INSTALL_DIR)
    if (!in_build_tree) {
        char *dir = vigen_strdup_printf("%s/%s", VIGEN_TEMPLATE_INSTALL_DIR, variant);
        if (is_dir(dir)) return dir;
        free(dir);
    }
#endif
#endif
#if defined(VIGEN_SOURCE_DIR)
    return vigen_strdup_printf("%s/%s", VIGEN_SOURCE_DIR "/templates", variant);
#else
    return vigen_strdup_printf("templates/%s", variant);
#endif
}
