/* rl_survey: the map from recorded frames (`ringloc survey`).
 *
 * Each frame goes in as its identified landmarks: the ideal normalized
 * image of each centre (rl_calib_centre) and of its radius
 * (rl_calib_radius). rl_survey_build tells which observations are the
 * same landmark (its id and, where a site repeats ids, its place), and
 * makes first poses and positions from the level model, frame by frame;
 * rl_survey_adjust (Ceres, rl_survey_adjust.cpp) then estimates every
 * landmark's position, the ceiling's height and every frame's pose and
 * tilt together by robust least squares over all observations, with the
 * landmarks' covariances; a landmark off the ceiling's plane (its own
 * height, estimated once with the plane held, 3 cm and five sigmas off
 * it) gets its own height z in the fit. The map frame: the origin landmark at (0, 0),
 * the axis landmark on +x; the scale from the landmarks' printed
 * diameter (their image radii), or from a known ceiling height or
 * origin-axis distance.
 *
 *   rl_survey sv;
 *   rl_survey_config cfg;
 *   rl_survey_obs seen[2] = {{25, 0.010, -0.020, 0.056, 1.0}, {7, 0.310, 0.020, 0.055, 1.0}};
 *   rl_survey_defaults(&cfg);
 *   cfg.origin_id = 25;
 *   cfg.axis_id = 7;
 *   rl_survey_init(&sv, &cfg);
 *   if (rl_survey_add_frame(&sv, "a.png", seen, 2) == RL_OK && rl_survey_build(&sv) == RL_OK &&
 *       rl_survey_adjust(&sv) == RL_OK)
 *       use(sv.n_lm, sv.height, sv.lm[0].x);
 *   else
 *       use(sv.err);
 *   rl_survey_free(&sv);
 */
#ifndef RL_SURVEY_H
#define RL_SURVEY_H

#include "rl_error.h"
#include "rl_pose.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int id;
    double xn, yn; /* ideal normalized image of the landmark's centre */
    double rn;     /* its radius, normalized; 0: not used (cut by the border) */
    double noise;  /* the centre's noise in units of pixel_sigma (1; more for a cut one) */
} rl_survey_obs;

typedef struct {
    rl_mount mount;        /* the camera on the robot (robot.yaml) */
    double diameter;       /* printed outer diameter, m */
    int origin_id;         /* at (0, 0) */
    int axis_id;           /* on +x */
    double ceiling_height; /* > 0: known, the scale from it; 0: estimated */
    double axis_distance;  /* > 0: origin to axis, measured, the scale from it */
    double pixel_scale;    /* px per normalized unit: sqrt(fx fy) */
    double pixel_sigma;    /* a centre's noise, px (RL_POSE_PIXEL_SIGMA) */
    double radius_sigma;   /* a radius's noise, px (0.15) */
    double tilt_sigma;     /* a prior on every frame's tilt, rad (0.05): the survey's own, wider than
                              robot.yaml's rocking, since it solves each frame's tilt with the rest */
    double gate;           /* how far from where a frame's pose puts it a landmark of
                              the same id is still taken as the same one, m (0.3) */
    int min_views;         /* frames that must see a landmark to place it (2) */
} rl_survey_config;

enum { /* rl_survey_frame.status */
    RL_SURVEY_USED = 0,
    RL_SURVEY_FEW,     /* fewer than two landmarks */
    RL_SURVEY_LOST,    /* its landmarks fit no place of the others */
    RL_SURVEY_OUTLIER  /* its centres disagree with the map the others made */
};

enum { /* rl_survey_landmark.status */
    RL_SURVEY_PLACED = 0,
    RL_SURVEY_RARE /* seen in fewer than min_views frames: not placed */
};

typedef struct {
    char *name;
    int first, n;                  /* its observations: obs[first .. first + n) */
    int status;
    double x, y, yaw, roll, pitch; /* robot pose, and its tilt (roll, pitch), m and rad */
} rl_survey_frame;

typedef struct {
    int id;
    double x, y;   /* map frame, m */
    double cov[3]; /* covariance xx, xy, yy, m^2 */
    double z, sigma_z; /* off the ceiling's plane: its own height above the floor and its
                          standard deviation, m (0: on the plane) */
    int views;     /* frames used that saw it */
    int status;
} rl_survey_landmark;

typedef struct {
    rl_survey_config cfg;
    rl_survey_obs *obs;
    int n_obs, cap_obs;
    int *obs_lm; /* the landmark each observation is (index into lm), -1: none (rl_survey_build) */
    rl_survey_frame *fr;
    int n_fr, cap_fr;
    rl_survey_landmark *lm; /* rl_survey_build */
    int n_lm;
    double height, sigma_height; /* ceiling above the floor and its standard deviation, m */
    double rms_px;               /* RMS image residual of the centres used, px */
    int frames_used, obs_used;  /* in the fit */
    int n_alone, alone[64];      /* ids seen only in frames by themselves (the first 64) */
    char err[256];
} rl_survey;

/* Defaults: the spec's mount at 0.88 m, a 0.21 m diameter, the noise
 * figures above; origin and axis ids 0 (the caller must set them). */
void rl_survey_defaults(rl_survey_config *cfg);

void rl_survey_init(rl_survey *sv, const rl_survey_config *cfg);

/* Copy one frame's observations in (name copied). RL_ENOMEM. */
RL_CHECK rl_err rl_survey_add_frame(rl_survey *sv, const char *name, const rl_survey_obs *obs, int n);

/* Associate and make the first map (rl_survey_build.c). RL_ETOOFEW when
 * the origin or the axis landmark was never placed (err says which). */
RL_CHECK rl_err rl_survey_build(rl_survey *sv);

/* The joint robust fit and the covariances: rl_survey_adjust_ceres
 * (rl_survey_adjust.cpp), in the module ringloc-ceres.so that this loads
 * on first use (rl_survey_adjust_load.c). RL_ERANGE when the solver fails
 * or the result is not finite, RL_EUNSUPPORTED when the module cannot be
 * loaded (err says why). */
RL_CHECK rl_err rl_survey_adjust(rl_survey *sv);
typedef rl_err (*rl_survey_adjust_fn)(rl_survey *sv);

/* RL_OK when the solver's module (ringloc-ceres.so) can be loaded, else
 * err says why: checked before a survey reads its frames. */
RL_CHECK rl_err rl_survey_solver_check(char *err, size_t errlen);

void rl_survey_free(rl_survey *sv);

#ifdef __cplusplus
}
#endif

#endif
