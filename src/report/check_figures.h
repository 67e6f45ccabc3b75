/* check_figures.h — the design family of a checked method and the names of
 * the error-constant families, for the reports of `vigen check` and
 * `vigen compare`.  Not installed. */
#ifndef VIGEN_REPORT_CHECK_FIGURES_H
#define VIGEN_REPORT_CHECK_FIGURES_H

#include <stdio.h>
#include "vigen/check.h"

/* The family whose order is the method's design order (VIGEN_CHECK_EC_*):
 * the separable or Nystrom family whose order is the highest when it is above
 * the general order; else separable H for a method explicit for separable H
 * only (a splitting method); else general H. */
int vigen_report_design_family(const vigen_check_report *rep);

/* The family (VIGEN_CHECK_EC_SEPARABLE or _NYSTROM) with the highest decided
 * order when it is above the general order; -1 otherwise. */
int vigen_report_higher_family(const vigen_check_report *rep);

/* The families of the error constants (VIGEN_CHECK_EC_*): "general H", ... in
 * the text report, "general", ... as JSON keys. */
extern const char *const vigen_report_ec_title[VIGEN_CHECK_EC_FAMILIES];
extern const char *const vigen_report_ec_key[VIGEN_CHECK_EC_FAMILIES];

#endif
