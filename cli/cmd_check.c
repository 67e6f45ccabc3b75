/* cmd_check.c — `vigen check`: parses the options, runs the checker, prints. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/check.h"
#include "cli.h"

static const char *vigen_check_usage =
    "usage: vigen check FILE [--against FILE2] [--max-order P] [--json] [--prec BITS]\n"
    "\n"
    "Certifies, in ball arithmetic, what the tableau in FILE (a tableau file or a spec\n"
    "file) is: row sums, symplecticity (every failing pair named), order (every\n"
    "bicoloured-tree condition up to P), order for separable H and of each part alone,\n"
    "simplifying assumptions B, C, D, the claims stated in the file (order = p: the\n"
    "order is exactly p; symplectic = ...), and with --against every entry that differs\n"
    "from FILE2 beyond the certified precision.\n"
    "\n"
    "A condition fails when its ball excludes 0 and holds when its ball contains 0:\n"
    "  - rounded decimal entries (\"0.2113\") stand for balls of half a unit in their last\n"
    "    digit; a condition on them holds within the precision of the data when its ball\n"
    "    contains 0 with a radius at most 2^-10 of its terms (the report shows the largest\n"
    "    such radius); a wider ball is undecided: the data are too short to decide;\n"
    "  - on exact expressions (\"1/4 - sqrt(3)/6\") a condition holds only when its ball\n"
    "    is tighter than 2^-(prec/2) of the size of its terms, with the same verdicts at\n"
    "    two successive precisions, the second of at least 1024 bits; the precision is\n"
    "    doubled until that is so (up to 4096 bits, or twice the start);\n"
    "  - when every entry is rational, or every entry is a + b sqrt(d) with rational a, b\n"
    "    and one d, holds are proofs instead: with D the common denominator, a condition\n"
    "    v of k entries per term and constant denominator g holds when |v| D^k g < 1, or\n"
    "    |v| |v'| (D^k g)^2 < 1 with v' the condition on the conjugate tableau\n"
    "    (sqrt(d) -> -sqrt(d)); no second precision is then needed;\n"
    "  - anything else is reported undecided.\n"
    "Verdicts that rest on holds within the precision of the data say so (JSON status\n"
    "\"within_data\"); short decimals among long ones (\"0.5\" among 16-digit entries) are\n"
    "named with the fraction to write if they are exact (\"1/2\").\n"
    "The starting precision covers the digits of every decimal and exact literal\n"
    "(10^-45 included) plus 64 bits, at least 128.\n"
    "\n"
    "  --against FILE2  compare every entry with FILE2\n"
    "  --max-order P    check orders 1..P (default 8, at most 12; raised to the claimed\n"
    "                   order + 1 so that a claim order = p can be confirmed)\n"
    "  --json           print one JSON object\n"
    "  --prec BITS      starting working precision (default: adequate to the entries)\n"
    "\n"
    "Exit status: 0 consistent and every stated claim holds (within the precision of\n"
    "the data counts; the report says so) and no entry differs from FILE2, 1 something\n"
    "fails or cannot be decided, 2 unreadable input or usage error.\n";

int vigen_check_main(int argc, char **argv, vigen_check_loader_fn load)
{
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.load = load;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) { fputs(vigen_check_usage, stdout); return 0; }
        if (strcmp(a, "--json") == 0) opt.json = 1;
        else if (strcmp(a, "--against") == 0 && i + 1 < argc) opt.against = argv[++i];
        else if ((strcmp(a, "--max-order") == 0 || strcmp(a, "--prec") == 0) && i + 1 < argc) {
            const char *v = argv[++i];
            char *end = NULL;
            long n = strtol(v, &end, 10);
            int is_order = strcmp(a, "--max-order") == 0;
            long lo = is_order ? 1 : 16, hi = is_order ? VIGEN_TREE_MAX_ORDER : 1000000;
            if (end == v || *end != '\0' || n < lo || n > hi) {
                fprintf(stderr, "vigen check: %s takes a whole number from %ld to %ld, not '%s'\n", a, lo, hi, v);
                return 2;
            }
            if (is_order) opt.max_order = (int)n;
            else {
                opt.prec = n;
                if (opt.max_prec < n) opt.max_prec = n;
            }
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "vigen check: unknown or incomplete option '%s'\n\n%s", a, vigen_check_usage);
            return 2;
        } else if (opt.path == NULL) opt.path = a;
        else {
            fprintf(stderr, "vigen check: one file at a time (use --against FILE2 to compare)\n");
            return 2;
        }
    }
    if (opt.path == NULL) { fputs(vigen_check_usage, stderr); return 2; }
    vigen_error err;
    vigen_error_init(&err);
    int code = vigen_check_run(&opt, stdout, &err);
    if (err.code != VIGEN_OK) {
        fprintf(stderr, "vigen check: %s\n", err.message ? err.message : vigen_status_name(err.code));
        vigen_error_clear(&err);
    }
    return code;
}
