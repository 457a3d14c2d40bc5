#include "rl_cli.h"

#include <errno.h>
#include <fcntl.h>
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
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE || v < -2147483647L || v > 2147483647L) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: '%s' is not an integer", opt, s);
        return 0;
    }
    if (v < lo || v > hi) {
        rl_cli_fail(cmd, RL_EXIT_USAGE, "%s: %s is out of range (%ld .. %ld)", opt, s, lo, hi);
        return 0;
    }
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
        return rl_cli_double(cmd, "--gamma", arg, 1.0, 3.0, &cfg->gamma) ? 1 : -1;
    case 's':
        if (!rl_cli_double(cmd, "--min-score", arg, 0.01, 1.0, &cfg->min_score))
            return -1;
        if (!(cfg->min_score > 0 && cfg->min_score <= 1))
            return rl_cli_fail(cmd, RL_EXIT_USAGE, "--min-score: %s is outside (0, 1]", arg), -1;
        return 1;
    }
    return 0;
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
