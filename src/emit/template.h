/* template.h — the template engine `vigen emit` renders C with, its slot
 * sets, and where the templates live.
 *
 * A template (templates/<variant>/<file>.in) is readable C with a few marks.
 * It opens with a comment declaring every slot it uses:
 *
 *     /+ vigen-template slots: NAME REAL STAGES SWEEP_EVALS EXPLICIT +/
 *
 * (with '*' for '+'; the comment may span lines and is not copied to the
 * output).  Slot names are [A-Z][A-Z0-9_]*.  The marks:
 *
 *   @NAME@          inline: replaced by the text of slot NAME.
 *   <prefix>@@NAME@@
 *                   a block, ending its line: replaced by the lines of slot
 *                   NAME, each preceded by <prefix> (the indentation, or a
 *                   comment's " * "); no lines, no output.
 *   @if NAME@, @if !NAME@, @else@, @end@
 *                   alone on a line (blanks around allowed): the lines up to
 *                   @else@ or @end@ are kept when flag NAME is on (off with
 *                   "!"); sections nest.
 *   @include FILE@  alone on a line (blanks around allowed): replaced by the
 *                   rendering of FILE, a template of its own (declaration
 *                   and contract) in the same folder as the including file,
 *                   with the same slots.  FILE is [A-Za-z0-9_][A-Za-z0-9_.-]*
 *                   (no "/", no leading "."), so that it cannot name a file
 *                   outside that folder; includes nest at most 8 deep.  Only
 *                   a template read from a file (vigen_template_render_file)
 *                   can include: in text rendered from memory the line is an
 *                   error.
 *
 * Every other character is copied as it is.  The contract is checked both
 * ways, on every line (those of sections that are off too): a mark naming a
 * slot that the declaration leaves out, a declared slot the emitter does not
 * supply or no mark uses, a slot used as the wrong kind and a malformed mark
 * are errors (VIGEN_E_TEMPLATE) naming the template file, the line and the
 * slot.  Rendering depends on the template and the slots only.
 */
#ifndef VIGEN_TEMPLATE_H
#define VIGEN_TEMPLATE_H

#include <stddef.h>
#include "vigen/error.h"

enum { VIGEN_SLOT_TEXT, VIGEN_SLOT_LINES, VIGEN_SLOT_FLAG };

typedef struct {
    char *name;
    int kind;        /* VIGEN_SLOT_* */
    char *text;      /* TEXT */
    char **lines;    /* LINES (without newlines) */
    size_t nlines, cap;
    int on;          /* FLAG */
} vigen_slot;

/* The values a slot builder supplies for one rendering (names unique: a later
 * definition of a name replaces the earlier one). */
typedef struct {
    vigen_slot **v;   /* each slot allocated on its own: a vigen_slot * stays valid */
    size_t n, cap;
} vigen_slots;

void vigen_slots_init(vigen_slots *s);
void vigen_slots_clear(vigen_slots *s);
void vigen_slots_text(vigen_slots *s, const char *name, const char *text);
void vigen_slots_textf(vigen_slots *s, const char *name, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
void vigen_slots_flag(vigen_slots *s, const char *name, int on);
/* A block slot with no lines yet; append with vigen_slot_line. */
vigen_slot *vigen_slots_lines(vigen_slots *s, const char *name);
void vigen_slot_line(vigen_slot *slot, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
const vigen_slot *vigen_slots_find(const vigen_slots *s, const char *name);

/* Renders template text (named `file` in messages) with the slots.  On
 * success *out is a heap string, and declared[k] is set to 1 for every slot
 * slots->v[k] the template declares (declared: NULL, or slots->n flags the
 * caller zeroes, so that one array can collect the declarations of a
 * variant's templates).  VIGEN_E_TEMPLATE: the template and the slots do not
 * match (the message names file:line and the slot). */
int vigen_template_render(char **out, const char *text, const char *file, const vigen_slots *slots,
                          unsigned char *declared, vigen_error *err);

/* Like vigen_template_render but reads the template from path, and resolves
 * its @include lines in path's folder.  A template (or included file) that
 * cannot be read is VIGEN_E_TEMPLATE too (a broken installation): the
 * message names the path and says to reinstall or set VIGEN_TEMPLATE_DIR;
 * the declarations of included files are collected in declared as well. */
int vigen_template_render_file(char **out, const char *path, const vigen_slots *slots, unsigned char *declared,
                               vigen_error *err);

/* The directory of a variant's templates (heap string): <root>/<variant>,
 * root being $VIGEN_TEMPLATE_DIR when set; else, for an installed vigen (an
 * executable outside its build directory), the templates installed with it,
 * found relative to the executable and then at the configured prefix; else
 * the source tree's templates/. */
char *vigen_template_dir(const char *variant);

#endif
