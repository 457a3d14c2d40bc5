/* rl_place: which map landmarks a frame sees, on a site that repeats ids.
 *
 * A large site reuses a small family's ids; planned so that no two places
 * show the same constellation (ringloc plan --area), one frame still says
 * where the robot is. At start-up an index is built in the caller's
 * workspace over the map's landmark pairs closer than `reach` (their ids
 * and distance) and over the map's area (a grid of cells). Per frame each
 * identified landmark is put on the ceiling of a level robot (on a map whose
 * landmarks have their own heights, z, each is scaled to the height of the
 * map landmark it is tried as: rl_place_obs.h); pairs of them
 * look up the map pairs with the same ids and distance, each proposing a
 * place (a rigid motion), and each place is verified against every other
 * identified landmark: it counts the landmarks that land within `gate` of a
 * map landmark of their own id. The best place is taken only when at least
 * `min_landmarks` verify and it leads every other place by `margin`;
 * otherwise RL_EAMBIGUOUS. The proposals come first from three landmarks
 * close together: a place that verifies all but one landmark of the frame
 * verifies two of those three, so it is among their proposals; when the
 * best place leaves a landmark unverified every indexed pair proposes.
 *
 * Tracking: given the previous pose and its age, places are first sought
 * within max_speed * age and max_turn * age of it, from the map landmarks
 * of each id near where the previous pose puts them (no index needed): two
 * landmarks suffice, and the place is taken when no other place within the
 * bound verifies as many. One that leaves more than half of the frame's
 * landmarks unverified is taken only when the whole map, searched as if
 * there were no prior, gives no clear place (two ids that happen to lie
 * near where the prior puts them, while the rest of the frame verifies
 * nowhere near, are a coincidence of a map whose ids repeat). Otherwise
 * (a robot carried elsewhere) the frame is searched as if there were no
 * prior. A place once found is kept: when that search gives no clear
 * place either (two landmarks verify at several places of the map) and
 * the robot turned faster than max_turn (a corner taken briskly), the
 * map's places are gated by the prior: the one within max_speed * age of
 * it, at any heading, that leads every other there is taken (tracked).
 *
 *   static uint8_t mem[1 << 20];
 *   rl_place_config pc;
 *   rl_place *pl;
 *   rl_place_prior prior = {0};             // or the previous pose and its age
 *   rl_place_found found;
 *   rl_pose pose;
 *   rl_mount mount;
 *   rl_mount_defaults(&mount, 0.88);
 *   rl_place_defaults(&pc);
 *   if (rl_place_size(&map, &pc) > sizeof mem || rl_place_init(&pl, &map, &pc, mem, sizeof mem) != RL_OK)
 *       return;
 *   rl_err e = rl_place_solve(pl, &cam, &mount, res.landmarks, res.n_landmarks, NULL, &prior, &pose, &found);
 *   if (e == RL_OK)
 *       use(pose.x, pose.y, found.verified);
 *   else if (e == RL_EAMBIGUOUS)
 *       use(found.verified, found.runner_up); // several places fit
 */
#ifndef RL_PLACE_H
#define RL_PLACE_H

#include <stddef.h>
#include "rl_calib.h"
#include "rl_config.h"
#include "rl_error.h"
#include "rl_map.h"
#include "rl_pose.h"
#include "rl_recog.h"

typedef struct {
    double reach;      /* longest map pair indexed, m (0: 2.05 times the map's
                          typical nearest-neighbour distance: neighbours and
                          diagonals and the next ones of a square grid) */
    double gate;       /* a landmark verifies within this of its map place, m
                          (0: 0.15 m, at most a quarter of that distance) */
    int min_landmarks; /* landmarks that must verify without a prior (3) */
    int margin;        /* verified landmarks the best leads every other place by (2) */
    double max_speed;  /* tracking: fastest the robot moves, m/s (1.5) */
    double max_turn;   /* tracking: fastest it turns, rad/s (3.0) */
    double track_age;  /* tracking: a previous pose older than this is not used, s (2.0) */
} rl_place_config;

/* The previous pose, for tracking (valid 0: none). */
typedef struct {
    int valid;
    double x, y, yaw; /* robot pose in the map, m and rad */
    double age;       /* seconds since the frame it came from */
} rl_place_prior;

enum {
    RL_PLACE_NONE = 0,   /* fewer than two identified landmarks */
    RL_PLACE_FOUND,      /* from the frame alone */
    RL_PLACE_TRACKED,    /* near the previous pose */
    RL_PLACE_AMBIGUOUS   /* several places fit, or too few landmarks verify */
};

typedef struct {
    int status;          /* RL_PLACE_* */
    int verified;        /* landmarks the best place verified */
    int runner_up;       /* the most any other place verified */
    int candidates;      /* places proposed and verified */
    double x, y, yaw;    /* the best place: the level robot's pose, m and rad */
    int match[RL_MAX_LANDMARKS]; /* per detection: its map landmark, or -1 */
} rl_place_found;

typedef struct rl_place rl_place;

void rl_place_defaults(rl_place_config *cfg);

/* Workspace bytes for the map's index; 0 for a map rl_map_check refuses,
 * a bad configuration or more than 65535 landmarks. */
size_t rl_place_size(const rl_map *map, const rl_place_config *cfg);

/* Build the index in mem[0..size); the map must stay in place while *pl is
 * used. RL_ENOMEM when size is less than rl_place_size(); RL_EINVAL for a
 * bad map or configuration. */
RL_CHECK rl_err rl_place_init(rl_place **pl, const rl_map *map, const rl_place_config *cfg, void *mem,
                              size_t size);

/* Index bytes (what rl_place_size asked for) and map pairs indexed. */
size_t rl_place_bytes(const rl_place *pl);
long rl_place_pairs(const rl_place *pl);

/* Which map landmark each of the n detections is: found->match. RL_OK
 * with a place, RL_EAMBIGUOUS when none is clear, RL_ETOOFEW with fewer
 * than two detections on the ceiling, RL_EINVAL for bad arguments.
 * prior may be NULL. */
RL_CHECK rl_err rl_place_find(const rl_place *pl, const rl_calib *cam, const rl_mount *mount,
                              const rl_detection *lm, int n, const rl_offsets *offsets,
                              const rl_place_prior *prior, rl_place_found *found);

/* rl_place_find, then rl_pose_solve_matched with what it found. */
RL_CHECK rl_err rl_place_solve(const rl_place *pl, const rl_calib *cam, const rl_mount *mount,
                               const rl_detection *lm, int n, const rl_offsets *offsets,
                               const rl_place_prior *prior, rl_pose *pose, rl_place_found *found);

#endif
