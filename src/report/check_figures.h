/* check_figures.h — the figures of `vigen check` (error constants, stability
 * interval, cost) in the text and JSON reports.  Not installed. */
#ifndef VIGEN_REPORT_CHECK_FIGURES_H
#define VIGEN_REPORT_CHECK_FIGURES_H

#include <stdio.h>
#include "vigen/check.h"

/* The family whose order is the method's design order (VIGEN_CHECK_EC_*):
 * the separable or Nystrom family whose order is the highest when it is above
 * the general order; else separable H for a method explicit for separable H
 * only (a splitting method); else general H. */
int vigen_report_design_family(const vigen_check_report *rep);

void vigen_report_figures_text(FILE *out, const vigen_check_report *rep);
/* ",\n \"error_constant\": ..., \"stability_interval\": ..., ..." (no braces) */
void vigen_report_figures_json(FILE *out, const vigen_check_report *rep);

#endif
