/* method_tableau.h — the state of a method whose tableau is known as texts
 * once read (a tableau file, a splitting file): shared by the rows of
 * methods.def that hand out copies of one tableau. */
#ifndef VIGEN_METHOD_TABLEAU_H
#define VIGEN_METHOD_TABLEAU_H

#include "vigen/tableau.h"

/* *state takes t (texts and metadata; t is emptied) for the row functions
 * vigen_method_tableau_tableau and vigen_method_tableau_release. */
int vigen_method_tableau_adopt(void **state, vigen_tableau *t, const char *path, vigen_error *err);

/* The precision at which a tableau of s stages is evaluated for digits. */
slong vigen_method_tableau_prec(slong digits, slong s);

#endif
