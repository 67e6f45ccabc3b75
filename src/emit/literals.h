/* literals.h — the coefficients of a tableau as correctly rounded C
 * literals: the evaluation context shared by the emitter's passes, entry
 * references and labels, the rounding itself, and the messages about entries
 * that cannot be rounded. */
#ifndef VIGEN_EMIT_LITERALS_H
#define VIGEN_EMIT_LITERALS_H

#include <arb.h>
#include <arb_mat.h>
#include "vigen/emit.h"

/* The entries of the tableau in file order: c, A, b, At, bt.  A coefficient
 * is either one of them (a reference, "ref", into this flat numbering) or
 * derived from several (ref = -1: merged sums, 1/(c_j - c_m)). */
enum { PART_C, PART_A, PART_B, PART_AT, PART_BT };

/* marks[ref] of the current pass */
enum { MARK_INEXACT = 1, MARK_ZERO = 2 };

/* One rendering: the tableau evaluated at prec bits, rounded to bits. */
typedef struct {
    const vigen_tableau *t;
    slong s, prec, bits;
    int real, allow_inexact, inexact_done;
    const char *variant;          /* the variant's name when it is not the default (the header
                                     records it), else NULL */
    arb_ptr c, b, bt;
    arb_mat_t A, At;
    char **At_text, **bt_text;    /* At = A and bt = b when absent */
    unsigned char *marks;         /* per entry, reset at every pass */
    slong inexact_derived;        /* derived coefficients rounded from midpoints */
    int fail_kind;                /* 1: ball straddles a rounding boundary, 2: contains zero */
    slong fail_ref;
    char fail_label[64];
    vigen_error *err;
} emit_ctx;

/* The target types, in VIGEN_REAL_* order: the one list of them. */
typedef struct {
    const char *name;   /* as --real takes it and the messages say it */
    const char *ctype;  /* the C type of the emitted code */
    const char *suffix; /* of the runtime's names for the type */
    slong bits;         /* significand bits */
} vigen_emit_real_type;
enum { VIGEN_EMIT_NREALS = 3 };
extern const vigen_emit_real_type vigen_emit_reals[VIGEN_EMIT_NREALS];

slong vigen_emit_n_entries(slong s);
/* The reference of entry (i, j) of a part (j ignored for vectors); At and bt
 * are A and b when the file leaves them out. */
slong vigen_emit_entry_ref(const emit_ctx *E, int part, slong i, slong j);
/* Label ("A[2][1]"), text in the file and current ball of an entry. */
void vigen_emit_entry_describe(const emit_ctx *E, slong ref, char *label, size_t n, const char **text,
                               arb_srcptr *value);
/* A ball around zero small enough to be taken as an exact zero. */
int vigen_emit_tiny_zero(const emit_ctx *E, const arb_t x);
/* Formats x correctly rounded to the target type as a C literal in *out, or
 * NULL for an exact zero.  ref names the entry x is (or -1 for a derived
 * coefficient, then described by label).  Returns VIGEN_E_PRECISION when the
 * ball straddles a rounding boundary (the caller retries at a higher
 * precision).  Exact zeros taken from tiny balls and entries rounded as
 * written (--allow-inexact) are marked, not reported: vigen_emit_report_marks
 * reports them once, after the last pass. */
int vigen_emit_literal(char **out, emit_ctx *E, const arb_t x, slong ref, const char *label);
/* Evaluates every entry at E->prec bits. */
int vigen_emit_evaluate(emit_ctx *E, vigen_error *err);
/* Replaces the error of an entry that more working precision could not
 * round by one that says what to do about it (VIGEN_E_INEXACT). */
void vigen_emit_precision_message(emit_ctx *E, const vigen_emit_options *opt, vigen_error *err);
/* The warnings of the last pass: exact zeros taken from tiny balls, one per
 * entry, and one summary of the entries rounded as written. */
void vigen_emit_report_marks(emit_ctx *E, const vigen_emit_options *opt);

#endif
