/* rl_cli: what every `ringloc` subcommand shares: error lines, option
 * values, and the subcommand entry points.
 *
 * Exit codes: 0 success, 1 a run-time failure (file, device, data),
 * 2 a usage error. Every failure is one line on stderr that starts with
 * "ringloc <command>: " and names the file or option at fault.
 */
#ifndef RL_CLI_H
#define RL_CLI_H

#include <stddef.h>

#define RL_EXIT_FAIL 1
#define RL_EXIT_USAGE 2

/* Print "ringloc CMD: message" to stderr; returns `code`. */
int rl_cli_fail(const char *cmd, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Parse an option value; on failure print a usage error naming the option
 * and return 0. */
int rl_cli_double(const char *cmd, const char *opt, const char *s, double *out);
int rl_cli_int(const char *cmd, const char *opt, const char *s, int *out);
/* "640x480" -> 640, 480 */
int rl_cli_size(const char *cmd, const char *opt, const char *s, int *w, int *h);

/* Subcommands: argv[0] is the subcommand's name. */
int rl_cmd_gen(int argc, char **argv);
int rl_cmd_plan(int argc, char **argv);
int rl_cmd_detect(int argc, char **argv);
int rl_cmd_locate(int argc, char **argv);
int rl_cmd_calibrate(int argc, char **argv);
int rl_cmd_run(int argc, char **argv);
int rl_cmd_monitor(int argc, char **argv);

#endif
