/* fuse_sim: a robot driving the renderer's paths, for the rl_fuse tests.
 * The truth is the renderer's path geometry (checked against each rendered
 * frame's truth); the odometry is a differential drive with a wheel scale
 * and a track width off and each wheel's travel noisy, integrated at 1 kHz
 * and sampled at a rate; the pose frames are the firmware's on the
 * rendered frames (or the truth plus their measured sigmas' noise), each
 * arriving a fixed delay after its capture (the frame's latency field)
 * with the arrival stamp jittered, plus a transport delay the field does
 * not carry (uniform, fixed, or a USB adapter's latency timer); time_ms on
 * the camera board's clock (drifting, restarting) for rl_fuse_msg_add.
 * A controller ticks every 10 ms: rl_fuse and today's reset-on-arrival
 * (the pose set to each frame when it arrives, odometry on top), both
 * compared with the truth at every tick.
 *
 *   fs_drive d;
 *   fs_scenario sc;
 *   static fs_result r;
 *   fs_scenario_defaults(&sc);
 *   if (fs_drive_load(&d, "dir", "circle", 38, "poses.jsonl", 0) == 0 && fs_run(&d, &sc, &r) == 0)
 *       printf("%.2f mm\n", r.rms_fused * 1e3);
 */
#ifndef FUSE_SIM_H
#define FUSE_SIM_H

#include "rl_fuse.h"

#define FS_MAX_FRAMES 128
#define FS_MAX_TICKS 4000 /* 40 s of 10 ms ticks */

typedef struct {
    double x, y, yaw;
} fs_pose;

/* a rendered drive and the firmware's frames on it */
typedef struct {
    char kind[16];     /* straight, rect, circle */
    int n;             /* frames rendered along it */
    double length;     /* m, one lap of a closed drive */
    int closed;
    fs_pose truth[FS_MAX_FRAMES]; /* the renderer's, per frame */
    fs_pose meas[FS_MAX_FRAMES];  /* the firmware's */
    double sx[FS_MAX_FRAMES], sy[FS_MAX_FRAMES], syaw[FS_MAX_FRAMES];
    double latency[FS_MAX_FRAMES]; /* s, capture -> send, measured by the firmware */
} fs_drive;

typedef struct {
    double v;            /* m/s */
    double odo_hz;       /* odometry samples a second */
    double delay;        /* capture -> send of a frame, s: in its latency field */
    double jitter;       /* the arrival stamp's error, uniform +-, s */
    /* the transport, outside the latency field (a frame never overtakes
     * the one before it on the line): */
    double extra_max;    /* a delay uniform in 0 .. this, s (a reader's polling, a loaded kernel) */
    double extra_fixed;  /* a constant delay, s */
    double ftdi_tick;    /* a USB adapter's latency timer: held to its next tick, s (0: none) */
    int from_clock;      /* frames through rl_fuse_msg_add (the board's time_ms and the
                            arrival) rather than capture = arrival - latency - line time */
    double drift_ppm;    /* the board's clock runs fast by this */
    double restart_at;   /* s: the firmware restarts (time_ms and seq from 0, 0.5 s without
                            frames); < 0 never */
    double laps;         /* of a closed drive (the frames reused lap after lap) */
    double gap_from, gap_to; /* distance driven (m) between which no frame comes */
    int outlier;         /* frame (in order of capture) replaced by the truth + 0.5 m; -1 none */
    double kidnap_at;    /* distance (m) where the robot is carried 3 m; < 0 never */
    int simulated;       /* frames = truth + noise of the measured sigmas */
    double scale_err;    /* true distance / odometry's (1.01) */
    double track_err;    /* true track / nominal (1.02) */
    double wheel_noise;  /* m per sqrt(m) of each wheel's travel (0.0002) */
    /* the controller reading the odometry (stamped when read, as ARIA does): */
    double read_late;    /* every read late by uniform 0 .. this, s */
    double stall_p;      /* the chance a read is stalled (a loaded machine) ... */
    double stall_max;    /* ... by uniform 0 .. this more, s (the samples behind it wait) */
    double lose_p;       /* the chance a sample is lost on the line (never read) */
    int cycled;          /* the read stamps moved to the cycle's envelope (rl_fuse_cycle) */
    double warmup;       /* s from the start the filter learns the scales, left out of the figures (1) */
    double track;        /* nominal track, m */
    unsigned seed;
    const char *export_dir; /* when set: odometry.txt, frames.bin and truth.txt written there */
} fs_scenario;

typedef struct {
    int n;                         /* ticks compared (from the first frame's arrival) */
    double t[FS_MAX_TICKS];
    fs_pose truth[FS_MAX_TICKS], fused[FS_MAX_TICKS], reset[FS_MAX_TICKS];
    double cov[FS_MAX_TICKS][3];   /* fused xx, xy, yy */
    int in_gap[FS_MAX_TICKS];      /* tick inside the stretch without frames */
    int corner[FS_MAX_TICKS];      /* within an odometry period after a corner (rect) */
    double rms_fused, rms_reset;   /* m */
    double max_err_fused, max_step; /* m; step: error change between consecutive ticks */
    double max_yaw, rms_yaw;       /* rad */
    double t_max_step, t_max_yaw;  /* s, when the largest were */
    double warm_max_err, warm_max_step, warm_max_yaw; /* in the warm-up */
    double gap_max_err, gap_dist;  /* in the stretch: largest error, m driven */
    double kidnap_err;             /* error after the second frame since the kidnap */
    double kidnap_err_2s;          /* largest error from 2 s after the kidnap on */
    double p95_fused;              /* m, over the ticks of rms_fused */
    double mean_latency;           /* the firmware's, s */
    rl_fuse_stats stats;
    double scale, turn;            /* learned at the end */
} fs_result;

void fs_scenario_defaults(fs_scenario *sc);

/* the truth of a drive at distance s (closed drives wrap) */
void fs_truth_at(const fs_drive *d, double s, fs_pose *p);

/* A drive rendered with n frames under dir (KIND_NNN.yaml) and the
 * firmware's frames on it: the JSON lines of `ringloc monitor`, the
 * first `skip` pose lines belonging to other drives. 0, or -1 with a line
 * on stderr; checks the path geometry against each frame's truth. */
int fs_drive_load(fs_drive *d, const char *dir, const char *kind, int n, const char *jsonl, int skip);

/* One drive under a scenario; 0 or -1 (too long for FS_MAX_TICKS). */
int fs_run(const fs_drive *d, const fs_scenario *sc, fs_result *r);

#endif
