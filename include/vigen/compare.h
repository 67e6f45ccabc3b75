/* vigen/compare.h — `vigen compare FILE...`: the figures of the checker
 * (design order, principal error constant, linear stability interval, cost)
 * of several methods side by side, with the efficiency measure of the
 * splitting literature, E = (evaluations per step) * C^(1/p), the cost of a
 * step scaled by the error constant C of order p so that methods of one order
 * with different numbers of stages compare at equal work (Blanes & Moan,
 * J. Comput. Appl. Math. 142 (2002); docs/analysis.md). */
#ifndef VIGEN_COMPARE_H
#define VIGEN_COMPARE_H

#include <stddef.h>
#include <stdio.h>
#include "vigen/check.h"
#include "vigen/error.h"

enum { VIGEN_COMPARE_TEXT = 0, VIGEN_COMPARE_LATEX = 1, VIGEN_COMPARE_JSON = 2 };

/* Checks each of the n files (tableau or spec files, loaded with opt->load)
 * under opt (max_order, prec, ...; path and json are ignored) and prints one
 * table to out in the format.  Every file is checked before anything is
 * printed: on an error nothing is printed, err names the file, and the
 * return is its code.  VIGEN_OK otherwise. */
int vigen_compare_run(const char *const *paths, size_t n, const vigen_check_options *opt, int format, FILE *out,
                      vigen_error *err);

#endif
