/* rl_fuse: the controller's filter, wheel odometry fused with ringloc's
 * pose frames, late frames applied at their capture time.
 *
 * For the robot's controller (ARIA, ROS, a bare loop), not the camera
 * board: C99, no allocation, no stdio, libm only. The state is the pose
 * (x, y, yaw) and the odometry's two systematic errors, a distance scale
 * (the wheels' diameter) and a turn scale (the track width): an extended
 * Kalman filter whose past (the last odometry samples, each with the state
 * after it, in the caller's memory: rl_fuse_history_count) lets a frame
 * that arrives late be applied at the instant its image was taken, the
 * odometry since then replayed on top.
 * A frame the odometry and both covariances make implausible (Mahalanobis
 * gate) is rejected and counted; when `recover_frames` rejected frames in
 * a row agree with each other through the odometry between them, the robot
 * was carried: the filter restarts from them (counted too). With no frames
 * the pose goes on from the odometry, its covariance growing by the wheel
 * noise and the scales' uncertainty.
 *
 * Clocks. Every time is in seconds on ONE monotonic clock, the
 * controller's: odometry samples carry the time the wheels were read (ARIA:
 * the packet's receive time, not when it was processed), and each frame
 * its capture time on that clock. rl_fuse_msg_add finds that time itself
 * from the frame's time_ms (the camera board's clock, steady) and the
 * frame's arrival: the delays on the way are never negative, so the lowest
 * arrival - time_ms over time gives the offset between the two clocks and
 * its slope their drift (a crystal's 100 ppm); a firmware restart (time_ms
 * going back, the sequence going back or far ahead) or an offset that
 * changed is detected, counted (stats.clock_resets) and learned afresh
 * without restarting the pose. The controller must stamp each frame's
 * arrival on the clock of its odometry when it reads the frame (any thread,
 * any polling cycle: a delay that varies does not matter, nor the latency
 * timer of a USB serial adapter, nor a loaded kernel). What still matters:
 * a delay that is the same for every frame cannot be told from the clocks'
 * offset, and the pose then lags by speed x that delay (1 mm per ms at
 * 1 m/s): the frame's latency field and its bytes on the line are counted,
 * anything constant the controller adds is not; and a controller clock
 * that steps (wall time, NTP). Callers that know each capture time on
 * their clock give frames with rl_fuse_frame_add, as before (version 1
 * frames, which have no sigmas, work both ways).
 *
 *   rl_fuse_config cfg;
 *   static rl_fuse f;
 *   static rl_fuse_entry hist[256];       // or malloc: rl_fuse_history_count entries
 *   static rl_fuse_cycle cy;              // the odometry's packet cycle
 *   rl_fuse_pose p;
 *   rl_fuse_event ev;
 *   rl_msg m;                             // a decoded pose frame (rl_packet.h)
 *   rl_fuse_defaults(&cfg);
 *   cfg.track = 0.33;                     // the odometry's nominal track width, m
 *   if (rl_fuse_init(&f, &cfg, hist, rl_fuse_history_count(2.5, 50)) != RL_OK ||
 *       rl_fuse_cycle_init(&cy, 0.02) != RL_OK)  // a packet every 20 ms
 *       return;
 *   // read at 12.30 s: t (the packet's cycle), x, y, yaw
 *   if (rl_fuse_odometry(&f, rl_fuse_cycle_stamp(&cy, 12.30), 1.02, 0.51, 0.12) != RL_OK)
 *       return;
 *   memset(&m, 0, sizeof m);
 *   m.type = RL_PACKET_POSE;
 *   if (rl_fuse_msg_add(&f, &m, 12.31, 115200) != RL_OK) { // arrival time, baud
 *       rl_fuse_last_event(&f, &ev);      // ev.fate RL_FUSE_REJECTED: ev.d2
 *   }
 *   if (rl_fuse_pose_at(&f, 12.32, &p) == RL_OK)
 *       use(p.x, p.y, p.yaw, p.cov[0][0]);
 */
#ifndef RL_FUSE_H
#define RL_FUSE_H

#include <stddef.h>
#include "rl_error.h"
#include "rl_packet.h"


#ifdef __cplusplus
extern "C" {
#endif

#define RL_FUSE_N 5 /* state: x, y, yaw, distance scale, turn scale */

typedef struct {
    double track;        /* the odometry's nominal track width, m (0.33) */
    double wheel_noise;  /* each wheel's travel error after 1 m, m (sd grows as sqrt(distance);
                            0.0002: through 3 m without landmarks the error is 0.7 .. 1.2 times
                            the sigma reported, with wheels that noisy, test_fuse_drive) */
    double scale, turn;  /* the odometry's distance and turn scales at the start (1, 1): a warm
                            start gives those learned before (rl_fuse_pose.scale, .turn) */
    double scale_sigma;  /* the distance scale's uncertainty before any frame (0.03; after a
                            warm start, what a day may change: rl_fuse_pose.scale_sd or more) */
    double turn_sigma;   /* the turn scale's (0.05) */
    double scale_drift;  /* the two scales' random walk, sd per sqrt(m) driven (1e-4) */
    double time_sigma;   /* error of a frame's capture time, s (0.002): v*dt added to its sigma */
    double sigma_xy;     /* frame sigma (m) when the frame has none (version 1; 0.005) */
    double sigma_yaw;    /* frame sigma (rad) when the frame has none (0.005) */
    double floor_xy;     /* added in quadrature to every frame's sigmas: the map's error (0.0005 m) */
    double floor_yaw;    /* (0.0005 rad) */
    double gate;         /* Mahalanobis distance squared beyond which a frame is rejected
                            (16.27: 3 degrees of freedom, 1 in 1000 good frames lost) */
    int recover_frames;  /* rejected frames in a row that agree among themselves:
                            the robot was carried, restart from them (2; 0: never) */
    double max_extrapolate; /* s a pose is predicted past the last odometry (0.5) */
} rl_fuse_config;

/* A pose frame on the controller's clock. Sigmas 0: unknown (the
 * config's sigma_xy / sigma_yaw stand in). */
typedef struct {
    double t;            /* capture time, s */
    double x, y, yaw;    /* m, m, rad */
    double sx, sy, syaw; /* standard deviations */
    double st;           /* the capture time's, s, added to the config's time_sigma (0: none) */
} rl_fuse_frame;

/* What happened to the frames (nothing is dropped without a count). */
typedef struct {
    unsigned long applied;      /* frames fused */
    unsigned long rejected;     /* beyond the gate */
    unsigned long recoveries;   /* restarts after the robot was carried */
    unsigned long too_old;      /* older than the history */
    unsigned long out_of_order; /* older than a frame already fused */
    unsigned long waiting_lost; /* newer than the odometry, replaced by a newer one before it came */
    unsigned long clock_resets; /* the camera board restarted or its clock's offset changed
                                   (rl_fuse_msg_add): its clock learned afresh, the pose kept */
    unsigned long untimed;      /* not fused: the board's clock not yet known to 10 ms (the
                                   first second or so after a start or a reset) */
} rl_fuse_stats;

/* A frame's fate, as it is decided (rl_fuse_last_event). */
typedef enum {
    RL_FUSE_NONE = 0,      /* no frame's fate decided yet */
    RL_FUSE_APPLIED,       /* fused (or the first: it set the pose) */
    RL_FUSE_REJECTED,      /* beyond the gate: d2 is its squared Mahalanobis distance */
    RL_FUSE_RESTARTED,     /* rejected, but it agreed with the rejected frames before it:
                              the robot was carried, the pose restarted from it (d2 as above) */
    RL_FUSE_TOO_OLD,       /* older than the history */
    RL_FUSE_OUT_OF_ORDER,  /* not newer than a frame already fused */
    RL_FUSE_LOST,          /* waited for the odometry and was replaced by a newer frame */
    RL_FUSE_UNTIMED        /* not fused: the board's clock not yet known (rl_fuse_msg_add) */
} rl_fuse_fate;

typedef struct {
    unsigned long n;       /* frames whose fate was decided so far: a new event when it grows */
    rl_fuse_fate fate;
    double t;              /* the frame's capture time on the controller's clock, s */
    double d2;             /* squared Mahalanobis distance (APPLIED, REJECTED, RESTARTED) */
    int clock_reset;       /* this frame reset the board's clock (rl_fuse_msg_add) */
    unsigned seq;          /* its sequence number (rl_fuse_msg_add; else 0) */
} rl_fuse_event;

/* The camera board's clock as learned from the frames' arrivals (see
 * rl_fuse_msg_add); internal. */
#define RL_FUSE_CLOCK_SPANS 16
typedef struct {
    double start, c, y;    /* a span's first board time; its lowest arrival - capture */
} rl_fuse_clock_pt;

typedef struct {
    rl_fuse_clock_pt low[RL_FUSE_CLOCK_SPANS];
    int head, count;       /* newest span at head */
    double a, b, c0;       /* controller time = board time + a + b (board time - c0) */
    double excess;         /* the typical delay beyond the envelope, s */
    double spread;         /* the spans' lowest points' mean gap above it, s */
    int excess_n;
    long n;                /* frames since the clock (re)started */
    int late;              /* frames in a row far later than the envelope */
    uint32_t last_ms;
    uint16_t last_seq;
} rl_fuse_clock;

typedef struct {
    double t;
    double o[3];               /* the odometry's pose: x, y, yaw */
    double m[RL_FUSE_N];       /* the state after this sample */
    double P[RL_FUSE_N][RL_FUSE_N];
    int valid;                 /* 0 before the first frame */
} rl_fuse_entry;

/* The filter; fields are internal (read stats, or use the functions). */
typedef struct {
    rl_fuse_config cfg;
    rl_fuse_entry *h;                 /* ring of odometry samples (the caller's) */
    int cap;                          /* its entries */
    int head, count;                  /* newest at head */
    rl_fuse_entry anchor;             /* the state just after the last fused frame */
    int has_pose;                     /* a frame has given the pose */
    double last_frame_t;              /* capture time of the last fused frame */
    rl_fuse_frame cand;               /* the last rejected frame: carried? */
    int n_cand;                       /* rejected frames in a row that agree, up to cand */
    rl_fuse_frame waiting;            /* a frame newer than the odometry */
    int has_waiting;
    rl_fuse_stats stats;
    rl_fuse_clock clock;              /* the camera board's (rl_fuse_msg_add) */
    rl_fuse_event event;              /* the last frame's fate */
    unsigned pending_seq, waiting_seq; /* the sequence numbers of the frame being added */
    int pending_reset, waiting_reset;  /* and of the waiting one; did it reset the clock */
} rl_fuse;

/* The fused pose at a time. */
typedef struct {
    double t;
    double x, y, yaw;
    double cov[3][3];     /* of x, y, yaw */
    double scale, turn;   /* the odometry's learned distance and turn scales */
    double scale_sd, turn_sd;
    double v, w;          /* the fused velocity: forward, m/s, and turn rate, rad/s (the
                             odometry's around t, times the learned scales) */
} rl_fuse_pose;

/* Every field of cfg at its default (in parentheses above). */
void rl_fuse_defaults(rl_fuse_config *cfg);

/* The entries a history needs to take frames up to `seconds` late (their
 * capture before the newest odometry sample) at `odo_hz` odometry samples
 * a second: 2.5 s at 50 Hz, 127 entries (about 32 kB). Older frames are
 * counted in rl_fuse_stats.too_old. 0 for values out of range. */
size_t rl_fuse_history_count(double seconds, double odo_hz);

/* Empty filter keeping its past in hist (n entries, the caller's, for as
 * long as f is used); RL_EINVAL for a config out of its domain (track,
 * noises, gate not positive) or fewer than 2 entries. */
RL_CHECK rl_err rl_fuse_init(rl_fuse *f, const rl_fuse_config *cfg, rl_fuse_entry *hist, size_t n);

/* One odometry sample: the robot's own dead-reckoned pose (m, rad) at time
 * t, at any rate. RL_EINVAL when t does not increase or a value is not
 * finite (the sample is ignored). The oldest sample falls out of the
 * history. A waiting frame whose time the odometry has now passed is fused. */
RL_CHECK rl_err rl_fuse_odometry(rl_fuse *f, double t, double x, double y, double yaw);

/* A frame: fused at its capture time and the odometry since replayed
 * (RL_OK); or kept until the odometry reaches its time (RL_OK); or
 * rejected by the gate (RL_ERANGE, counted; a restart when it agrees with
 * the rejected frames before it, then RL_OK); or older than the history
 * or than the last fused frame (RL_ERANGE, counted); RL_EINVAL when not
 * finite. The first frame sets the pose. */
RL_CHECK rl_err rl_fuse_frame_add(rl_fuse *f, const rl_fuse_frame *fr);

/* The pose at time t: interpolated inside the history (before the last
 * fused frame's capture: that frame's state moved back through the
 * odometry), predicted past its newest sample (at the speed and turn rate
 * of the last 0.15 s of odometry, at most max_extrapolate). RL_ENOTFOUND
 * before the first frame, RL_ERANGE for a time before the history (or
 * past the extrapolation limit: *p then holds the pose at the limit). */
RL_CHECK rl_err rl_fuse_pose_at(const rl_fuse *f, double t, rl_fuse_pose *p);

/* A decoded pose frame (rl_packet.h), and its arrival on the controller's
 * clock (s: when its last byte was read), through the camera board's
 * clock: the frame's capture time is its time_ms moved by the offset and
 * drift learned from the arrivals (see "Clocks" above), then as
 * rl_fuse_frame_add (same returns; RL_EINVAL for a frame that is not a
 * pose). baud: the line's, for the frame's bytes (0: not counted). */
RL_CHECK rl_err rl_fuse_msg_add(rl_fuse *f, const rl_msg *m, double arrival, int baud);

/* The last frame whose fate was decided (by rl_fuse_frame_add,
 * rl_fuse_msg_add, or rl_fuse_odometry for a frame that waited for it). A
 * caller that wants every event compares ev->n with the last it saw. */
void rl_fuse_last_event(const rl_fuse *f, rl_fuse_event *ev);

/* A decoded pose frame (rl_packet.h) as a frame on the controller's clock,
 * for callers that trust their arrival stamps (rl_fuse_msg_add does not):
 * capture = arrival - latency - the frame's bytes at baud (10 bits a byte).
 * Version 1 frames have no sigmas (0: the config's stand in). */
void rl_fuse_frame_from_msg(const rl_msg *m, double arrival, int baud, rl_fuse_frame *fr);

/* Odometry read late. A robot's controller reports its odometry on a
 * fixed cycle (ARCOS: a server information packet every 100 ms, on the
 * controller's crystal), and the program stamps each packet when it reads
 * it (ARIA: getLastOdometryTime). A loaded machine reads some of them late
 * (tens of ms: the pose then lags by speed x that), so the read stamps are
 * moved to the cycle's lower envelope (the reads that met the least delay,
 * its slope the crystals' drift), as for the frames' arrivals; the reads
 * queued behind a stalled one get their cycles' times too. A read a whole
 * number of cycles late, as closely as reads usually lie on the envelope
 * (a few ms), may be the packet after one lost on the line or a stall that
 * long: it is given its read time; when the next read is late too, the
 * cycles are counted in as lost. For the first 2 s of cycles (a program's
 * first reads come in a burst) and until the envelope is known, the read
 * time is given as it is.
 *
 *   static rl_fuse_cycle cy;
 *   rl_fuse_cycle_init(&cy, 0.1);         // ARCOS's 100 ms
 *   // for each odometry packet, read at `read` on the controller's clock:
 *   if (rl_fuse_odometry(&f, rl_fuse_cycle_stamp(&cy, read), x, y, yaw) != RL_OK) ...
 */
typedef struct {
    rl_fuse_clock clock;   /* the cycle's envelope: cycle k at board time k x period */
    double period;         /* s */
    double last;           /* the last stamp given */
    double prev_read;      /* the last read time */
    uint32_t k;            /* the next sample's cycle */
    int late;              /* reads in a row whole periods after the envelope */
    int known;             /* the envelope known to a quarter period */
    unsigned long lost;    /* cycles counted in as lost on the line */
} rl_fuse_cycle;

/* Empty: no sample read yet, a cycle of `period` s (RL_EINVAL unless
 * 0 < period <= 10). */
RL_CHECK rl_err rl_fuse_cycle_init(rl_fuse_cycle *c, double period);

/* The time of the sample read at `read` (s, the controller's clock):
 * its place on the cycle's envelope, always later than the last stamp
 * given (the read time itself while the envelope is not known). */
double rl_fuse_cycle_stamp(rl_fuse_cycle *c, double read);

#ifdef __cplusplus
}
#endif

#endif
