/* fuzz_tableau.c — libFuzzer harness for the tableau loader: the input is
 * run as a tableau file in a sandbox with the method vocabulary and small
 * caps, the table it returns is read by the tableau reader
 * (src/method/tableau_file.h), and a tableau read is evaluated at a modest
 * precision (vigen_tableau_evaluate), written back as a tableau file and
 * that text read again. */
#include "method/tableau_file.h"
#include "method/vocabulary.h"
#include "vigen/tableau.h"
#include "fuzz_common.h"

enum { PREC = 128 };

static int load(vigen_tableau *t, const char *text, vigen_error *err)
{
    vigen_sandbox_limits limits = {.memory_limit = 8u << 20, .instruction_limit = 200000};
    vigen_sandbox *sb = NULL;
    int rc = vigen_sandbox_new(&sb, &limits, vigen_vocabulary_open, err);
    FUZZ_ASSERT(rc == VIGEN_OK);
    rc = vigen_sandbox_run_string(sb, text, "@fuzz.lua", err);
    if (rc == VIGEN_OK) rc = vigen_tableau_from_table(t, sb, "fuzz.lua", err);
    FUZZ_ASSERT(rc == VIGEN_OK || err->message != NULL);
    vigen_sandbox_free(sb);
    return rc;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_quiet();
    char *text = fuzz_cstring(data, size);
    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau t;
    if (load(&t, text, &err) == VIGEN_OK) {
        int rc = vigen_tableau_evaluate(&t, PREC, &err);
        FUZZ_ASSERT(rc == VIGEN_OK || err.message != NULL);
        vigen_error_clear(&err);
        /* what vigen writes, it reads back */
        char *lua = vigen_tableau_to_lua(&t);
        vigen_tableau back;
        FUZZ_ASSERT(lua != NULL);
        rc = load(&back, lua, &err);
        FUZZ_ASSERT(rc == VIGEN_OK || rc == VIGEN_E_LIMIT);
        if (rc == VIGEN_OK) {
            FUZZ_ASSERT(back.s == t.s);
            vigen_tableau_clear(&back);
        }
        vigen_error_clear(&err);
        free(lua);
        vigen_tableau_clear(&t);
    }
    vigen_error_clear(&err);
    free(text);
    return 0;
}
