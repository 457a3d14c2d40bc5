/* rl_cli_num: the option values rl_cli.h does not parse: a long, an
 * unsigned long (a seed) and comma-separated lists of numbers
 * ("X,Y,YAW", "3,7,12"). Like rl_cli_int, each prints one usage error
 * naming the option and returns 0 when the value is not what it takes;
 * 1 and the value otherwise.
 *
 *   unsigned long seed;
 *   double pose[5];
 *   int n;
 *   if (!rl_cli_ulong("render", "--seed", "2026", 0, 4294967295ul, &seed) ||
 *       !rl_cli_doubles("render", "--mount", "0.12,-0.03,0.02", "X,Y,YAW", pose, 5, &n))
 *       use(2);                           // the error line is printed
 */
#ifndef RL_CLI_NUM_H
#define RL_CLI_NUM_H

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

#endif
