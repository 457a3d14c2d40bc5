#include "rl_cli.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *program = "ringloc";

void rl_cli_set_program(const char *name)
{
    program = name;
}

void rl_cli_start(const char *name)
{
    int fd;
    rl_cli_set_program(name);
    /* a closed 0, 1 or 2 would be the next file opened (a recorded frame
     * would get the pose frames meant for standard output) */
    for (fd = 0; fd <= 2; fd++)
        if (fcntl(fd, F_GETFD) < 0 && errno == EBADF) {
            int n = open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
            if (n >= 0 && n != fd) /* a lower one was closed too: it is reopened first */
                close(n);
        }
    signal(SIGXFSZ, SIG_IGN); /* over a file-size limit: EFBIG, not a silent death */
}

int rl_cli_finish(const char *cmd, int code)
{
    int failed = ferror(stdout);
    errno = 0;
    if (fflush(stdout) != 0)
        failed = 1;
    if (fclose(stdout) != 0 && !failed)
        failed = 1;
    if (!failed)
        return code;
    rl_cli_fail(cmd, RL_EXIT_FAIL, "standard output: %s",
                errno ? strerror(errno) : "a write failed (the output is incomplete)");
    return code ? code : RL_EXIT_FAIL;
}

void rl_cli_prefix(const char *cmd, char *out, size_t len)
{
    if (cmd == NULL || cmd[0] == '\0')
        snprintf(out, len, "%s", program);
    else
        snprintf(out, len, "%s %s", program, cmd);
}

int rl_cli_fail(const char *cmd, int code, const char *fmt, ...)
{
    char prefix[128];
    va_list ap;
    rl_cli_prefix(cmd, prefix, sizeof prefix);
    fprintf(stderr, "%s: ", prefix);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return code;
}

int rl_cli_getopt(const char *cmd, int argc, char **argv, const struct option *opts)
{
    char prefix[128];
    int c, at;
    opterr = 0;
    c = getopt_long(argc, argv, ":h", opts, NULL);
    if (c != '?' && c != ':')
        return c;
    rl_cli_prefix(cmd, prefix, sizeof prefix);
    at = optind > 1 && optind <= argc ? optind - 1 : 0;
    if (c == ':')
        rl_cli_fail(cmd, RL_EXIT_USAGE, "option '%s' needs a value (see '%s --help')", argv[at], prefix);
    else if (optopt != 0)
        rl_cli_fail(cmd, RL_EXIT_USAGE, "unknown option '-%c' (see '%s --help')", optopt, prefix);
    else
        rl_cli_fail(cmd, RL_EXIT_USAGE, "unknown option '%s' (see '%s --help')", argv[at], prefix);
    return '?';
}

int rl_cli_double(const char *cmd, const char *opt, const char *s, double lo, double hi,
                  double *out)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || !isfinite(v)) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: '%s' is not a number", opt, s);
        return 0;
    }
    if (!(v >= lo && v <= hi)) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: %s is out of range (%g .. %g)", opt, s, lo, hi);
        return 0;
    }
    *out = v;
    return 1;
}

int rl_cli_int(const char *cmd, const char *opt, const char *s, long lo, long hi, int *out)
{
    long v;
    /* an int's range, whatever lo and hi say */
    if (!rl_cli_long(cmd, opt, s, lo > -2147483647L ? lo : -2147483647L, hi < 2147483647L ? hi : 2147483647L, &v))
        return 0;
    *out = (int)v;
    return 1;
}

int rl_cli_size(const char *cmd, const char *opt, const char *s, int max, int *w, int *h)
{
    char tail;
    long a, b;
    if (sscanf(s, "%ldx%ld%c", &a, &b, &tail) != 2 || a <= 0 || b <= 0) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: '%s' is not a size like 640x480", opt, s);
        return 0;
    }
    if (a > max || b > max) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: %s: each side at most %d", opt, s, max);
        return 0;
    }
    *w = (int)a;
    *h = (int)b;
    return 1;
}

int rl_cli_recog_option(const char *cmd, int c, const char *arg, rl_recog_config *cfg,
                        const char **family)
{
    switch (c) {
    case 'f': *family = arg; return 1;
    case 'L':
        if (strcmp(arg, "auto") == 0) cfg->local = RL_LOCAL_AUTO;
        else if (strcmp(arg, "always") == 0) cfg->local = RL_LOCAL_ALWAYS;
        else if (strcmp(arg, "never") == 0) cfg->local = RL_LOCAL_NEVER;
        else return rl_cli_fail(cmd, RL_EXIT_USAGE, "--local: '%s' is not auto, always or never", arg), -1;
        return 1;
    case 'Y': /* --gamma */
        if (strcmp(arg, "auto") == 0) {
            cfg->gamma = 0;
            return 1;
        }
        {
            char *end;
            double g = strtod(arg, &end);
            if (end == arg || *end != '\0' || !(g >= 1.0 && g <= 3.0))
                return rl_cli_fail(cmd, RL_EXIT_USAGE, "--gamma: '%s' is not auto or a number from 1 to 3", arg), -1;
            cfg->gamma = g;
        }
        return 1;
    case 's':
        if (!rl_cli_double(cmd, "--min-score", arg, 0.01, 1.0, &cfg->min_score))
            return -1;
        if (!(cfg->min_score > 0 && cfg->min_score <= 1))
            return rl_cli_fail(cmd, RL_EXIT_USAGE, "--min-score: %s is outside (0, 1]", arg), -1;
        return 1;
    }
    return 0;
}


int rl_cli_getopt_recog(const char *cmd, int argc, char **argv, const struct option *opts, rl_recog_config *cfg,
                        const char **family)
{
    int c, r;
    while ((c = rl_cli_getopt(cmd, argc, argv, opts)) != -1) {
        if ((r = rl_cli_recog_option(cmd, c, optarg, cfg, family)) < 0)
            return '?';
        if (r == 0)
            return c;
    }
    return -1;
}

void rl_cli_annotate_name(char *buf, size_t len, const char *out, const char *image, int several)
{
    const char *base = strrchr(image, '/'), *dot, *odot = strrchr(out, '.');
    int stem;
    if (!several) {
        snprintf(buf, len, "%s", out);
        return;
    }
    base = base ? base + 1 : image;
    dot = strrchr(base, '.');
    stem = dot ? (int)(dot - base) : (int)strlen(base);
    if (odot && !strchr(odot, '/'))
        snprintf(buf, len, "%.*s-%.*s%s", (int)(odot - out), out, stem, base, odot);
    else
        snprintf(buf, len, "%s-%.*s.png", out, stem, base);
}

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
/* One number of a comma-separated list at *s into out[i], *s past it and
 * its comma; 0 when there is none (or a trailing comma). */
typedef int (*list_item_fn)(const char **s, void *out, int i);

static int item_end(const char **s, char *end)
{
    if (end == *s || (*end != ',' && *end != '\0') || (*end == ',' && end[1] == '\0') || errno == ERANGE)
        return 0;
    *s = *end ? end + 1 : end;
    return 1;
}

static int next_double(const char **s, void *out, int i)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(*s, &end);
    if (!isfinite(v) || !item_end(s, end))
        return 0;
    ((double *)out)[i] = v;
    return 1;
}

static int next_int(const char **s, void *out, int i)
{
    char *end;
    long l;
    errno = 0;
    l = strtol(*s, &end, 10);
    if (l < INT_MIN || l > INT_MAX || !item_end(s, end))
        return 0;
    ((int *)out)[i] = (int)l;
    return 1;
}

static int parse_list(const char *cmd, const char *opt, const char *s, const char *form, list_item_fn next,
                      void *out, int max, int *n)
{
    const char *p = s;
    *n = 0;
    do {
        if (*n == max) {
            rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: more than %d values", opt, max);
            return 0;
        }
        if (!next(&p, out, *n)) {
            rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: '%s' is not %s", opt, s, form);
            return 0;
        }
        (*n)++;
    } while (*p != '\0');
    return 1;
}

int rl_cli_doubles(const char *cmd, const char *opt, const char *s, const char *form, double *out, int max,
                   int *n)
{
    return parse_list(cmd, opt, s, form, next_double, out, max, n);
}

int rl_cli_ints(const char *cmd, const char *opt, const char *s, const char *form, int *out, int max, int *n)
{
    return parse_list(cmd, opt, s, form, next_int, out, max, n);
}
