/* sim_report: see sim_report.h. */
#include "sim_report.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

void sim_report_defaults(sim_run *r)
{
    memset(r, 0, sizeof *r);
    r->cut_at = r->push_at = -1;
    r->cut_for = 3;
    r->recovered_mm = 10;
    r->recovery_s = -1;
    r->slow = 1;
}

/* grow *buf (n elements of size sz, capacity *cap) by one; NULL if out of memory */
static void *grow(void *buf, size_t n, size_t *cap, size_t sz)
{
    void *b;
    if (n < *cap)
        return buf;
    *cap = *cap ? 2 * *cap : 256;
    b = realloc(buf, *cap * sz);
    if (!b)
        free(buf);
    return b;
}

/* one line into r; 0 if it is not one */
typedef int (*take_line)(sim_run *r, const char *line, size_t *cap);

static int take_tick(sim_run *r, const char *line, size_t *cap)
{
    sim_tick k;
    if (sscanf(line, "%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %d", &k.t, &k.fx, &k.fy, &k.fyaw, &k.ax, &k.ay,
               &k.ayaw, &k.sigma, &k.tx, &k.ty, &k.tyaw, &k.wp) != 12)
        return 0;
    if (!(r->tick = grow(r->tick, r->n, cap, sizeof *r->tick)))
        return -1;
    r->tick[r->n++] = k;
    return 1;
}

static int take_reached(sim_run *r, const char *line, size_t *cap)
{
    sim_reached w;
    if (sscanf(line, "%d %lf %lf %lf %lf %lf %lf %lf", &w.i, &w.gx, &w.gy, &w.t, &w.ax, &w.ay, &w.tx, &w.ty) != 8)
        return 0;
    if (!(r->reached = grow(r->reached, r->nreached, cap, sizeof *r->reached)))
        return -1;
    r->reached[r->nreached++] = w;
    return 1;
}

/* every line of path through take; `what` names the expected line */
static int load(sim_run *r, const char *path, take_line take, const char *what, char *err, size_t errlen)
{
    FILE *f = fopen(path, "r");
    char line[512];
    size_t cap = 0;
    int no = 0, got = 1;
    if (!f) {
        snprintf(err, errlen, "%s: cannot read", path);
        return -1;
    }
    while (got > 0 && fgets(line, sizeof line, f)) {
        no++;
        got = take(r, line, &cap);
    }
    fclose(f);
    if (got == 0)
        snprintf(err, errlen, "%s:%d: not %s", path, no, what);
    else if (got < 0)
        snprintf(err, errlen, "%s: out of memory", path);
    return got > 0 ? 0 : -1;
}

int sim_report_load(sim_run *r, const char *poses, const char *route, char *err, size_t errlen)
{
    if (load(r, poses, take_tick, "'t fx fy fyaw ax ay ayaw sigma tx ty tyaw wp' (a simulator's pose log)", err,
             errlen))
        return -1;
    return route ? load(r, route, take_reached, "'i gx gy t ax ay tx ty' (a route log)", err, errlen) : 0;
}

double sim_report_error_mm(const sim_tick *k)
{
    double dx = round(k->fx * 1000) - round(k->tx * 1000), dy = round(k->fy * 1000) - round(k->ty * 1000);
    return sqrt(dx * dx + dy * dy);
}

double sim_report_yaw_error_deg(const sim_tick *k)
{
    double d = round(k->fyaw * 180 / PI) - round(k->tyaw * 180 / PI);
    d = fmod(d + 540, 360) - 180;
    return fabs(d);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the push's recovery: from the push until the error stays under the limit */
static void judge_push(sim_run *r)
{
    size_t i, last_bad = 0;
    int seen = 0;
    for (i = 0; i < r->n; i++) {
        double since = r->tick[i].t - r->start;
        if (since < r->push_at)
            continue;
        seen = 1;
        if (sim_report_error_mm(&r->tick[i]) >= r->recovered_mm)
            last_bad = i;
    }
    if (!seen)
        return;
    if (last_bad + 1 < r->n || sim_report_error_mm(&r->tick[r->n - 1]) < r->recovered_mm)
        r->recovery_s = last_bad ? r->tick[last_bad + 1].t - r->start - r->push_at : 0;
}

void sim_report_judge(sim_run *r)
{
    double *e = malloc((r->n ? r->n : 1) * sizeof *e), s = 0, sy = 0, end = INFINITY;
    size_t i;
    int started = 0;
    r->judged = r->excluded = 0;
    r->max_mm = r->max_yaw_deg = r->cut_max_mm = r->worst_waypoint_mm = 0;
    for (i = 0; i < r->n && !started; i++)
        if (r->tick[i].wp >= 0) {
            r->start = r->tick[i].t;
            started = 1;
        }
    if (r->nreached)
        end = r->reached[r->nreached - 1].t;
    if (r->push_at >= 0 && started)
        judge_push(r);
    for (i = 0; i < r->n && e; i++) {
        const sim_tick *k = &r->tick[i];
        double since = k->t - r->start, d = sim_report_error_mm(k), dy = sim_report_yaw_error_deg(k);
        if (!started || since < 0 || k->t > end)
            continue;
        if (r->cut_at >= 0 && since >= r->cut_at && since < r->cut_at + r->cut_for + 2 * r->slow)
            r->cut_max_mm = fmax(r->cut_max_mm, d);
        if (r->push_at >= 0 && since >= r->push_at &&
            (r->recovery_s < 0 || since < r->push_at + r->recovery_s)) {
            r->excluded++;
            continue;
        }
        e[r->judged++] = d;
        s += d * d;
        sy += dy * dy;
        r->max_mm = fmax(r->max_mm, d);
        r->max_yaw_deg = fmax(r->max_yaw_deg, dy);
    }
    if (e && r->judged) {
        r->rms_mm = sqrt(s / (double)r->judged);
        r->yaw_rms_deg = sqrt(sy / (double)r->judged);
        qsort(e, r->judged, sizeof *e, cmp_double);
        r->p95_mm = e[(size_t)(0.95 * (double)(r->judged - 1))];
    }
    free(e);
    for (i = 0; i < r->nreached; i++) {
        double dx = round(r->reached[i].tx * 1000) - round(r->reached[i].gx * 1000);
        double dy = round(r->reached[i].ty * 1000) - round(r->reached[i].gy * 1000);
        r->worst_waypoint_mm = fmax(r->worst_waypoint_mm, sqrt(dx * dx + dy * dy));
    }
}

void sim_report_free(sim_run *r)
{
    free(r->tick);
    free(r->reached);
    r->tick = NULL;
    r->reached = NULL;
    r->n = r->nreached = 0;
}
