/* rl_odolog: see rl_odolog.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_infile.h"
#include "rl_odolog.h"

int rl_odolog_parse_line(char *line, rl_odosample *s)
{
    double v[4];
    char *p = line, *end;
    int i;
    char *hash = strchr(line, '#');
    if (hash)
        *hash = '\0';
    for (i = 0; i < 4; i++) {
        while (*p == ' ' || *p == '\t' || *p == ',')
            p++;
        if (*p == '\0' || *p == '\n' || *p == '\r')
            return i == 0 ? 0 : -1;
        v[i] = strtod(p, &end);
        if (end == p || !isfinite(v[i]))
            return -1;
        p = end;
    }
    while (*p == ' ' || *p == '\t' || *p == ',' || *p == '\r' || *p == '\n')
        p++;
    if (*p != '\0')
        return -1;
    s->t = v[0];
    s->x = v[1];
    s->y = v[2];
    s->yaw = v[3];
    return 1;
}

static rl_err fail(rl_odolog *log, FILE *f, rl_err e, char *err, size_t errlen, const char *path,
                   long line, const char *why)
{
    if (line > 0)
        snprintf(err, errlen, "%s:%ld: %s", path, line, why);
    else
        snprintf(err, errlen, "%s: %s", path, why);
    fclose(f);
    rl_odolog_free(log);
    return e;
}

rl_err rl_odolog_load(const char *path, rl_odolog *log, char *err, size_t errlen)
{
    char line[512], why[160];
    size_t cap = 0;
    long no = 0;
    rl_err e;
    FILE *f = rl_infile_fopen(path, "an odometry log", &e, err, errlen);
    memset(log, 0, sizeof *log);
    if (f == NULL)
        return e;
    while (fgets(line, sizeof line, f)) {
        rl_odosample s;
        int r;
        no++;
        if (strchr(line, '\n') == NULL && !feof(f))
            return fail(log, f, RL_EFORMAT, err, errlen, path, no, "line too long");
        r = rl_odolog_parse_line(line, &s);
        if (r < 0)
            return fail(log, f, RL_EFORMAT, err, errlen, path, no, "not 't x y yaw' (four numbers)");
        if (r == 0)
            continue;
        if (log->n > 0 && !(s.t > log->s[log->n - 1].t)) {
            snprintf(why, sizeof why, "time %.6g does not follow %.6g", s.t, log->s[log->n - 1].t);
            return fail(log, f, RL_EFORMAT, err, errlen, path, no, why);
        }
        if (log->n == cap) {
            size_t nc = cap ? 2 * cap : 1024;
            rl_odosample *ns = realloc(log->s, nc * sizeof *ns);
            if (ns == NULL)
                return fail(log, f, RL_ENOMEM, err, errlen, path, 0, "out of memory");
            log->s = ns;
            cap = nc;
        }
        log->s[log->n++] = s;
    }
    if (ferror(f))
        return fail(log, f, RL_EIO, err, errlen, path, 0, "read error");
    if (log->n == 0)
        return fail(log, f, RL_EFORMAT, err, errlen, path, 0, "no odometry samples");
    fclose(f);
    return RL_OK;
}

void rl_odolog_free(rl_odolog *log)
{
    free(log->s);
    log->s = NULL;
    log->n = 0;
}
