/* cli.h — the command handlers of the vigen command line. */
#ifndef VIGEN_CLI_H
#define VIGEN_CLI_H

#include "vigen/check.h"

int vigen_check_main(int argc, char **argv, vigen_check_loader_fn load);
int vigen_emit_main(int argc, char **argv);

#endif
