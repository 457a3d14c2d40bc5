/* rl_cmd: the `ringloc` subcommands (host/cmd_*.c). argv[0] is the
 * subcommand's name; each returns the exit code (rl_cli.h).
 *
 *   int main(int argc, char **argv) { return rl_cmd_detect(argc - 1, argv + 1); }
 */
#ifndef RL_CMD_H
#define RL_CMD_H

#include <stddef.h>
#include "rl_recog.h"

int rl_cmd_gen(int argc, char **argv);
int rl_cmd_plan(int argc, char **argv);
int rl_cmd_detect(int argc, char **argv);
int rl_cmd_locate(int argc, char **argv);
int rl_cmd_calibrate_offsets(int argc, char **argv);
int rl_cmd_calibrate_mount(int argc, char **argv);
int rl_cmd_run(int argc, char **argv);
int rl_cmd_monitor(int argc, char **argv);
int rl_cmd_fuse(int argc, char **argv);
int rl_cmd_sitecheck(int argc, char **argv);
int rl_cmd_survey(int argc, char **argv);



#endif
