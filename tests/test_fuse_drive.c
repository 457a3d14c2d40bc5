/* rl_fuse on the rendered drives, against the truth at every 10 ms tick
 * (issue 27's "done when"): the firmware's pose frames on a circle
 * rendered 0.1 m a frame (10 a second at 1 m/s), and on the CI's path
 * drives (straight, 12 frames over 2.4 m; rect, 16 a lap), odometry simulated at 10 and 50 Hz with a 1% wheel scale
 * error, a 2% track width error and wheel noise; beside today's
 * reset-on-arrival. Prints every figure, fails on a target missed.
 * Writes the circle at 1 m/s as `ringloc fuse` takes it into EXPORT_DIR,
 * and over a real line (uniform 0 .. 100 ms outside the latency field,
 * with the arrivals) into EXPORT_DIR/line.
 * usage: test_fuse_drive FUSE_DIR FUSE_JSONL PATHS_DIR PATHS_JSONL PICTURE.png EXPORT_DIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fuse_plot.h"
#include "fuse_sim.h"

#define SEEDS 20

static int fails;
static fs_result res; /* large: one at a time */

static void check(int ok, const char *what)
{
    if (!ok) {
        printf("FAIL: %s\n", what);
        fails++;
    }
}

static void row(const fs_drive *d, const fs_scenario *sc, const fs_result *r)
{
    double spacing = d->closed ? d->length / d->n : d->length / (d->n - 1);
    printf("%-8s %4.1f m/s %4.1f fps %2.0f Hz odo | fused %5.2f mm RMS (max %5.2f) step max %4.2f mm "
           "(%.2f s) yaw max %5.3f deg (%.2f s) | reset-on-arrival %6.2f mm RMS | scale %.4f turn %.4f | applied %lu rejected %lu\n",
           d->kind, sc->v, sc->v / spacing, sc->odo_hz, r->rms_fused * 1e3, r->max_err_fused * 1e3,
           r->max_step * 1e3, r->t_max_step, r->max_yaw * 180 / M_PI, r->t_max_yaw, r->rms_reset * 1e3, r->scale, r->turn,
           r->stats.applied, r->stats.rejected);
    printf("         warm-up (first %.1f s, the scales being learned): error max %.2f mm, step max %.2f mm, "
           "yaw max %.3f deg\n", sc->warmup, r->warm_max_err * 1e3, r->warm_max_step * 1e3,
           r->warm_max_yaw * 180 / M_PI);
}

/* at 1 m/s, 10 frames a second, 100 ms capture -> arrival */
static void done_when_1(const fs_drive *ci)
{
    const fs_drive *d[1] = {ci};
    double hz[2] = {10, 50};
    int i, j;
    printf("== 1 m/s, 10 pose frames/s, 100 ms capture -> arrival (targets: <= 3 mm RMS, step <= 1 mm, "
           "yaw <= 0.1 deg)\n");
    for (i = 0; i < 1; i++)
        for (j = 0; j < 2; j++) {
            fs_scenario sc;
            fs_scenario_defaults(&sc);
            sc.odo_hz = hz[j];
            sc.laps = 2;
            if (fs_run(d[i], &sc, &res) != 0) {
                check(0, "run");
                continue;
            }
            row(d[i], &sc, &res);
            check(res.rms_fused <= 0.003, "fused RMS above 3 mm");
            check(res.max_step <= 0.001, "a step above 1 mm between ticks");
            check(res.max_yaw <= 0.1 * M_PI / 180, "yaw error above 0.1 degree");
            check(res.rms_fused < res.rms_reset, "fused no better than reset-on-arrival");
        }
    printf("   (the firmware's own capture -> send latency on these frames: %.1f ms on average; the rest "
           "of the 100 ms stands for the camera's pipeline, carried in the frame's latency field)\n",
           res.mean_latency * 1e3);
}

/* every drive at 0.3 .. 1.2 m/s: reported; fused better than reset */
static void speeds(const fs_drive *st, const fs_drive *ci, const fs_drive *rect)
{
    const fs_drive *d[3] = {st, ci, rect};
    double v[4] = {0.3, 0.6, 1.0, 1.2};
    int i, j;
    printf("== the drives at 0.3 .. 1.2 m/s, 50 Hz odometry (straight and rect: the CI path drives, 0.22 m "
           "and 0.375 m a frame; rect's ticks just after its instant corners left out)\n");
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            fs_scenario sc;
            fs_scenario_defaults(&sc);
            sc.v = v[j];
            sc.laps = 2;
            if (fs_run(d[i], &sc, &res) != 0) {
                check(0, "run");
                continue;
            }
            row(d[i], &sc, &res);
            check(res.rms_fused < res.rms_reset, "fused no better than reset-on-arrival");
            check(res.rms_fused <= 0.005, "fused RMS above 5 mm");
        }
}

/* a 3 m stretch without landmarks after a lap and a half: the error
 * against the distance, and RMS error / sigma over SEEDS odometry noises */
static void stretch(const fs_drive *d, double laps, double from, const char *png)
{
    static double e2[4000], s2[4000];
    double worst = 0, rmin = 1e9, rmax = 0;
    int seed, i, n = 0;
    memset(e2, 0, sizeof e2);
    memset(s2, 0, sizeof s2);
    for (seed = 1; seed <= SEEDS; seed++) {
        fs_scenario sc;
        fs_scenario_defaults(&sc);
        sc.laps = laps;
        sc.gap_from = from;
        sc.gap_to = from + 3.0;
        sc.odo_hz = seed % 2 ? 50 : 10;
        sc.seed = (unsigned)seed;
        if (fs_run(d, &sc, &res) != 0) {
            check(0, "run");
            return;
        }
        for (i = 0, n = 0; i < res.n; i++)
            if (res.in_gap[i] && !res.corner[i]) {
                e2[n] += pow(res.fused[i].x - res.truth[i].x, 2) + pow(res.fused[i].y - res.truth[i].y, 2);
                s2[n] += res.cov[i][0] + res.cov[i][2];
                n++;
            }
        worst = fmax(worst, res.gap_max_err);
        if (seed == 1 && png && fuse_plot_write(png, &res, "circle at 1 m/s, 10 frames/s, 50 Hz odometry, "
                                                "3 m without landmarks in the second lap") != 0)
            check(0, "picture");
    }
    for (i = 0; i < n; i++) {
        double r = sqrt(e2[i] / s2[i]);
        rmin = fmin(rmin, r);
        rmax = fmax(rmax, r);
    }
    printf("== %s: 3 m without landmarks from %.2f m (%d seeds, 10/50 Hz odometry): largest error %.2f mm = "
           "%.3f%% of 3 m (target <= 0.5%%); RMS error/sigma over the seeds %.2f .. %.2f at every tick "
           "(target 0.5 .. 2)\n", d->kind, from, SEEDS, worst * 1e3, worst / 3.0 * 100, rmin, rmax);
    check(worst <= 0.005 * 3.0, "error in the stretch above 0.5% of the distance");
    check(rmin >= 0.5 && rmax <= 2.0, "RMS error/sigma outside 0.5 .. 2");
}

static void outlier_and_kidnap(const fs_drive *st, const fs_drive *ci)
{
    fs_scenario sc;
    fs_scenario_defaults(&sc);
    sc.outlier = 6;
    if (fs_run(st, &sc, &res) == 0) {
        printf("== a frame 0.5 m off the truth (straight, frame 6): rejected %lu, applied %lu; "
               "fused %.2f mm RMS, max %.2f mm\n", res.stats.rejected, res.stats.applied,
               res.rms_fused * 1e3, res.max_err_fused * 1e3);
        check(res.stats.rejected == 1 && res.stats.recoveries == 0, "outlier not rejected");
        check(res.max_err_fused <= 0.005, "the outlier moved the pose");
    } else
        check(0, "run");
    fs_scenario_defaults(&sc);
    sc.laps = 2;
    sc.kidnap_at = 5.0;
    sc.simulated = 1;
    if (fs_run(ci, &sc, &res) == 0) {
        printf("== carried 3 m (circle, at 5 m; frames from the truth and the measured sigmas): rejected "
               "%lu, recoveries %lu; error after the second frame since %.2f mm\n", res.stats.rejected,
               res.stats.recoveries, res.kidnap_err * 1e3);
        check(res.stats.recoveries == 1 && res.stats.rejected == 2, "not recovered on the second frame");
        check(res.kidnap_err <= 0.01, "pose not back within 1 cm after two frames");
    } else
        check(0, "run");
}

/* The real line (issue 38): 15 ms in the frames' latency field and a
 * transport delay outside it; frames through rl_fuse_msg_add, from the
 * board's time_ms and the arrival stamps only; the circle for 37 s at
 * 1 m/s, 10 frames a second, 50 Hz odometry. The truth is the path's. */
typedef struct {
    const char *name;
    double extra_max, extra_fixed, ftdi_tick, drift_ppm, restart_at;
    int outlier;
    double kidnap_at;
} line_case;

/* the real line's drive: 37 s, 15 ms in the latency field, the board's clock */
static void line_defaults(fs_scenario *sc)
{
    fs_scenario_defaults(sc);
    sc->laps = 10;
    sc->delay = 0.015;
    sc->from_clock = 1;
}

static void line_row(const char *how, const line_case *c, const fs_result *r)
{
    printf("%-34s %-10s fused %6.2f mm RMS, p95 %6.2f mm, max %6.2f mm | reset-on-arrival %6.2f mm | "
           "applied %lu rejected %lu restarts %lu clock resets %lu\n", c->name, how, r->rms_fused * 1e3,
           r->p95_fused * 1e3, r->max_err_fused * 1e3, r->rms_reset * 1e3, r->stats.applied,
           r->stats.rejected, r->stats.recoveries, r->stats.clock_resets);
}

static void real_line(const fs_drive *ci)
{
    static const line_case cases[] = {
        {"uniform 0..100 ms", 0.1, 0, 0, 0, -1, -1, -1},
        {"USB adapter's 16 ms latency timer", 0, 0, 0.016, 0, -1, -1, -1},
        {"uniform 0..100 ms, 100 ppm drift", 0.1, 0, 0, 100, -1, -1, -1},
        {"uniform 0..100 ms, -100 ppm drift", 0.1, 0, 0, -100, -1, -1, -1},
        {"uniform 0..100 ms, restart at 15 s", 0.1, 0, 0, 0, 15, -1, -1},
        {"uniform 0..100 ms, 0.5 m outlier", 0.1, 0, 0, 0, -1, 150, -1},
        {"uniform 0..100 ms, carried 3 m", 0.1, 0, 0, 0, -1, -1, 20},
        {"fixed 16 ms", 0, 0.016, 0, 0, -1, -1, -1},
        {"30 ms bias, uniform 0..100 ms", 0.1, 0.030, 0, 0, -1, -1, -1},
    };
    size_t i;
    int old;
    printf("== the real line: 15 ms in the latency field, the transport's delay outside it (circle, 37 s at "
           "1 m/s, 50 Hz odometry; targets from arrival stamps: <= 3 mm RMS, p95 <= 5 mm, 0 restarts)\n");
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        for (old = 1; old >= 0; old--) {
            const line_case *c = &cases[i];
            fs_scenario sc;
            line_defaults(&sc);
            sc.extra_max = c->extra_max;
            sc.extra_fixed = c->extra_fixed;
            sc.ftdi_tick = c->ftdi_tick;
            sc.drift_ppm = c->drift_ppm;
            sc.restart_at = c->restart_at;
            sc.outlier = c->outlier;
            sc.kidnap_at = c->kidnap_at;
            sc.simulated = c->kidnap_at >= 0;
            sc.from_clock = !old;
            if (fs_run(ci, &sc, &res) != 0) {
                check(0, "run");
                continue;
            }
            if (c->kidnap_at >= 0 && !old)
                printf("   carried: largest error from 2 s after it %.2f mm\n", res.kidnap_err_2s * 1e3);
            line_row(old ? "arrival" : "time_ms", c, &res);
            if (old)
                continue;
            if (c->extra_fixed > 0) { /* the same for every frame: the pose lags by v x it */
                check(res.rms_fused <= c->extra_fixed * sc.v + 0.003, "a constant delay: more than its lag");
                check(res.stats.recoveries == 0, "a constant delay: a false restart");
                continue;
            }
            check(res.rms_fused <= 0.003, "real line: fused RMS above 3 mm");
            check(res.p95_fused <= 0.005, "real line: fused p95 above 5 mm");
            check(res.stats.clock_resets == (c->restart_at >= 0), "real line: clock resets miscounted");
            if (c->restart_at >= 0 || c->drift_ppm != 0)
                check(res.max_err_fused <= 0.005, "real line: restart or drift: error above 5 mm");
            if (c->outlier >= 0)
                check(res.stats.rejected == 1 && res.max_err_fused <= 0.020, "real line: outlier not rejected");
            if (c->kidnap_at >= 0)
                check(res.stats.recoveries == 1 && res.kidnap_err_2s < 0.010,
                      "real line: carried robot not back under 10 mm within 2 s");
            else
                check(res.stats.recoveries == 0, "real line: a false restart");
        }
}

/* A loaded controller (issue 38, measured against the stand-in with
 * ARIA): the odometry stamped when it is read, some reads stalled by the
 * machine (the pose then lags by speed x the stall: 58 mm at 1 m/s), some
 * samples lost on the line; the frames over the real line as above. The
 * read stamps as they are, and moved to the odometry's cycle
 * (rl_fuse_cycle). */
static void loaded_controller(const fs_drive *ci)
{
    static const double hz[2] = {10, 50};
    static const struct {
        const char *name;
        double late, stall_p, stall_max, lose_p;
    } cases[] = {
        {"reads 0..2 ms late, 5% stalled up to 80 ms", 0.002, 0.05, 0.08, 0},
        {"reads 0..2 ms late, 1% stalled up to 250 ms", 0.002, 0.01, 0.25, 0},
        {"reads 0..2 ms late, 1% of samples lost", 0.002, 0, 0, 0.01},
    };
    size_t i;
    int j, cyc;
    printf("== a loaded controller: the odometry stamped when read, frames over the real line (uniform "
           "0..100 ms); targets with the cycle: <= 3 mm RMS, p95 <= 5 mm, 0 restarts\n");
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        for (j = 0; j < 2; j++)
            for (cyc = 0; cyc <= 1; cyc++) {
                fs_scenario sc;
                char what[96];
                line_defaults(&sc);
                sc.extra_max = 0.1;
                sc.odo_hz = hz[j];
                sc.read_late = cases[i].late;
                sc.stall_p = cases[i].stall_p;
                sc.stall_max = cases[i].stall_max;
                sc.lose_p = cases[i].lose_p;
                sc.cycled = cyc;
                if (fs_run(ci, &sc, &res) != 0) {
                    check(0, "run");
                    continue;
                }
                snprintf(what, sizeof what, "%s, %2.0f Hz", cases[i].name, hz[j]);
                printf("%-56s %-10s fused %6.2f mm RMS, p95 %6.2f mm, max %6.2f mm | applied %lu rejected %lu "
                       "restarts %lu\n", what, cyc ? "cycle" : "read time", res.rms_fused * 1e3,
                       res.p95_fused * 1e3, res.max_err_fused * 1e3, res.stats.applied, res.stats.rejected,
                       res.stats.recoveries);
                if (!cyc)
                    continue;
                check(res.rms_fused <= 0.003, "loaded controller: fused RMS above 3 mm");
                check(res.p95_fused <= 0.005, "loaded controller: fused p95 above 5 mm");
                check(res.stats.recoveries == 0, "loaded controller: a false restart");
            }
}

int main(int argc, char **argv)
{
    static fs_drive st, ci, rect;
    if (argc != 7) {
        fprintf(stderr, "usage: test_fuse_drive FUSE_DIR FUSE_JSONL PATHS_DIR PATHS_JSONL PICTURE.png EXPORT_DIR\n");
        return 2;
    }
    if (fs_drive_load(&ci, argv[1], "circle", 38, argv[2], 0) != 0 ||
        fs_drive_load(&st, argv[3], "straight", 12, argv[4], 0) != 0 ||
        fs_drive_load(&rect, argv[3], "rect", 16, argv[4], 12) != 0)
        return 1;
    done_when_1(&ci);
    speeds(&st, &ci, &rect);
    stretch(&ci, 3, 2 * ci.length + 0.5, argv[5]);
    stretch(&rect, 2.6, 7.0, NULL);
    outlier_and_kidnap(&st, &ci);
    real_line(&ci);
    loaded_controller(&ci);
    {
        fs_scenario sc;
        fs_scenario_defaults(&sc);
        sc.laps = 2;
        sc.export_dir = argv[6];
        check(fs_run(&ci, &sc, &res) == 0, "export for ringloc fuse");
    }
    { /* the real line as `ringloc fuse --arrivals` takes it (EXPORT_DIR/line) */
        static char dir[1024];
        fs_scenario sc;
        line_defaults(&sc);
        sc.extra_max = 0.1;
        snprintf(dir, sizeof dir, "%s/line", argv[6]);
        sc.export_dir = dir;
        check(fs_run(&ci, &sc, &res) == 0, "export of the real line for ringloc fuse");
    }
    printf("%s\n", fails ? "FAILED" : "all targets met");
    return fails ? 1 : 0;
}
