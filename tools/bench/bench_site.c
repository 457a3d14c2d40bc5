#include "bench_site.h"
#include "bench_stats.h"
#include "bench_stages.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_clock.h"
#include "rl_png.h"
#include "rl_report.h"
#include "rl_site.h"

#define FRAMES 512
#define REPEAT 5
#define INNER 20

/* What is timed: one frame's place finding or pose solve. */
typedef struct {
    const rl_map *map;
    const rl_heap_place *hp;
    const rl_calib *cam;
    const rl_mount *mount;
    const rl_result *res;
    const rl_place_prior *prior; /* find: NULL for none */
    const rl_place_found *found; /* solve: the matches */
    int ok;
} job;

static void find(job *j)
{
    rl_place_found f;
    j->ok &= rl_place_find(j->hp->pl, j->cam, j->mount, j->res->landmarks, j->res->n_landmarks, NULL, j->prior,
                           &f) == RL_OK;
}

static void solve(job *j)
{
    rl_pose p;
    j->ok &= rl_pose_solve_matched(j->cam, j->map, j->mount, j->res->landmarks, j->res->n_landmarks,
                                   j->found->match, NULL, &p) == RL_OK;
}

/* Least over REPEAT runs of INNER calls: microseconds per call. */
static double least_us(void (*fn)(job *), job *j)
{
    double best = HUGE_VAL;
    int i, k;
    for (i = 0; i < REPEAT; i++) {
        uint64_t a = rl_clock_now_us();
        for (k = 0; k < INNER; k++)
            fn(j);
        best = fmin(best, (double)(rl_clock_now_us() - a) / INNER);
    }
    return best;
}

/* dir's site: map, camera and robot, the recognizer for the map's ids and
 * the place index (its build time into *build_ms). 0, or 1 with the line
 * printed. */
static rl_bench_stages stages;

static int load_site(const char *dir, rl_site *site, double *build_ms)
{
    static rl_site_folder held;
    rl_site_files files;
    rl_recog_config cfg;
    char err[768];
    uint64_t t0;
    rl_site_files_folder(&files, &held, dir);
    rl_recog_defaults(&cfg);
    rl_bench_stages_start(&stages, &cfg);
    if (rl_site_load(site, &files, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-bench: %s\n", err);
        return 1;
    }
    t0 = rl_clock_now_us();
    if (rl_site_prepare(site, &cfg, err, sizeof err) != RL_OK || site->place.pl == NULL) {
        fprintf(stderr, "ringloc-bench: %s/map.yaml: no place index (are ids repeated?)\n", dir);
        return 1;
    }
    *build_ms = (double)(rl_clock_now_us() - t0) / 1000.0;
    return 0;
}

/* The times of one frame: recognition, the place found with no prior and
 * tracked, the pose solved after it. 0, or -1 when the frame has no place. */
static int time_frame(rl_site *site, const rl_image *img, rl_result *res, double *recog, double *find_t,
                      double *track_t, double *solve_t)
{
    rl_place_found f;
    rl_place_prior prior;
    double r;
    int i;
    *recog = HUGE_VAL;
    for (i = 0; i < REPEAT; i++) {
        if (rl_report_run(&site->recog, img, res, &r) != RL_OK)
            return -1;
        *recog = fmin(*recog, r);
    }
    if (rl_place_find(site->place.pl, &site->calib, &site->mount, res->landmarks, res->n_landmarks, NULL, NULL,
                      &f) != RL_OK)
        return -1;
    {
        job j = {&site->map, &site->place, &site->calib, &site->mount, res, NULL, &f, 1};
        *find_t = least_us(find, &j);
        /* the place found once per recognition, in the stage table */
        rl_bench_stages_add(&stages, RL_STAGE_PLACE, *find_t * 1000.0 * REPEAT);
        rl_bench_stages_unit(&stages, img);
        /* tracking: the frame's own place as the last pose, a tenth of a second ago */
        prior.valid = 1;
        prior.x = f.x;
        prior.y = f.y;
        prior.yaw = f.yaw;
        prior.age = 0.1;
        j.prior = &prior;
        *track_t = least_us(find, &j);
        *solve_t = least_us(solve, &j);
        return j.ok ? 0 : 1;
    }
}

int rl_bench_site(const char *dir)
{
    static rl_site site;
    static rl_result res;
    static double find_us[FRAMES], track_us[FRAMES], recog_us[FRAMES], solve_us[FRAMES];
    char path[2048], err[512];
    int k, n = 0, failed = 0, r;
    double build_ms;
    if (load_site(dir, &site, &build_ms) != 0)
        return 1;
    for (k = 0; k < FRAMES; k++) {
        rl_image img;
        snprintf(path, sizeof path, "%s/random_%03d.png", dir, k);
        if (rl_png_read_gray(path, &img, err, sizeof err) != RL_OK)
            break;
        r = time_frame(&site, &img, &res, &recog_us[n], &find_us[n], &track_us[n], &solve_us[n]);
        rl_png_free(&img);
        if (r < 0) {
            failed++;
            continue;
        }
        failed += r;
        n++;
    }
    if (n == 0) {
        fprintf(stderr, "ringloc-bench: %s: no random_NNN.png frames with a place\n", dir);
        rl_site_free(&site);
        return 1;
    }
    printf("place: a site of %d landmarks (%d ids): index %.1f bytes per landmark (%zu bytes, %ld pairs), built in "
           "%.0f ms\n", site.map.count, rl_family_count(&site.map.family),
           (double)rl_place_bytes(site.place.pl) / site.map.count, rl_place_bytes(site.place.pl),
           rl_place_pairs(site.place.pl), build_ms);
    printf("place: %d frames (%d without a place), median of the least of %d runs: %.1f us per frame with no prior, "
           "%.1f us tracked; the pose solve after it %.1f us; recognition %.0f us (finding the place is %.1f%% of "
           "it)\n", n, failed, REPEAT, rl_bench_median(find_us, n), rl_bench_median(track_us, n), rl_bench_median(solve_us, n),
           rl_bench_median(recog_us, n), 100.0 * rl_bench_median(find_us, n) / rl_bench_median(recog_us, n));
    snprintf(path, sizeof path, "%s (a large site's %d frames, the place found with no prior)", dir, n);
    rl_bench_stages_print(&stages, path, 0.0);
    rl_site_free(&site);
    return 0;
}
