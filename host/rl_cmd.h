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
int rl_cmd_calibrate(int argc, char **argv);
int rl_cmd_mount(int argc, char **argv);
int rl_cmd_run(int argc, char **argv);
int rl_cmd_monitor(int argc, char **argv);
int rl_cmd_fuse(int argc, char **argv);
int rl_cmd_sitecheck(int argc, char **argv);
int rl_cmd_survey(int argc, char **argv);

/* The recognition options detect, locate and site-check share (--family
 * 'f', --local 'L', --min-score 's'): 1 if c was one of them (applied),
 * -1 after a usage error line, 0 if c is another option. */
int rl_cli_recog_option(const char *cmd, int c, const char *arg, rl_recog_config *cfg,
                        const char **family);

/* "out.png" for one image; "out-<stem of image>.png" for several. */
void rl_cli_annotate_name(char *buf, size_t len, const char *out, const char *image, int several);

#endif
