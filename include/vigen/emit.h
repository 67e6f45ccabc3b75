/* emit.h — `vigen emit`: compiles a tableau into a specialised C stepper.
 *
 *   vigen emit FILE --name NAME [--real double|long-double|float128] [-o DIR]
 *              [--variant NAME] [--dim N] [--batch] [--allow-inexact] [-q]
 *
 * writes DIR/NAME.h and DIR/NAME.c (DIR defaults to "."), rendered from
 * templates/<variant>/stepper.h.in and templates/<variant>/stepper.c.in
 * (the variant: "prk" unless chosen) and linked against the runtime library
 * (runtime/include/vigen/runtime.h).
 *
 * - FILE is a tableau file or a spec file (nodes and basis, as for vigen
 *   generate).  A spec is generated on the fly with vigen_emit_spec_digits
 *   certified digits (40 for double and long double, 60 for float128; twice
 *   as many, up to 960, in the rare case that a value lies that close to a
 *   rounding boundary), and the header says so.
 * - Coefficients are literals correctly rounded (to nearest, ties to even)
 *   from the certified balls to the target type: 53, 64 or 113 bits, printed
 *   as exact C hex-float literals.  When a ball straddles a rounding boundary
 *   the tableau is re-evaluated at higher precision; an entry given as a
 *   rounded decimal with too few digits is refused (VIGEN_E_INEXACT, with a
 *   message naming the entry and what to do: more digits, an exact entry, or
 *   --allow-inexact) unless --allow-inexact asks for the decimal as written to
 *   be rounded: then one warning lists how many entries were rounded so.  An
 *   entry that is a ball around zero of radius below 2^-(bits+20) is emitted
 *   as an exact zero with a warning (one per entry).
 * - A tableau without At is a classical RK method: At = A, bt = b.
 * - NAME becomes a C identifier: characters outside [A-Za-z0-9_] become '_',
 *   a leading digit or underscore gets the prefix "m_", C keywords get the
 *   suffix "_"; a warning tells when NAME changed.  The file names use the
 *   sanitised name, so NAME cannot point elsewhere.  Texts from the tableau
 *   file (name, source, description, entry texts) enter the output only inside
 *   comments or string literals and only as printable ASCII with comment and
 *   string terminators broken.
 * - Output is byte-identical for identical input: the header names the
 *   tableau, its digest, the generator version and the options; there is no
 *   timestamp and no path.  Digest: FNV-1a 64 of the canonical text
 *   "vigen-tableau-v1\n" + name + "\n" + s + "\n" then every entry text of c,
 *   A (row-major), b, At, ct, bt, one per line, "-" for an absent part.
 * - The tableau is audited (vigen_emit_audit below): a warning on stderr,
 *   not silenced by -q, when it is certainly not consistent or not
 *   symplectic; the files are still written and the exit status is 0.
 * - Structure: the stage equations are solved by fixed-point iteration or
 *   simplified Newton (runtime options).  When the tableau's dependency graph
 *   is acyclic for separable H (H = T(p) + V(t, q)), an explicit path is also
 *   emitted and used when sys->separable is set; when it is acyclic for any H
 *   only the explicit path is emitted.  Equal rows share stage values and
 *   gradients, zero coefficients are skipped, and the gradient at the end of
 *   a step is reused at the start of the next (first same as last) when the
 *   tableau has a zero row and a row equal to b.
 * - Mechanical problems (NAME_alloc_mechanical, H = 1/2 p^T M^-1 p + V with
 *   the force given) are stepped in Nystrom form: positions as the only
 *   stage unknowns, one force per stage and sweep, the row sums of A, A At,
 *   sum b and b^T At rounded from balls like the other coefficients; the
 *   explicit path calls the force in place of dH/dq (docs/emit.md).
 * - --dim N (opt->dim): a static dimension, see vigen_emit_options.dim.
 * - --batch (opt->batch): the batched stepper NAME_step_batch beside the
 *   scalar one (templates/prk/batch.h.in, batch.c.in; docs/ensembles.md).
 *
 * Variants: src/emit/variants.def lists the steppers the emitter can write,
 * chosen by name (vigen_emit_options.variant): "prk", the default, the
 * partitioned Runge-Kutta stepper above, for double, long double and
 * float128; and "split", a splitting stepper that calls the exact flows of
 * the parts of H back (NAME_alloc_split of a vigen_split_problem, the
 * substeps of the file in order, consecutive ones of a flow merged, time
 * carried by the first flow; docs/splitting.md), for splitting files and
 * compositions of them, the default for a file whose `flows` are named
 * (anything but drift and kick).  Each is a template directory
 * templates/<variant>/ (stepper.h.in, stepper.c.in: readable C with
 * @NAME@ and @@BLOCK@@ slots and @if FLAG@ sections, every slot declared in
 * the template's first comment) and a slot builder in C that computes every
 * slot from the tableau.  The PRK slots: NAME, UNAME, TABLEAU_NAME, REAL,
 * SFX, HAM, STEPPER_TYPE, STAGES, ORDER, COEF_HEAD, NARRAYS, NX, texts;
 * HEADER and COEF_LINES, comment lines; DOUBLE, LONG_DOUBLE, FLOAT128,
 * IMPLICIT, EXPLICIT, LAGRANGE, FSAL, HAS_UPDATE_Q,
 * HAS_UPDATE_P, flags; and the blocks of C lines of the stage loops, the
 * Newton matrix, the extrapolation and the explicit step.
 * docs/templates.md describes each slot and how to add a variant.
 */
#ifndef VIGEN_EMIT_H
#define VIGEN_EMIT_H

#include <stddef.h>
#include "vigen/error.h"
#include "vigen/tableau.h"

enum { VIGEN_REAL_DOUBLE, VIGEN_REAL_LONG_DOUBLE, VIGEN_REAL_FLOAT128 };

/* The largest static dimension vigen_emit_options.dim takes (the arrays of
 * such a workspace are inside it: about 30 + 6 s arrays of dim reals). */
#define VIGEN_EMIT_MAX_DIM 100000

typedef struct {
    const char *name;        /* requested NAME (sanitised by the emitter) */
    int real;                /* VIGEN_REAL_* */
    const char *input_label; /* how the input is named in the header and in warnings
                                (basename); a tableau made by the generator in this run
                                (generated_now) is said to come from the spec of that name */
    int allow_inexact;       /* round the midpoint of a ball that straddles a rounding
                                boundary (decimal entries with too few digits), with a
                                warning, instead of refusing */
    const char *template_dir;/* the folder holding templates/<variant>/; NULL: as the vigen
                                command finds it ($VIGEN_TEMPLATE_DIR, beside the executable,
                                the install prefix, the source tree).  A program linking
                                libvigen from a moved prefix passes the package's
                                vigen_TEMPLATE_DIR here */
    const char *variant;     /* the stepper to write, by its name in src/emit/variants.def (its
                                templates are templates/<variant>/); NULL: the first row,
                                "prk" */
    size_t dim;              /* static dimension: 0 (any dimension, chosen at alloc), or N
                                (`--dim N`): loops of the fixed length N, the arrays in the
                                workspace itself, and NAME_alloc / NAME_alloc_mechanical
                                refusing (NULL) a problem whose dim is not N; the header
                                defines NAME_DIM (upper case) as N, 0 when any */
    int batch;               /* `--batch`: also NAME_step_batch, W trajectories per call in
                                structure-of-arrays layout (double, explicit tableaux only;
                                docs/ensembles.md) */
} vigen_emit_options;

/* The target types by name, as `vigen emit --real` takes them:
 * vigen_emit_real_parse sets *real (VIGEN_REAL_*) from "double",
 * "long-double" or "float128" and returns VIGEN_OK, or VIGEN_E_USAGE (*real
 * untouched) for any other name; vigen_emit_real_name is the name of a type
 * (NULL out of range); vigen_emit_real_names lists them for a message:
 * "double, long-double or float128". */
int vigen_emit_real_parse(int *real, const char *name);
const char *vigen_emit_real_name(int real);
const char *vigen_emit_real_names(void);

/* Certified digits with which `vigen emit` generates a spec for a target
 * type (VIGEN_REAL_*): 40 for double and long double, 60 for float128.  The
 * emitter rounds the generated decimals, each a ball of relative radius at
 * most 5 * 10^-digits; a ball of width w straddles a boundary between two
 * neighbouring values of the target type (relative spacing 2^-52 .. 2^-53 for
 * double, 2^-63 .. 2^-64 for long double, 2^-112 .. 2^-113 for float128) with
 * probability about w over that spacing: 40 digits leave 10^-23 (double) and
 * 10^-20 (long double) per entry; 40 digits would leave 10^-5 for float128,
 * 60 leave 10^-25. */
slong vigen_emit_spec_digits(int real);

/* Renders the header and source for a loaded tableau (balls need not be
 * evaluated: the emitter evaluates at the precision it needs).  *h_text and
 * *c_text are heap strings; *ident receives the sanitised name.  Warnings
 * (vigen_warn, after success only): entries emitted as exact zeros, one per
 * entry, and with allow_inexact one summary of the entries rounded as
 * written.  VIGEN_E_USAGE: opt->variant names no variant (the message lists
 * the variants with their descriptions) or opt->real no type.
 * VIGEN_E_INEXACT: an entry cannot be rounded correctly; the message names it
 * (not the file: callers prefix the path) and says what to do.
 * VIGEN_E_TEMPLATE, a broken installation or variant: a template cannot be
 * read (the message names it and says to reinstall or set
 * VIGEN_TEMPLATE_DIR), or the variant's templates and its slots do not match
 * (the message names the template, line and slot; or the slot the builder
 * supplies that no template of the variant declares, and the variant). */
int vigen_emit_render(const vigen_tableau *t, const vigen_emit_options *opt, char **h_text, char **c_text,
                      char **ident, vigen_error *err);

/* Sanitises a requested name into a C identifier (heap string). */
char *vigen_emit_identifier(const char *name);

/* The audit `vigen emit` runs on every tableau it compiles: vigen_check_tableau
 * on the row sums (c_i = sum_j a_ij, ct_i = sum_j at_ij, sum b = 1, sum bt = 1)
 * and symplecticity (b_i at_ij + b_j a_ji = b_i b_j, bt = b), the order
 * conditions left out.  Each certain failure is one vigen_warn (not
 * consistent; not symplectic, or symplectic only for separable H when just
 * bt != b spoils it), followed by the checker's single-entry diagnosis when it
 * has one and a line pointing to `vigen check PATH`; *warnings counts the
 * failures (0: nothing certainly wrong; conditions that hold only within the
 * precision of rounded data, or are undecided, never warn).  t is evaluated
 * in place (its texts are kept; its claims are set aside for the audit and
 * restored).  path names the file in the messages (NULL: the tableau name).
 * Returns VIGEN_OK, or the checker's error when t cannot be evaluated. */
int vigen_emit_audit(vigen_tableau *t, const char *path, int *warnings, vigen_error *err);

/* The variant vigen_emit_render writes for t when asked for `variant`
 * (NULL: the default): variant itself, else "split" for a splitting whose
 * flows are named (anything but drift and kick), else "prk". */
const char *vigen_emit_variant_chosen(const vigen_tableau *t, const char *variant);

/* The order NAME_ORDER and the stepper type's order field carry: the order
 * the checker certifies for general H (a claim of the file that holds, the
 * enumerated order conditions, Butcher's theorem beyond them), -1 when it is
 * not decided. */
int vigen_emit_certified_order(const vigen_tableau *t);
/* The same for a family of problems (VIGEN_CHECK_GENERAL, VIGEN_CHECK_SEPARABLE,
 * ... of vigen/check.h): the split variant's order with exact flows is the
 * order for H = T(p) + V(q). */
int vigen_emit_certified_order_family(const vigen_tableau *t, int family);

/* Loads FILE for emission, once (vigen_method_load), and asks it for the
 * tableau (vigen_method_tableau): a tableau file as it is; a spec generated with
 * vigen_emit_spec_digits(real) digits, doubled (up to 960) while the emitter
 * still finds a value it cannot round, with allow_inexact honoured only at
 * the last attempt.  Renders into *h, *c, *ident.  On success t holds the
 * tableau and *loaded is 1; on failure t is cleared and *loaded is 0.
 * Messages are complete for the caller to print as they are: an error about
 * the tableau names FILE (loading and generating name it themselves; a
 * rendering error gets "FILE: " in front), while an unknown variant or type
 * and a template error (VIGEN_E_TEMPLATE) are not about FILE and do not name
 * it.  VIGEN_E_INEXACT: an entry cannot be rounded (the data are too short). */
int vigen_emit_load_render(vigen_tableau *t, int *loaded, const char *file, vigen_emit_options *opt, char **h,
                           char **c, char **ident, vigen_error *err);

#endif
