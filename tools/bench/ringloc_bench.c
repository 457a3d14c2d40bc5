/* ringloc-bench: recognition speed against AprilTag 3 on twin frames.
 *
 *   ringloc-bench DIR...
 *
 * Each DIR holds frames rendered with `ringloc-render --twin` (NAME.png
 * with ring landmarks, NAME_tag.png with AprilTag 36h11 tags of the same
 * size at the same places, NAME.yaml with the truth). For every frame size
 * it prints the median recognition time per frame of ringloc and of
 * AprilTag (tag36h11, one thread, default decimation), their ratio, what
 * each found, and ringloc's workspace. Both run in this process on the
 * same core, one after the other, so the ratio holds on any machine.
 * Then, for each DIR, --pose, --site and --real, the recognizer's stages
 * (rl_stage.h, timed through its hook: bench_stages.h) per frame in
 * microseconds and in whole-frame histogram passes, beside AprilTag 3.
 */
#define _GNU_SOURCE
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <apriltag/apriltag.h>
#include <apriltag/tag36h11.h>
#include "rl_cli.h"
#include "rl_clock.h"
#include "rl_png.h"
#include "rl_report.h"
#include "rl_site.h"
#include "bench_real.h"
#include "bench_site.h"
#include "bench_stages.h"
#include "bench_stats.h"
#include "bench_track.h"

#define REPEAT 5
#define MAX_FRAMES 256

static double least(const double *v, int n)
{
    double m = v[0];
    int i;
    for (i = 1; i < n; i++)
        if (v[i] < m)
            m = v[i];
    return m;
}

/* The twin frames of dir: for every NAME_tag.png, "dir/NAME" (sorted,
 * at most MAX_FRAMES, malloc'ed) into names; their count, or -1 with the
 * line printed. */
static int twin_names(const char *dir, char **names)
{
    char **paths, err[512];
    int n = 0, k, i;
    if (rl_png_list(dir, &paths, &k, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-bench: %s\n", err);
        return -1;
    }
    for (i = 0; i < k; i++) {
        size_t len = strlen(paths[i]);
        if (n < MAX_FRAMES && len > 8 && strcmp(paths[i] + len - 8, "_tag.png") == 0)
            names[n++] = strndup(paths[i], len - 8);
    }
    rl_png_list_free(paths, k);
    return n;
}

/* Run k's stage times (st since before) into kept when it is the fastest
 * run so far (t: the runs' whole times): the stages of the one fastest run,
 * the statistic of the summary rows and of AprilTag's time beside them. */
static void fastest_stages(const rl_bench_stages *st, const rl_bench_stages *before, int k, const double *t,
                           double *kept)
{
    int s, j;
    for (j = 0; j < k; j++)
        if (t[j] <= t[k])
            return;
    for (s = 0; s < RL_STAGE_DONE; s++)
        kept[s] = st->ns[s] - before->ns[s];
}

/* One twin frame, each image REPEAT times in a row (warm, as a detector
 * running frame after frame is), the fastest run of each: interference from
 * the rest of the machine only ever adds time, to either. What each found
 * is added to *found_rl and *found_at, the ring frame's size put in *W, *H.
 * 0, or 1 with the line printed. */
static int time_twin(const char *name, rl_heap_recog *hr, apriltag_detector_t *td, rl_bench_stages *st,
                     double *t_rl, double *t_at, int *found_rl, int *found_at, int *W, int *H)
{
    static rl_result res;
    rl_image ring, tag;
    double t[REPEAT], ta[REPEAT];
    char path[2048], err[512];
    rl_bench_stages start = *st;
    double kept[RL_STAGE_DONE];
    int k, s;
    snprintf(path, sizeof path, "%s.png", name);
    if (rl_png_read_gray(path, &ring, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-bench: %s\n", err), 1;
    snprintf(path, sizeof path, "%s_tag.png", name);
    if (rl_png_read_gray(path, &tag, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-bench: %s\n", err), 1;
    *W = ring.width;
    *H = ring.height;
    for (k = 0; k < REPEAT; k++) {
        rl_bench_stages before = *st;
        if (rl_report_run(hr, &ring, &res, &t[k]) != RL_OK)
            return fprintf(stderr, "ringloc-bench: %s: recognition failed\n", strrchr(name, '/') + 1), 1;
        fastest_stages(st, &before, k, t, kept);
    }
    for (s = 0; s < RL_STAGE_DONE; s++)
        st->ns[s] = start.ns[s] + kept[s];
    st->runs = start.runs + 1; /* the frame once: its fastest run */
    st->fastest_of = REPEAT;
    for (k = 0; k < REPEAT; k++) {
        image_u8_t im = {tag.width, tag.height, tag.stride, tag.data};
        double t0 = (double)rl_clock_now_us();
        zarray_t *dets = apriltag_detector_detect(td, &im);
        ta[k] = (double)rl_clock_now_us() - t0;
        if (k == 0)
            *found_at += zarray_size(dets);
        apriltag_detections_destroy(dets);
    }
    rl_bench_stages_unit(st, &ring);
    rl_bench_stages_count(st, &res);
    *t_rl = least(t, REPEAT);
    *t_at = least(ta, REPEAT);
    *found_rl += res.n_landmarks;
    rl_png_free(&ring);
    rl_png_free(&tag);
    return 0;
}

/* Each twin folder's stage table, printed after the summary rows. */
#define MAX_DIRS 8
static rl_bench_stages stages[MAX_DIRS];
static double stage_peer[MAX_DIRS];
static char stage_what[MAX_DIRS][512];
static int n_stages;

static int bench_dir(const char *dir, apriltag_detector_t *td)
{
    static char *names[MAX_FRAMES];
    static double t_rl[MAX_FRAMES], t_at[MAX_FRAMES];
    static rl_bench_stages st;
    int n, i, found_rl = 0, found_at = 0, W = 0, H = 0;
    rl_recog_config cfg;
    rl_heap_recog hr;
    if ((n = twin_names(dir, names)) < 0)
        return 1;
    if (n == 0) {
        fprintf(stderr, "ringloc-bench: %s: no twin frames (NAME.png + NAME_tag.png)\n", dir);
        return 1;
    }
    rl_recog_defaults(&cfg);
    rl_bench_stages_start(&st, &cfg);
    rl_heap_recog_init(&hr, &cfg);
    for (i = 0; i < n; i++) {
        if (time_twin(names[i], &hr, td, &st, &t_rl[i], &t_at[i], &found_rl, &found_at, &W, &H) != 0)
            return 1;
        free(names[i]);
    }
    {
        double mr = rl_bench_median(t_rl, n) / 1000.0, ma = rl_bench_median(t_at, n) / 1000.0, at_least = 0;
        size_t ws = rl_recog_workspace_size(W, H, &cfg);
        printf("%4dx%-4d %6d %12.3f %12.3f %9.1fx %9d %9d %10zu %7.2f\n", W, H, n, mr, ma, ma / mr,
               found_rl, found_at, ws, (double)ws / ((double)W * H));
        stages[n_stages] = st;
        for (i = 0; i < n; i++)
            at_least += t_at[i];
        stage_peer[n_stages] = at_least / n; /* each frame's fastest run, as the stages' */
        snprintf(stage_what[n_stages], sizeof stage_what[0], "%s", dir);
        n_stages += n_stages < MAX_DIRS - 1;
    }
    rl_heap_recog_free(&hr);
    return 0;
}

/* The local pass's cost per retried candidate: each frame recognized with
 * the local pass off and always on, alternately, LOCAL_REPEAT times; the
 * extra time of the fastest run of each over the candidates it retried
 * (the paper spent 0.10 s on each). The difference of two times is a
 * small part of either, so it takes the least of many runs: interference
 * from the rest of the machine only ever adds time. */
#define LOCAL_REPEAT 15


static int bench_local(const char *dir)
{
    static rl_result res;
    rl_recog_config cfg;
    rl_heap_recog never, always;
    double extra = 0, base = 0;
    long tried = 0, found = 0;
    int k, frames = 0;
    char path[2048], err[512];
    rl_recog_defaults(&cfg);
    cfg.local = RL_LOCAL_NEVER;
    rl_heap_recog_init(&never, &cfg);
    cfg.local = RL_LOCAL_ALWAYS;
    rl_heap_recog_init(&always, &cfg);
    for (k = 0; k < MAX_FRAMES; k++) {
        rl_image img;
        double t[LOCAL_REPEAT], u[LOCAL_REPEAT];
        int i;
        snprintf(path, sizeof path, "%s/glare_%03d.png", dir, k);
        if (rl_png_read_gray(path, &img, err, sizeof err) != RL_OK)
            break;
        for (i = 0; i < LOCAL_REPEAT; i++) {
            if (rl_report_run(&never, &img, &res, &t[i]) != RL_OK ||
                rl_report_run(&always, &img, &res, &u[i]) != RL_OK) {
                fprintf(stderr, "ringloc-bench: %s: recognition failed\n", path);
                return 1;
            }
        }
        extra += least(u, LOCAL_REPEAT) - least(t, LOCAL_REPEAT);
        base += least(t, LOCAL_REPEAT);
        tried += res.local_tried;
        found += res.local_found;
        frames++;
        rl_png_free(&img);
    }
    if (frames == 0) {
        fprintf(stderr, "ringloc-bench: %s: no glare_NNN.png frames\n", dir);
        return 1;
    }
    printf("local pass: %d frames, %ld candidates retried, %ld identified, %.1f us per retried candidate"
           " (least of %d runs; target < 50 us, the paper 100000 us)\n",
           frames, tried, found, tried ? extra / tried : 0.0, LOCAL_REPEAT);
    /* the same runs' global pass: a loaded machine slows both alike */
    printf("local pass: the frames' global pass took %.1f us each in the same runs; a retried candidate"
           " costs %.1f%% of that\n",
           base / frames, tried && base > 0 ? 100.0 * (extra / tried) / (base / frames) : 0.0);
    rl_heap_recog_free(&never);
    rl_heap_recog_free(&always);
    return 0;
}

/* The pose solver on a drive's frames (map.yaml, camera.yaml, robot.yaml
 * and straight/rect/circle_NNN.png, as ringloc-render --path writes):
 * microseconds per pose against the same frames' recognition. */
static int bench_pose(const char *dir)
{
    static const char *kinds[] = {"straight", "rect", "circle"};
    static rl_result res;
    static rl_site site;
    static rl_site_folder held;
    static double pose_us[MAX_FRAMES], recog_us[MAX_FRAMES];
    static rl_bench_stages st;
    rl_site_files files;
    rl_recog_config cfg;
    char path[2048], err[768];
    int q, k, n = 0, solved = 0;
    rl_site_files_folder(&files, &held, dir);
    rl_recog_defaults(&cfg);
    rl_bench_stages_start(&st, &cfg);
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK || rl_site_prepare(&site, &cfg, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-bench: %s\n", err);
        return 1;
    }
    for (q = 0; q < 3; q++)
        for (k = 0; k < MAX_FRAMES && n < MAX_FRAMES; k++) {
            rl_image img;
            rl_pose pose;
            double t[REPEAT], r[REPEAT];
            int i, j, bad = 0;
            snprintf(path, sizeof path, "%s/%s_%03d.png", dir, kinds[q], k);
            if (rl_png_read_gray(path, &img, err, sizeof err) != RL_OK)
                break;
            for (i = 0; i < REPEAT; i++) {
                uint64_t a;
                if (rl_report_run(&site.recog, &img, &res, &r[i]) != RL_OK)
                    break;
                a = rl_clock_now_us();
                for (j = 0; j < 20; j++)
                    bad |= rl_pose_solve(&site.calib, &site.map, &site.mount, res.landmarks, res.n_landmarks, NULL,
                                         &pose) != RL_OK;
                t[i] = (double)(rl_clock_now_us() - a) / 20.0;
                rl_bench_stages_add(&st, RL_STAGE_POSE, t[i] * 1000.0);
            }
            rl_bench_stages_unit(&st, &img);
            rl_png_free(&img);
            if (i < REPEAT || bad)
                continue;
            solved += pose.tilt_solved;
            pose_us[n] = least(t, REPEAT);
            recog_us[n] = least(r, REPEAT);
            n++;
        }
    rl_site_free(&site);
    if (n == 0) {
        fprintf(stderr, "ringloc-bench: %s: no drive frames (straight/rect/circle_NNN.png)\n", dir);
        return 1;
    }
    printf("pose: %d frames (the tilt solved in %d), %.1f us per pose (median of the least of %d runs), "
           "%.0f%% of the same frames' recognition (%.1f us)\n", n, solved, rl_bench_median(pose_us, n), REPEAT,
           100.0 * rl_bench_median(pose_us, n) / rl_bench_median(recog_us, n), rl_bench_median(recog_us, n));
    snprintf(path, sizeof path, "%s (a drive's %d frames, with the pose)", dir, n);
    rl_bench_stages_print(&st, path, 0.0);
    return 0;
}

int main(int argc, char **argv)
{
    apriltag_family_t *tf;
    apriltag_detector_t *td;
    cpu_set_t one;
    int i, rc = 0, header = 0;
    rl_cli_start("ringloc-bench");
    if (argc < 2 || strcmp(argv[1], "--help") == 0) {
        fprintf(argc < 2 ? stderr : stdout,
                "usage: ringloc-bench DIR... [--local GLARE_DIR] [--pose DRIVE_DIR] [--site SITE_DIR]\n"
                "                     [--real PHOTO_DIR] [--track DIR:PREFIX]...\n"
                "  DIR: twin frames from ringloc-render --twin; GLARE_DIR: its --set glare frames;\n"
                "  DRIVE_DIR: a drive from ringloc-render --path (map, camera, robot files);\n"
                "  SITE_DIR: a planned site (ringloc plan --area) and random_NNN.png frames under it\n"
                "  (ringloc-render --site-map --path random);\n"
                "  PHOTO_DIR: real ceiling photos (PNG) to place rings and AprilTag twins into\n"
                "  DIR:PREFIX: an ordered drive, DIR/PREFIX*.png with map, camera and robot in DIR:\n"
                "  tracked frames (rl_track.h) beside full ones, against the truth (docs/tracking.md)\n"
                "Each set also gets a table of the recognizer's stages (histogram, labelling, CLRs,\n"
                "global pass, tone reads, second labellings, local pass, reads across motion; pose\n"
                "and place where there is a map): time per frame in us and in passes of one\n"
                "histogram over the whole frame, measured in the same run (docs/design.md)\n");
        return argc < 2 ? 2 : 0;
    }
    /* one core: both detectors on the same one */
    CPU_ZERO(&one);
    CPU_SET(sched_getcpu() < 0 ? 0 : sched_getcpu(), &one);
    sched_setaffinity(0, sizeof one, &one);
    tf = tag36h11_create();
    td = apriltag_detector_create();
    apriltag_detector_add_family(td, tf);
    td->nthreads = 1; /* quad_decimate stays at its default */
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--real") == 0 && i + 1 < argc) {
            rc |= rl_bench_real(argv[++i], 3, 1, 25.7, td, tf);
            continue;
        }
        if (strcmp(argv[i], "--site") == 0 && i + 1 < argc) {
            rc |= rl_bench_site(argv[++i]);
            continue;
        }
        if (strcmp(argv[i], "--track") == 0 && i + 1 < argc) {
            char dir[1024];
            const char *colon = strrchr(argv[++i], ':');
            if (colon == NULL || colon - argv[i] >= (long)sizeof dir) {
                fprintf(stderr, "ringloc-bench: --track %s: expected DIR:PREFIX\n", argv[i]);
                rc = 1;
                continue;
            }
            snprintf(dir, sizeof dir, "%.*s", (int)(colon - argv[i]), argv[i]);
            rc |= rl_bench_track(dir, colon + 1);
            continue;
        }
        if (strcmp(argv[i], "--pose") == 0 && i + 1 < argc) {
            rc |= bench_pose(argv[++i]);
            continue;
        }
        if (strcmp(argv[i], "--local") == 0 && i + 1 < argc) {
            rc |= bench_local(argv[++i]);
            continue;
        }
        if (!header) {
            printf("recognition time per frame, median over frames of the least of %d runs each\n",
                   REPEAT);
            printf("%-9s %6s %12s %12s %10s %9s %9s %10s %7s\n", "size", "frames", "ringloc_ms",
                   "apriltag_ms", "ratio", "rings", "tags", "workspace", "B/px");
            header = 1;
        }
        rc |= bench_dir(argv[i], td);
    }
    for (i = 0; i < n_stages; i++)
        rl_bench_stages_print(&stages[i], stage_what[i], stage_peer[i]);
    apriltag_detector_destroy(td);
    tag36h11_destroy(tf);
    return rc;
}
