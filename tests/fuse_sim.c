/* fuse_sim: see fuse_sim.h. */
#define _DEFAULT_SOURCE 1
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fuse_sim.h"

#define CIRCLE_R 0.6
#define STEP 0.001 /* the odometry's own integration, s */
#define MAX_ODO 4096
#define MAX_EVENTS 1024

void fs_scenario_defaults(fs_scenario *sc)
{
    sc->v = 1.0;
    sc->odo_hz = 50;
    sc->delay = 0.100;
    sc->jitter = 0.0005;
    sc->extra_max = sc->extra_fixed = sc->ftdi_tick = 0;
    sc->from_clock = 0;
    sc->drift_ppm = 0;
    sc->restart_at = -1;
    sc->laps = 1;
    sc->gap_from = sc->gap_to = -1;
    sc->outlier = -1;
    sc->kidnap_at = -1;
    sc->simulated = 0;
    sc->scale_err = 1.01;
    sc->track_err = 1.02;
    sc->wheel_noise = 0.0002;
    sc->read_late = sc->stall_p = sc->stall_max = sc->lose_p = 0;
    sc->cycled = 0;
    sc->warmup = 1.0;
    sc->track = 0.33;
    sc->seed = 1;
    sc->export_dir = NULL;
}

static double wrap(double a)
{
    return atan2(sin(a), cos(a));
}

/* the renderer's paths (tools/render/ringloc_render.c, path_pose) by distance */
void fs_truth_at(const fs_drive *d, double s, fs_pose *p)
{
    if (d->closed) {
        s = fmod(s, d->length);
        if (s < 0)
            s += d->length;
    }
    if (strcmp(d->kind, "straight") == 0) {
        p->x = 0.6 + s;
        p->y = 1.55;
        p->yaw = 0;
    } else if (strcmp(d->kind, "circle") == 0) {
        double a = s / CIRCLE_R;
        p->x = 1.83 + CIRCLE_R * cos(a);
        p->y = 1.52 + CIRCLE_R * sin(a);
        p->yaw = wrap(a + M_PI / 2);
    } else {
        double w = 1.8, h = 1.2;
        if (s < w) { p->x = 0.9 + s; p->y = 0.9; p->yaw = 0; }
        else if (s < w + h) { p->x = 2.7; p->y = 0.9 + s - w; p->yaw = M_PI / 2; }
        else if (s < 2 * w + h) { p->x = 2.7 - (s - w - h); p->y = 2.1; p->yaw = M_PI; }
        else { p->x = 0.9; p->y = 2.1 - (s - 2 * w - h); p->yaw = -M_PI / 2; }
    }
}

/* distance along the drive of rendered frame k */
static double frame_s(const fs_drive *d, int k)
{
    return d->closed ? k * d->length / d->n : d->length * k / (d->n - 1);
}

static double num_after(const char *line, const char *key)
{
    const char *p = strstr(line, key);
    return p ? atof(p + strlen(key)) : NAN;
}

static int load_truth(fs_drive *d, const char *dir)
{
    int k;
    for (k = 0; k < d->n; k++) {
        char path[1024], line[512];
        FILE *f;
        fs_pose want;
        int got = 0;
        snprintf(path, sizeof path, "%s/%s_%03d.yaml", dir, d->kind, k);
        if ((f = fopen(path, "r")) == NULL) {
            fprintf(stderr, "%s: cannot open\n", path);
            return -1;
        }
        while (!got && fgets(line, sizeof line, f))
            got = sscanf(line, "robot: {x: %lf, y: %lf, yaw: %lf}", &d->truth[k].x, &d->truth[k].y,
                         &d->truth[k].yaw) == 3;
        fclose(f);
        fs_truth_at(d, frame_s(d, k), &want);
        /* the geometry is the renderer's (a corner's heading may be either edge's) */
        if (!got || hypot(want.x - d->truth[k].x, want.y - d->truth[k].y) > 1e-5 ||
            (fabs(wrap(want.yaw - d->truth[k].yaw)) > 1e-5 && strcmp(d->kind, "rect") != 0)) {
            fprintf(stderr, "%s: truth (%g, %g) is not the path's (%g, %g)\n", path, d->truth[k].x,
                    d->truth[k].y, want.x, want.y);
            return -1;
        }
    }
    return 0;
}

static int load_frames(fs_drive *d, const char *jsonl, int skip)
{
    char line[1024];
    int k = 0, seen = 0;
    FILE *f = fopen(jsonl, "r");
    if (f == NULL) {
        fprintf(stderr, "%s: cannot open\n", jsonl);
        return -1;
    }
    while (k < d->n && fgets(line, sizeof line, f)) {
        if (strstr(line, "\"type\": \"pose\"") == NULL || seen++ < skip)
            continue;
        d->meas[k].x = num_after(line, "\"x\": ");
        d->meas[k].y = num_after(line, "\"y\": ");
        d->meas[k].yaw = num_after(line, "\"yaw\": ");
        d->latency[k] = num_after(line, "\"latency_ms\": ") * 1e-3;
        d->sx[k] = num_after(line, "\"sigma\": {\"x\": ");
        d->sy[k] = num_after(strstr(line, "\"sigma\""), "\"y\": ");
        d->syaw[k] = num_after(strstr(line, "\"sigma\""), "\"yaw\": ");
        k++;
    }
    fclose(f);
    if (k < d->n) {
        fprintf(stderr, "%s: %d pose frames for the %d frames of %s\n", jsonl, k, d->n, d->kind);
        return -1;
    }
    return 0;
}

int fs_drive_load(fs_drive *d, const char *dir, const char *kind, int n, const char *jsonl, int skip)
{
    memset(d, 0, sizeof *d);
    snprintf(d->kind, sizeof d->kind, "%s", kind);
    if (n < 2 || n > FS_MAX_FRAMES)
        return -1;
    d->n = n;
    d->closed = strcmp(kind, "straight") != 0;
    d->length = strcmp(kind, "straight") == 0 ? 2.4 : strcmp(kind, "circle") == 0 ? 2 * M_PI * CIRCLE_R : 6.0;
    return load_truth(d, dir) == 0 && load_frames(d, jsonl, skip) == 0 ? 0 : -1;
}

