/* check_fields.h — the vocabulary of the rows of vigen/check_fields.def (the
 * conditions and values they are written with), for the two printers that
 * expand them, check_text.c and check_json.c.  Not installed. */
#ifndef VIGEN_REPORT_CHECK_FIELDS_H
#define VIGEN_REPORT_CHECK_FIELDS_H

#include "vigen/check.h"

/* every entry is a + b sqrt(d) for one d (and not all rational) */
#define QUADRATIC(rep) ((rep)->quadratic_d && !(rep)->rational_denominator)
/* holds on exact entries are proofs: rational and real quadratic tableaux */
#define PROVED(rep) ((rep)->rational_denominator || (rep)->quadratic_d)
/* the level of a family of trees: LEVEL(rep, GENERAL), LEVEL(rep, SEPARABLE), ... */
#define LEVEL(rep, family) (&(rep)->orders[VIGEN_CHECK_##family].level)
/* the decision rule, stated once in the JSON object */
#define RULE_TEXT                                                                                                      \
    "a condition fails when its ball excludes 0 and holds when it contains 0: on rounded entries within the "         \
    "precision of the data, with a radius at most 2^-10 of its terms; on exact entries with a radius below "          \
    "2^-(prec/2) of its terms and the same verdicts at two precisions; otherwise it is undecided"

#endif
