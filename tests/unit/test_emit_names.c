/* test_emit_names.c — the emitted symbol prefix against the keyword table:
 * every word of src/emit/c_keywords.def is changed by vigen_emit_identifier
 * (suffix "_"), a word that is not a keyword is kept, and the copy of the
 * list that cmake/VigenStepper.cmake checks NAME against (the installed
 * package has no sources) holds exactly the table's words, so that
 * vigen_add_stepper accepts exactly the names the emitter keeps. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "vigen/emit.h"


static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) return NULL;
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    return strdup(buf);
}

/* The words of the X(word) rows (after the header comment). */
static int table_words(char words[][32], int max)
{
    char *text = slurp("src/emit/c_keywords.def");
    CHECK(text != NULL);
    if (text == NULL) return 0;
    char *p = strstr(text, "*/");
    int n = 0;
    while (p && (p = strstr(p, "X(")) != NULL && n < max) {
        char *e = strchr(p, ')');
        if (e == NULL || e - p - 2 >= 32) break;
        memcpy(words[n], p + 2, (size_t)(e - p - 2));
        words[n++][e - p - 2] = 0;
        p = e;
    }
    free(text);
    return n;
}

int main(void)
{
    char words[128][32];
    int n = table_words(words, 128);
    CHECK(n >= 32);   /* C89 alone has 32 keywords */
    for (int k = 0; k < n; k++) {
        char *id = vigen_emit_identifier(words[k]);
        char want[40];
        snprintf(want, sizeof want, "%s_", words[k]);
        if (strcmp(id, want) != 0) {
            fprintf(stderr, "keyword %s became %s\n", words[k], id);
            testlib_failures++;
        }
        free(id);
    }
    char *id = vigen_emit_identifier("integrator");
    CHECK(strcmp(id, "integrator") == 0);
    free(id);

    char *cm = slurp("cmake/VigenStepper.cmake");
    CHECK(cm != NULL);
    if (cm) {
        char *p = strstr(cm, "set(keywords");
        char *e = p ? strchr(p, ')') : NULL;
        CHECK(p != NULL && e != NULL);
        if (p && e) {
            *e = 0;
            int count = 0;
            for (char *w = strtok(p + strlen("set(keywords"), " \n"); w; w = strtok(NULL, " \n")) {
                int found = 0;
                for (int k = 0; k < n; k++) found |= strcmp(w, words[k]) == 0;
                if (!found) { fprintf(stderr, "VigenStepper.cmake keyword %s is not in c_keywords.def\n", w); testlib_failures++; }
                count++;
            }
            if (count != n) {
                fprintf(stderr, "VigenStepper.cmake lists %d keywords, c_keywords.def %d\n", count, n);
                testlib_failures++;
            }
        }
        free(cm);
    }
    TEST_MAIN_END();
}
