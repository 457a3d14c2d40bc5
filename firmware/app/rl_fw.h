/* rl_fw: the firmware's entry point: configuration, devices, the main
 * loop (rl_run.h) until a signal or the end of a PNG sequence. `ringloc-fw`
 * (what the robot's systemd unit runs) and `ringloc run` both call it.
 *
 *   #include "rl_cli.h"
 *   int main(int argc, char **argv)
 *   {
 *       rl_cli_set_program("ringloc-fw");
 *       return rl_fw_main(NULL, argc, argv);
 *   }
 */
#ifndef RL_FW_H
#define RL_FW_H

/* Run the firmware with command-line arguments argv[1..argc) (--config,
 * --frames, --help). cmd names it in messages (NULL for the program
 * alone: "ringloc-fw: ...", "run": "ringloc run: ..."). Returns the exit
 * code: 0, RL_EXIT_FAIL (configuration), RL_EXIT_USAGE (arguments). */
int rl_fw_main(const char *cmd, int argc, char **argv);

#endif
