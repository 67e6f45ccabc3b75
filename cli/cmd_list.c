/* cmd_list.c — `vigen list`: the methods known by name, with what the
 * checker certifies about each (vigen/library.h). */
#include "cli.h"
#include "vigen/library.h"

int vigen_cmd_list(const vigen_cli_args *args)
{
    vigen_error err;
    vigen_error_init(&err);
    if (vigen_library_list(stdout, args->value[VIGEN_OPT_list_json] != NULL, &err) != VIGEN_OK)
        return vigen_cli_fail(args->command, &err);
    return 0;
}
