/* limits.h — the caps every Lua state of vigen runs under (spec files,
 * tableau files): memory and instructions.  Commands take them from
 * --max-memory and --max-instructions.  And the cap on the working
 * precision of every arb computation (--max-prec), and the largest number of
 * stages a file may ask for. */
#ifndef VIGEN_LIMITS_H
#define VIGEN_LIMITS_H

#include <stddef.h>
#include "vigen/error.h"

typedef struct {
    size_t memory_limit;      /* bytes; default 256 MiB (0: the default) */
    long instruction_limit;   /* VM instructions per top-level call; default 50 million (<= 0: the default) */
} vigen_sandbox_limits;

/* The process-wide defaults (256 MiB, 50 million instructions, unless
 * changed by vigen_sandbox_limits_set_default). */
void vigen_sandbox_limits_default(vigen_sandbox_limits *limits);
/* Changes the process-wide defaults (fields <= 0 are left as they are). */
void vigen_sandbox_limits_set_default(const vigen_sandbox_limits *limits);

/* The largest number of stages (nodes or basis functions of a spec) a file
 * may give, the bound node and basis families already had
 * (VIGEN_NODES_MAX_S): Theorem 3 and the checker's conditions cost O(s^3) to
 * O(s^4) ball operations per precision; 100,000 nodes made FLINT abort
 * allocating the s x s matrices. */
#define VIGEN_MAX_STAGES 256

/* The cap on the working precision, in bits, of every computation a file or
 * an option asks for (the precision implied by the digits of a literal,
 * --prec, --digits and the doubling loops of generate and check).  The
 * default, 2^19 bits (158,000 decimal digits), is 1.5 times what --digits
 * 100000 starts at (a polynomial basis of 2 or 3 stages is generated there in
 * about a second) and 128 times the checker's own refinement cap (4096 bits);
 * a check at 10^6 bits takes minutes (gauss_3: over 2 minutes, 290 MB), so
 * that a file or an option cannot make vigen run for hours or use gigabytes
 * through precision alone. */
#define VIGEN_MAX_PREC_DEFAULT 524288L

/* Numerical integration (basis functions without a closed-form integral)
 * costs about the cube of the precision: it runs at most at 1/16 of the cap,
 * 32768 bits (9,800 digits: about 70 s for one such function, exp(t^2)) by
 * default. */
#define VIGEN_QUADRATURE_PREC_SHARE 16

/* The cap in force (the process-wide default unless changed). */
long vigen_prec_limit(void);
/* Changes it (bits <= 0: back to VIGEN_MAX_PREC_DEFAULT). */
void vigen_prec_limit_set(long bits);
/* VIGEN_OK when prec is within the cap (what: "--prec asks for"); otherwise VIGEN_E_LIMIT with a
 * message "WHAT PREC bits of working precision, above the cap of CAP
 * bits (--max-prec BITS raises it)". */
int vigen_prec_limit_check(long prec, const char *what, vigen_error *err);

#endif
