/* limits.h — the caps every Lua state of vigen runs under (spec files,
 * tableau files): memory and instructions.  Commands take them from
 * --max-memory and --max-instructions. */
#ifndef VIGEN_LIMITS_H
#define VIGEN_LIMITS_H

#include <stddef.h>

typedef struct {
    size_t memory_limit;      /* bytes; default 256 MiB (0: the default) */
    long instruction_limit;   /* VM instructions per top-level call; default 50 million (<= 0: the default) */
} vigen_sandbox_limits;

void vigen_sandbox_limits_default(vigen_sandbox_limits *limits);
/* Changes the process-wide defaults (fields <= 0 are left as they are). */
void vigen_sandbox_limits_set_default(const vigen_sandbox_limits *limits);

#endif
