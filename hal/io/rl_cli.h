/* rl_cli: what every command line shares (`ringloc` and its subcommands,
 * `ringloc-fw`, the tools): error lines, option values (numbers, sizes,
 * lists of numbers), the recognition options several commands share and
 * the names of annotated images.
 *
 * Exit codes: 0 success, 1 a run-time failure (file, device, data),
 * 2 a usage error. Every failure is one line on stderr that starts with
 * "ringloc <command>: " (or the program set by rl_cli_set_program) and
 * names the file or option at fault.
 *
 *   int frames;
 *   if (!rl_cli_int("run", "--frames", "12", 0, 1000000, &frames))
 *       use(RL_EXIT_USAGE);                // the error line is printed
 */
#ifndef RL_CLI_H
#define RL_CLI_H

#include <getopt.h>
#include <stddef.h>
#include "rl_recog.h"

#define RL_EXIT_FAIL 1
#define RL_EXIT_USAGE 2

/* The program named in error lines ("ringloc" until set). */
void rl_cli_set_program(const char *name);

/* First thing in every main: rl_cli_set_program(name), descriptors 0-2
 * opened on /dev/null where closed (no file opened later takes their
 * place), and SIGXFSZ ignored (a file-size limit is then an error, EFBIG,
 * reported like a full disk, instead of a silent death). */
void rl_cli_start(const char *name);

/* Last thing in every main that prints results: standard output flushed
 * and closed. If any write to it failed (a full disk, a closed pipe, a
 * file-size limit), one line "PROGRAM CMD: standard output: REASON" and
 * RL_EXIT_FAIL when code was 0; else code.
 *
 *   return rl_cli_finish("detect", code);  // code: the command's own exit status
 */
int rl_cli_finish(const char *cmd, int code);

/* "PROGRAM CMD" (or "PROGRAM" when cmd is NULL or empty) into out. */
void rl_cli_prefix(const char *cmd, char *out, size_t len);

/* Print "PROGRAM CMD: message" to stderr; returns `code`. */
int rl_cli_fail(const char *cmd, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* getopt_long for a command whose only short option is -h: an unknown
 * option or a missing value prints one usage error naming it and the
 * command's --help, and returns '?'. */
int rl_cli_getopt(const char *cmd, int argc, char **argv, const struct option *opts);

/* Parse an option value, a number within [lo, hi]; on failure print a
 * usage error naming the option (and the range) and return 0. */
int rl_cli_double(const char *cmd, const char *opt, const char *s, double lo, double hi,
                  double *out);
int rl_cli_int(const char *cmd, const char *opt, const char *s, long lo, long hi, int *out);
/* "640x480" -> 640, 480, each 1 .. max */
int rl_cli_size(const char *cmd, const char *opt, const char *s, int max, int *w, int *h);
/* A decimal integer within [lo, hi]. */
int rl_cli_long(const char *cmd, const char *opt, const char *s, long lo, long hi, long *out);

/* A non-negative decimal integer within [lo, hi]. */
int rl_cli_ulong(const char *cmd, const char *opt, const char *s, unsigned long lo, unsigned long hi,
                 unsigned long *out);

/* One to max finite numbers separated by commas into out[0 .. *n-1]; a
 * value that is not prints "OPT: 'S' is not FORM" (form: what the option
 * takes, "X,Y,YAW"); more than max prints "OPT: more than MAX values". */
int rl_cli_doubles(const char *cmd, const char *opt, const char *s, const char *form, double *out, int max,
                   int *n);

/* The same for integers (each within int's range). */
int rl_cli_ints(const char *cmd, const char *opt, const char *s, const char *form, int *out, int max, int *n);

/* The recognition options detect, locate and site-check share (--family
 * 'f', --local 'L', --min-score 's'): 1 if c was one of them (applied),
 * -1 after a usage error line, 0 if c is another option. */
int rl_cli_recog_option(const char *cmd, int c, const char *arg, rl_recog_config *cfg,
                        const char **family);

/* rl_cli_getopt that applies the recognition options itself
 * (rl_cli_recog_option): the next other option, -1 at the end, '?' after
 * a usage error line. */
int rl_cli_getopt_recog(const char *cmd, int argc, char **argv, const struct option *opts, rl_recog_config *cfg,
                        const char **family);

/* "out.png" for one image; "out-<stem of image>.png" for several. */
void rl_cli_annotate_name(char *buf, size_t len, const char *out, const char *image, int several);



#endif
