#include "bench_track.h"
#include "bench_stages.h"
#include "bench_stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_png.h"
#include "rl_pngrun.h"
#include "rl_site.h"

#define FRAMES 512
#define TRUTH_MAX 64
#define POSE_TOLERANCE 0.05 /* m */
#define CAPPED_READS 3      /* the third run: rl_track_config.max_reads */

/* A frame's truth: the robot's place and the landmarks wholly in view. */
typedef struct {
    double x, y;
    int n, id[TRUTH_MAX];
    double u[TRUTH_MAX], v[TRUTH_MAX], r[TRUTH_MAX], visible[TRUTH_MAX];
} truth;

/* NAME.yaml of NAME.png; 0 when it cannot be read. */
static int truth_read(const char *png, truth *t)
{
    char path[2100], line[512];
    size_t len = strlen(png);
    FILE *f;
    int have = 0;
    if (len < 4 || len > 2000)
        return 0;
    snprintf(path, sizeof path, "%.*s.yaml", (int)(len - 4), png);
    if ((f = fopen(path, "r")) == NULL)
        return 0;
    t->n = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        double X, Y;
        int k = t->n;
        have |= sscanf(line, "robot: {x: %lf, y: %lf", &t->x, &t->y) == 2;
        if (k < TRUTH_MAX && sscanf(line, " - {id: %d, x: %lf, y: %lf, u: %lf, v: %lf, radius: %lf, visible: %lf",
                                    &t->id[k], &X, &Y, &t->u[k], &t->v[k], &t->r[k], &t->visible[k]) == 7)
            t->n++;
    }
    fclose(f);
    return have;
}

/* One mode's figures over the drive. */
typedef struct {
    int frames, windows, fulls, whole, whole_read, ids, wrong_ids, posed, pose_right, pose_frames;
    double us_all[FRAMES], us_win[FRAMES], us_full[FRAMES], unit[FRAMES], err[FRAMES];
    /* localizing (the place and the pose, rl_run's pose_us) alone and
     * with the frame's recognition, by the same frames as us_* */
    double pose_all[FRAMES], pose_win[FRAMES], pose_full[FRAMES];
    double both_all[FRAMES], both_win[FRAMES], both_full[FRAMES];
    int nerr;
    long by_box, by_window; /* landmarks of windowed frames read as a box, as a window */
} tally;

typedef struct {
    tally *t;
    rl_bench_stages unit; /* the histogram pass, per frame */
    /* the stages' run (rl_stage.h's hook): the frame's times into frame,
     * a window frame's kept in win_ns[frame][stage] (us), its recog_us in
     * win_us[frame] */
    rl_bench_stages *frame;
    double (*win_ns)[RL_STAGE_DONE], *win_us;
    int wins;
} sink;

/* The truth landmark a detection lies on (within half its radius), or -1. */
static int on_truth(const truth *t, const rl_detection *d)
{
    int k;
    for (k = 0; k < t->n; k++)
        if (hypot(t->u[k] - d->u, t->v[k] - d->v) < 0.5 * t->r[k])
            return k;
    return -1;
}

static void count_ids(tally *s, const truth *t, const rl_result *res)
{
    int i, k;
    for (i = 0; i < res->n_landmarks; i++) {
        k = on_truth(t, &res->landmarks[i]);
        s->ids++;
        s->wrong_ids += k < 0 || t->id[k] != res->landmarks[i].id;
    }
    for (k = 0; k < t->n; k++) {
        if (t->visible[k] < 0.999)
            continue;
        s->whole++;
        for (i = 0; i < res->n_landmarks; i++)
            if (res->landmarks[i].id == t->id[k] && on_truth(t, &res->landmarks[i]) == k) {
                s->whole_read++;
                break;
            }
    }
}

static rl_err put(void *ctx, const rl_run_report *rep)
{
    sink *sk = (sink *)ctx;
    tally *s = sk->t;
    truth t;
    int whole = 0, k;
    if (s->frames >= FRAMES || !truth_read(rep->frame->name, &t))
        return RL_OK;
    rl_bench_stages_unit(&sk->unit, &rep->frame->img);
    s->unit[s->frames] = sk->unit.unit_ns / sk->unit.units / 1000.0;
    sk->unit.unit_ns = 0;
    sk->unit.units = 0;
    s->pose_all[s->frames] = rep->pose_us;
    s->both_all[s->frames] = rep->recog_us + rep->pose_us;
    s->us_all[s->frames++] = rep->recog_us;
    for (k = 0; k < rep->res->n_landmarks && rep->windows; k++)
        s->by_box += rep->res->landmarks[k].pass == RL_PASS_GLOBAL;
    for (k = 0; k < rep->res->n_landmarks && rep->windows; k++)
        s->by_window += rep->res->landmarks[k].pass == RL_PASS_LOCAL;
    if (sk->frame != NULL && rep->windows && sk->wins < FRAMES) {
        int st;
        for (st = 0; st < RL_STAGE_DONE; st++)
            sk->win_ns[sk->wins][st] = sk->frame->ns[st] / 1000.0;
        sk->win_us[sk->wins++] = rep->recog_us;
    }
    if (sk->frame != NULL)
        memset(sk->frame->ns, 0, sizeof sk->frame->ns);
    if (rep->windows) {
        s->pose_win[s->windows] = rep->pose_us;
        s->both_win[s->windows] = rep->recog_us + rep->pose_us;
        s->us_win[s->windows++] = rep->recog_us;
    } else {
        s->pose_full[s->fulls] = rep->pose_us;
        s->both_full[s->fulls] = rep->recog_us + rep->pose_us;
        s->us_full[s->fulls++] = rep->recog_us;
    }
    count_ids(s, &t, rep->res);
    for (k = 0; k < t.n; k++)
        whole += t.visible[k] >= 0.999;
    if (whole < 2)
        return RL_OK;
    s->pose_frames++;
    if (rep->pose_err == RL_OK) {
        double e = hypot(rep->pose->x - t.x, rep->pose->y - t.y);
        s->posed++;
        s->pose_right += e <= POSE_TOLERANCE;
        s->err[s->nerr++] = e;
    }
    return RL_OK;
}

/* dir's frames named prefix*, in order (malloc'ed); their count. */
static int drive_frames(const char *dir, const char *prefix, char ***out)
{
    char **paths, err[512];
    int n = 0, k, i;
    if (rl_png_list(dir, &paths, &k, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-bench: %s\n", err);
        return -1;
    }
    *out = calloc((size_t)k + 1, sizeof **out);
    for (i = 0; i < k && *out != NULL; i++) {
        const char *base = strrchr(paths[i], '/');
        base = base ? base + 1 : paths[i];
        if (strncmp(base, prefix, strlen(prefix)) == 0 && n < FRAMES)
            (*out)[n++] = strdup(paths[i]);
    }
    rl_png_list_free(paths, k);
    return *out ? n : -1;
}

/* One row: n frames' median recognition time (us) and in passes; on the
 * first row of a run its reads and poses; then the median time of
 * localizing them (the place and the pose) and of the frame with it, in
 * passes. */
static void print_row(const char *what, int n, double *us, double *pose, double *both, tally *s, int first)
{
    double u = rl_bench_median(s->unit, s->frames), m = n ? rl_bench_median(us, n) : 0;
    double p = n ? rl_bench_median(pose, n) : 0, b = n ? rl_bench_median(both, n) : 0;
    printf("  %-16s %6d %10.1f %8.2f", what, n, m, u > 0 ? m / u : 0.0);
    if (first)
        printf("   %5d/%-5d %5d  %5d/%-5d %8.1f", s->whole_read, s->whole, s->wrong_ids, s->pose_right, s->pose_frames,
               s->nerr ? 1000.0 * rl_bench_median(s->err, s->nerr) : 0.0);
    else
        printf("   %11s %5s  %11s %8s", "", "", "", "");
    printf("  %7.2f %9.2f\n", u > 0 ? p / u : 0.0, u > 0 ? b / u : 0.0);
}

/* The tracked run once more with the stages' hook on (its calls add to
 * the times: the table above runs without it): where a window frame's
 * time goes, each stage's median over the window frames (a shared
 * machine's preemptions would swamp a mean) in us and in passes (unit),
 * and the frame's, whose part no stage holds is the plan's and the
 * loop's (their medians do not add up to the frame's). */
static void window_stages(rl_pngrun *pr, rl_site *site, char **names, int n, sink *sk, double unit)
{
    static tally hooked;
    static double ns[FRAMES][RL_STAGE_DONE], us[FRAMES], col[FRAMES], rest[FRAMES];
    rl_bench_stages frame;
    rl_recog_config cfg;
    int s, k;
    memset(&hooked, 0, sizeof hooked);
    rl_bench_stages_start(&frame, &cfg);
    /* the recognizer made again, with the hook (the runs before had none) */
    rl_heap_recog_free(&site->recog);
    site->recog.cfg.stage_hook = cfg.stage_hook;
    sk->t = &hooked;
    sk->frame = &frame;
    sk->win_ns = ns;
    sk->win_us = us;
    sk->wins = 0;
    (void)rl_pngrun_files(pr, site, names, n);
    rl_heap_recog_free(&site->recog);
    memset(&site->recog.cfg.stage_hook, 0, sizeof cfg.stage_hook);
    sk->frame = NULL;
    if (sk->wins == 0 || !(unit > 0))
        return;
    printf("  window frames by stage (the tracked run again, the hook on: %d window frames; medians, us and "
           "passes):\n", sk->wins);
    for (k = 0; k < sk->wins; k++)
        rest[k] = us[k];
    for (s = 0; s < RL_STAGE_DONE; s++) {
        double m;
        for (k = 0; k < sk->wins; k++) {
            col[k] = ns[k][s];
            rest[k] -= ns[k][s];
        }
        m = rl_bench_median(col, sk->wins);
        for (k = 0; k < sk->wins && !(m > 0); k++)
            m = col[k] > 0 ? -1 : m; /* a stage some frames ran: shown */
        if (m != 0)
            printf("    %-24s %8.1f %8.3f\n", rl_stage_name((rl_stage)s), m > 0 ? m : 0.0, m > 0 ? m / unit : 0.0);
    }
    printf("    %-24s %8.1f %8.3f\n", "the plan and the rest", rl_bench_median(rest, sk->wins),
           rl_bench_median(rest, sk->wins) / unit);
    printf("    %-24s %8.1f %8.3f\n", "window frame", rl_bench_median(us, sk->wins),
           rl_bench_median(us, sk->wins) / unit);
}

int rl_bench_track(const char *dir, const char *prefix)
{
    static rl_site site;
    static rl_site_folder held;
    static tally full, tracked, capped;
    sink sk;
    rl_site_files files;
    rl_recog_config cfg;
    rl_pngrun pr;
    char **names = NULL, err[768];
    int n, k;
    rl_site_files_folder(&files, &held, dir);
    rl_recog_defaults(&cfg);
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK || rl_site_prepare(&site, &cfg, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-bench: %s\n", err);
        return 1;
    }
    if ((n = drive_frames(dir, prefix, &names)) <= 0) {
        fprintf(stderr, "ringloc-bench: %s: no %s*.png frames\n", dir, prefix);
        rl_site_free(&site);
        free(names);
        return 1;
    }
    memset(&full, 0, sizeof full);
    memset(&tracked, 0, sizeof tracked);
    memset(&capped, 0, sizeof capped);
    memset(&sk, 0, sizeof sk);
    rl_pngrun_defaults(&pr, "bench");
    pr.run.frame_interval = 0.1; /* a drive at 10 frames a second, as `locate` takes it */
    pr.put = put;
    pr.ctx = &sk;
    sk.t = &full;
    (void)rl_pngrun_files(&pr, &site, names, n);
    rl_track_defaults(&pr.run.track);
    sk.t = &tracked;
    (void)rl_pngrun_files(&pr, &site, names, n);
    pr.run.track.max_reads = CAPPED_READS;
    sk.t = &capped;
    (void)rl_pngrun_files(&pr, &site, names, n);
    pr.run.track.max_reads = 0;
    printf("track, %s/%s*.png (%d frames in order, 10 a second; a full frame every %d): median us per frame and\n"
           "in whole-frame histogram passes (%.1f us, the same frames); whole landmarks read right, wrong ids,\n"
           "poses within %.0f cm of the truth (frames with two whole landmarks), median pose error mm; then\n"
           "localizing (the place and the pose) and the frame with it, in passes (medians of the same frames)\n",
           dir, prefix, n, pr.run.track.full_every, rl_bench_median(full.unit, full.frames), 100 * POSE_TOLERANCE);
    printf("  %-16s %6s %10s %8s   %11s %5s  %11s %8s  %7s %9s\n", "frames", "count", "us", "passes", "whole read",
           "wrong", "poses", "err mm", "pose", "with pose");
    print_row("full (--no-track)", full.frames, full.us_all, full.pose_all, full.both_all, &full, 1);
    print_row("tracked: all", tracked.frames, tracked.us_all, tracked.pose_all, tracked.both_all, &tracked, 1);
    print_row("  by windows", tracked.windows, tracked.us_win, tracked.pose_win, tracked.both_win, &tracked, 0);
    printf("  (their landmarks: %ld verified or read as the global pass reads a box, %ld as the local pass reads a window)\n",
           tracked.by_box, tracked.by_window);
    print_row("  in full", tracked.fulls, tracked.us_full, tracked.pose_full, tracked.both_full, &tracked, 0);
    print_row("tracked, 3 reads", capped.frames, capped.us_all, capped.pose_all, capped.both_all, &capped, 1);
    print_row("  by windows", capped.windows, capped.us_win, capped.pose_win, capped.both_win, &capped, 0);
    print_row("  in full", capped.fulls, capped.us_full, capped.pose_full, capped.both_full, &capped, 0);
    window_stages(&pr, &site, names, n, &sk, rl_bench_median(full.unit, full.frames));
    for (k = 0; k < n; k++)
        free(names[k]);
    free(names);
    rl_site_free(&site);
    return 0;
}
