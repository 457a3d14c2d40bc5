#include "bench_site.h"
#include "bench_stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_calibfile.h"
#include "rl_clock.h"
#include "rl_heap_place.h"
#include "rl_heap_recog.h"
#include "rl_mapfile.h"
#include "rl_png.h"
#include "rl_report.h"
#include "rl_robotfile.h"

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

int rl_bench_site(const char *dir)
{
    static rl_map map;
    static rl_result res;
    static double find_us[FRAMES], track_us[FRAMES], recog_us[FRAMES], solve_us[FRAMES];
    rl_calib cam;
    rl_mount mount;
    rl_recog_config cfg;
    rl_heap_recog hr;
    rl_heap_place hp;
    char path[2048], err[512];
    int ids[RL_MAX_IDS], k, n = 0, failed = 0;
    uint64_t t0;
    double build_ms;
    snprintf(path, sizeof path, "%s/map.yaml", dir);
    if (rl_mapfile_load(path, &map, err, sizeof err) != RL_OK)
        goto fail;
    snprintf(path, sizeof path, "%s/camera.yaml", dir);
    if (rl_calibfile_load(path, &cam, err, sizeof err) != RL_OK)
        goto fail;
    snprintf(path, sizeof path, "%s/robot.yaml", dir);
    if (rl_robotfile_load(path, &mount, err, sizeof err) != RL_OK)
        goto fail;
    t0 = rl_clock_now_us();
    if (rl_heap_place_init(&hp, &map, NULL) != RL_OK || hp.pl == NULL) {
        fprintf(stderr, "ringloc-bench: %s/map.yaml: no place index (are ids repeated?)\n", dir);
        return 1;
    }
    build_ms = (double)(rl_clock_now_us() - t0) / 1000.0;
    rl_recog_defaults(&cfg);
    rl_recog_use_map(&cfg, &map, ids);
    rl_heap_recog_init(&hr, &cfg);
    for (k = 0; k < FRAMES; k++) {
        rl_image img;
        rl_place_found f;
        rl_place_prior prior;
        double r, best_r = HUGE_VAL;
        int i;
        snprintf(path, sizeof path, "%s/random_%03d.png", dir, k);
        if (rl_png_read_gray(path, &img, err, sizeof err) != RL_OK)
            break;
        for (i = 0; i < REPEAT; i++) {
            if (rl_report_run(&hr, &img, &res, &r) != RL_OK)
                break;
            best_r = fmin(best_r, r);
        }
        rl_png_free(&img);
        if (i < REPEAT || rl_place_find(hp.pl, &cam, &mount, res.landmarks, res.n_landmarks, NULL, NULL, &f) != RL_OK) {
            failed++;
            continue;
        }
        {
            job j = {&map, &hp, &cam, &mount, &res, NULL, &f, 1};
            find_us[n] = least_us(find, &j);
            /* tracking: the frame's own place as the last pose, a tenth of a second ago */
            prior.valid = 1;
            prior.x = f.x;
            prior.y = f.y;
            prior.yaw = f.yaw;
            prior.age = 0.1;
            j.prior = &prior;
            track_us[n] = least_us(find, &j);
            solve_us[n] = least_us(solve, &j);
            failed += !j.ok;
        }
        recog_us[n] = best_r;
        n++;
    }
    rl_heap_recog_free(&hr);
    if (n == 0) {
        fprintf(stderr, "ringloc-bench: %s: no random_NNN.png frames with a place\n", dir);
        rl_heap_place_free(&hp);
        return 1;
    }
    printf("place: a site of %d landmarks (%d ids): index %.1f bytes per landmark (%zu bytes, %ld pairs), built in "
           "%.0f ms\n", map.count, rl_family_count(&map.family), (double)rl_place_bytes(hp.pl) / map.count,
           rl_place_bytes(hp.pl), rl_place_pairs(hp.pl), build_ms);
    printf("place: %d frames (%d without a place), median of the least of %d runs: %.1f us per frame with no prior, "
           "%.1f us tracked; the pose solve after it %.1f us; recognition %.0f us (finding the place is %.1f%% of "
           "it)\n", n, failed, REPEAT, rl_bench_median(find_us, n), rl_bench_median(track_us, n), rl_bench_median(solve_us, n),
           rl_bench_median(recog_us, n), 100.0 * rl_bench_median(find_us, n) / rl_bench_median(recog_us, n));
    rl_heap_place_free(&hp);
    return 0;
fail:
    fprintf(stderr, "ringloc-bench: %s\n", err);
    return 1;
}
