/* rl_cli_num: longs, seeds and lists of numbers on a command line (rl_cli_num.h). */
#include "rl_cli_num.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include "rl_cli.h"

/* strtol without its leniencies: the whole string, no overflow. */
static int whole_long(const char *s, long *v)
{
    char *end;
    errno = 0;
    *v = strtol(s, &end, 10);
    return end != s && *end == '\0' && errno != ERANGE;
}

int rl_cli_long(const char *cmd, const char *opt, const char *s, long lo, long hi, long *out)
{
    long v;
    if (!whole_long(s, &v)) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: '%s' is not an integer", opt, s);
        return 0;
    }
    if (v < lo || v > hi) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: %s is out of range (%ld .. %ld)", opt, s, lo, hi);
        return 0;
    }
    *out = v;
    return 1;
}

int rl_cli_ulong(const char *cmd, const char *opt, const char *s, unsigned long lo, unsigned long hi,
                 unsigned long *out)
{
    char *end;
    unsigned long v;
    errno = 0;
    /* strtoul takes "-1" as ULONG_MAX: a sign is refused first */
    v = s[0] >= '0' && s[0] <= '9' ? strtoul(s, &end, 10) : 0;
    if (!(s[0] >= '0' && s[0] <= '9') || *end != '\0' || errno == ERANGE) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: '%s' is not a non-negative integer", opt, s);
        return 0;
    }
    if (v < lo || v > hi) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: %s is out of range (%lu .. %lu)", opt, s, lo, hi);
        return 0;
    }
    *out = v;
    return 1;
}

/* The next comma-separated number of *s into v, *s moved past it and its
 * comma; 0 when it is not one (an empty item, a trailing comma). */
static int next_double(const char **s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(*s, &end);
    if (end == *s || (*end != ',' && *end != '\0') || (*end == ',' && end[1] == '\0') || errno == ERANGE ||
        !isfinite(*v))
        return 0;
    *s = *end ? end + 1 : end;
    return 1;
}

static int next_int(const char **s, int *v)
{
    char *end;
    long l;
    errno = 0;
    l = strtol(*s, &end, 10);
    if (end == *s || (*end != ',' && *end != '\0') || (*end == ',' && end[1] == '\0') || errno == ERANGE ||
        l < INT_MIN || l > INT_MAX)
        return 0;
    *v = (int)l;
    *s = *end ? end + 1 : end;
    return 1;
}

int rl_cli_doubles(const char *cmd, const char *opt, const char *s, const char *form, double *out, int max,
                   int *n)
{
    const char *p = s;
    double v;
    *n = 0;
    do {
        if (!next_double(&p, &v)) {
            rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: '%s' is not %s", opt, s, form);
            return 0;
        }
        if (*n == max) {
            rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: more than %d values", opt, max);
            return 0;
        }
        out[(*n)++] = v;
    } while (*p != '\0');
    return 1;
}

int rl_cli_ints(const char *cmd, const char *opt, const char *s, const char *form, int *out, int max, int *n)
{
    const char *p = s;
    int v;
    *n = 0;
    do {
        if (!next_int(&p, &v)) {
            rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: '%s' is not %s", opt, s, form);
            return 0;
        }
        if (*n == max) {
            rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: more than %d values", opt, max);
            return 0;
        }
        out[(*n)++] = v;
    } while (*p != '\0');
    return 1;
}
