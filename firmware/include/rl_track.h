/* rl_track: tracking windows, a frame read only where the map's landmarks
 * must be.
 *
 * A robot does not see a new world every frame. From the last pose, the
 * motion since (an odometry delta, or a constant velocity from the last
 * two poses), the map, the camera and its mount, rl_track_plan predicts
 * each map landmark's image centre, radius and id in the next frame
 * (those entering across the border too). rl_track_read reads only there,
 * the predictions in an order that spreads them over the frame: each first
 * verified where predicted (its centre drawn to its ink, its profile
 * judged by the global pass's rule against every id, or, for a landmark
 * known from the frame before (read there by windows, or by the full
 * frame, its pose taken) whose id scores 0.94 or more where the map
 * holds rivals of its id, against those rivals alone, and refused
 * where a zone twin fits as well at its own radius: rl_verify; next to the border,
 * from its visible edge: rl_verify_read_border), else as
 * the global pass reads a candidate whose box is the prediction, else,
 * for a landmark about whole (unless the box read named another id at a
 * circle whole in the frame, in a whole window: the frame is then read in
 * full), as the local pass reads
 * one (a window with its own threshold, rl_local; for one the border cuts,
 * only while fewer than 3 were read); a read is kept only when it names the
 * predicted id within max_first_shift radii (the first) or max_shift
 * radii (the next ones, their predictions moved by the shift and turn
 * the reads so far show: a rocking robot). A full frame (rl_recog_run)
 * instead: every full_every-th frame, with no recent pose, when a whole
 * landmark's window is not read back (the same frame is then read in
 * full), and when the pose jumps from its prediction (the robot carried).
 * Landmarks cut by the border (less than window_visible in view), and
 * those past max_reads, wait for the next full frame: no landmark a full
 * frame reads is lost for longer than full_every frames, and no id is
 * taken that the recognizer's own rules would not take (the frame's reads
 * go through the zone twins' check, rl_twins, as a full frame's: a read it
 * refuses is missed; a landmark whose read the check kept in the frame
 * before, read by windows with its pose taken, is not judged again).
 *
 * Allocation-free: the tracker is the caller's struct.
 *
 *   rl_track trk;
 *   rl_track_config tc;
 *   rl_mount mount;
 *   rl_pose pose = {0};                            // the frame's pose, once solved
 *   double t = 0.1;                                // the frame's time, s
 *   int ok = 0, pose_ok = 0;
 *   rl_mount_defaults(&mount, 0.88);
 *   rl_track_defaults(&tc);                        // a full frame every 10th
 *   rl_track_init(&trk, &tc);
 *   if (rl_track_plan(&trk, &cam, &mount, &map, t, NULL) &&
 *       rl_track_read(&trk, rec, &img, &res, &ok) == RL_OK && ok)
 *       use(res.n_landmarks);                      // the windows' landmarks
 *   else if (rl_recog_run(rec, &img, &res) == RL_OK)
 *       rl_track_full(&trk, &res);
 *   // ... the pose from res (pose_ok); a tracked frame whose pose jumped is read again:
 *   if (rl_track_pose(&trk, pose_ok ? &pose : NULL, t) && rl_recog_run(rec, &img, &res) == RL_OK)
 *       rl_track_full(&trk, &res);
 */
#ifndef RL_TRACK_H
#define RL_TRACK_H

#include "rl_calib.h"
#include "rl_config.h"
#include "rl_error.h"
#include "rl_map.h"
#include "rl_pose.h"
#include "rl_recog.h"

typedef struct {
    int full_every;      /* a full frame at least every this many frames (10); 0: tracking off */
    double max_age;      /* a last pose older than this is not tracked from, s (0.5) */
    double max_jump;     /* a tracked frame's pose this far from its prediction is a jump, m (0.2) */
    double max_jump_yaw; /* the same for the heading, rad (0.35) */
    double min_visible;  /* landmarks predicted at least this much in the frame are read (0.5) */
    int max_reads;       /* at most this many landmarks read per tracked frame, spread over
                            the frame (the rest wait for the next full frame): a cap on a
                            tracked frame's cost; 0 (default): every one in view */
    double max_first_shift; /* the frame's first read may lie this many radii from its
                               prediction (1.5: the robot's rocking moves the image) */
    double max_shift;    /* the next ones, from their predictions moved as the reads so far
                            moved, radii (1.0) */
    double window_visible; /* a landmark at least this much in view that its box does not read
                              is read in a window of its own (0.9: about whole ones; ones cut
                              more wait for the full frame, whose local pass reads them) */
} rl_track_config;

/* The robot's motion since the last pose, in that pose's robot frame
 * (odometry), m and rad. */
typedef struct {
    double dx, dy, dyaw;
} rl_track_motion;

/* One predicted landmark: its map entry, id, image centre and radius. */
typedef struct {
    int index, id;
    double u, v, radius; /* px */
    double visible;      /* fraction of its disk in the frame */
} rl_track_window;

typedef struct {
    rl_track_config cfg;
    int have, have_prev;          /* poses known */
    double x, y, yaw, t;          /* the last pose and its time, s */
    double px, py, pyaw, pt;      /* the one before */
    double ex, ey, eyaw;          /* the pose predicted for this frame */
    int since_full;               /* frames since the last full frame */
    int full_next;                /* 1: the next frame is read in full */
    int have_levels;
    rl_levels levels;             /* the last full frame's levels */
    int tracked;                  /* 1: this frame was read by windows */
    int n;                        /* this frame's predictions */
    rl_track_window win[RL_MAX_LANDMARKS];
    /* map entries (rl_track_window.index) whose read kept its id through
     * the zone twins' check in the last frame, read by windows and its
     * pose taken (known); this frame's, until its pose is (seen). They
     * index the map rl_track_plan was given: a caller that changes the
     * map calls rl_track_init first */
    int known[RL_MAX_LANDMARKS], n_known, seen[RL_MAX_LANDMARKS], n_seen;
    /* map entries a full frame read, its pose taken (named; the frame
     * after it is the first by windows): judged as known by rl_verify
     * (their ids against their rivals) but not passed unjudged by the
     * zone twins' check. The full frame's reads (their ids and centres)
     * are kept until rl_track_plan names their map entries (full_reads
     * 1: to be named) */
    int named[RL_MAX_LANDMARKS], n_named, full_reads, n_full, full_id[RL_MAX_LANDMARKS];
    double full_u[RL_MAX_LANDMARKS], full_v[RL_MAX_LANDMARKS];
    /* the map entries of this frame's reads that kept their ids unjudged
     * as known (none after rl_track_full): what a log shows of the
     * shortcut, for a test to judge against the truth */
    int unjudged[RL_MAX_LANDMARKS], n_unjudged;
    long frames_tracked, frames_full, fallbacks; /* counts */
} rl_track;

/* Fill every field with its default. */
void rl_track_defaults(rl_track_config *cfg);

/* A tracker with no pose yet (its first frame is full); also after the
 * map given to rl_track_plan changes (its known landmarks are the map's
 * entries). */
void rl_track_init(rl_track *t, const rl_track_config *cfg);

/* Whether the frame at time t_s (s) can be read by windows; if so its
 * predictions are in t->win (none for a landmark predicted too small for
 * an id of the map's family: the recognizer must use the map's family). odom: the motion since the last pose, or
 * NULL for a constant velocity from the last two poses. 0 (read it in
 * full) when tracking is off, a full frame is due, there is no recent
 * pose, or fewer than two whole landmarks are predicted in view. */
int rl_track_plan(rl_track *t, const rl_calib *cam, const rl_mount *mount, const rl_map *map, double t_s,
                  const rl_track_motion *odom);

/* Read the planned windows of img into res (cleared first; the last full
 * frame's levels): the landmarks whose read names the predicted id within
 * max_shift radii of the prediction. *ok = 1 when every whole landmark
 * predicted was read back and at least two were; 0: the prediction failed,
 * read the frame in full. RL_EINVAL for bad arguments or a frame of
 * another size than rec's. */
RL_CHECK rl_err rl_track_read(rl_track *t, rl_recog *rec, const rl_image *img, rl_result *res, int *ok);

/* A full frame was read into res (the levels kept for the windows). */
void rl_track_full(rl_track *t, const rl_result *res);

/* The frame's pose (NULL: none) at time t_s: remembered for the next
 * prediction. Returns 1 when the frame was read by windows and its pose
 * jumped from the prediction (or it has none): the caller reads the same
 * frame in full (rl_track_plan returns 0 for it; the caller calls
 * rl_track_full, then this again). */
int rl_track_pose(rl_track *t, const rl_pose *pose, double t_s);

#endif
