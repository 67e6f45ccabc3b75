/* fuzz_spec.c — libFuzzer harness for the spec loader: the input is run as
 * a spec file in a sandbox with the method vocabulary and small caps (as
 * vigen_method_load runs a file, without the file), and the table it
 * returns is read by the spec reader (src/method/spec.h).  Specs with at most
 * three nodes are then generated at a few digits, so that the reader's
 * output reaches the Galerkin generator too. */
#include "method/galerkin.h"
#include "method/spec.h"
#include "method/vocabulary.h"
#include "vigen/tableau.h"
#include "fuzz_common.h"
#include "vigen/limits.h"

enum { FUZZ_SPEC_MAX_PREC = 2048 };

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_quiet();
    /* a small precision cap, like the small instruction and memory caps
     * below: an integrand that needs hundreds of digits to certify (a basis
     * function of super-exponential range) is refused at the cap within the
     * time of one execution; at the default cap such inputs take up to the
     * wall-clock cap (--max-seconds) and end with the cap's message */
    vigen_prec_limit_set(FUZZ_SPEC_MAX_PREC);
    char *text = fuzz_cstring(data, size);
    vigen_sandbox_limits limits = {.memory_limit = 8u << 20, .instruction_limit = 200000};
    vigen_error err;
    vigen_error_init(&err);
    vigen_sandbox *sb = NULL;
    int rc = vigen_sandbox_new(&sb, &limits, vigen_vocabulary_open, &err);
    FUZZ_ASSERT(rc == VIGEN_OK);
    rc = vigen_sandbox_run_string(sb, text, "@fuzz.lua", &err);
    if (rc != VIGEN_OK) {
        FUZZ_ASSERT(err.message != NULL);
        vigen_sandbox_free(sb);
    } else {
        vigen_spec *spec = NULL;
        rc = vigen_spec_from_table(&spec, sb, "fuzz.lua", &err);   /* takes sb */
        FUZZ_ASSERT(rc == VIGEN_OK ? spec != NULL : err.message != NULL);
        if (rc == VIGEN_OK && spec->s <= 3 && spec->basis_count <= 3) {
            vigen_error_clear(&err);
            vigen_tableau t;
            if (vigen_galerkin_generate(&t, spec, 8, &err) == VIGEN_OK) vigen_tableau_clear(&t);
            else FUZZ_ASSERT(err.message != NULL);
        }
        vigen_spec_free(spec);
    }
    vigen_error_clear(&err);
    free(text);
    return 0;
}
