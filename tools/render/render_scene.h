/* render_scene: what one frame shows, as the renderer's modules share it:
 * the camera (its calibration, pose and tilt), the ceiling (tiles and
 * their phase, its brightness), the objects on it (landmarks on their
 * sheets, lights, clutter: later ones lie on top) and the frame's looks
 * (exposure, blur, motion, halo, sensor).
 *
 * render_scenes fills the objects, render_looks the looks,
 * render_camera_pose the pose; render_camera_frame then draws it and
 * render_truth writes what it shows.
 *
 *   static render_scene s;                 // large: keep it static
 *   s.n = 0;
 *   render_scene_add(&s, RENDER_OBJ_LIGHT, 1.2, 0.6, 0, 0.29, 0.29, 0);
 */
#ifndef RENDER_SCENE_H
#define RENDER_SCENE_H

#include "rl_calib.h"
#include "rl_config.h"
#include "rl_family.h"
#include "render_sensor.h"

#define RENDER_MAX_OBJ 512 /* objects in one scene (more are not added) */
#define RENDER_INK 0.04    /* the landmarks' ink: black (a radiance; paper is 0.86) */

typedef enum {
    RENDER_OBJ_PAPER, RENDER_OBJ_LANDMARK, RENDER_OBJ_SMOKE, RENDER_OBJ_DOWNLIGHT, RENDER_OBJ_SPRINKLER,
    RENDER_OBJ_VENT, RENDER_OBJ_SPEAKER, RENDER_OBJ_BOX, RENDER_OBJ_EXIT, RENDER_OBJ_LIGHT
} render_obj_kind;

typedef struct {
    render_obj_kind kind;
    double x, y, rot; /* centre in the map frame, rotation */
    double cr, sr;    /* cos and sin of rot (render_scene_add) */
    double a, b;      /* radius, or half extents */
    int id;           /* landmark id */
    double drop;      /* how far it hangs below the ceiling, m (a beam, a lower panel); 0: on it */
} render_object;

typedef struct {
    rl_calib cam;
    rl_family fam;
    double diameter;       /* landmark D, m */
    double distance;       /* camera to ceiling, m */
    double ceiling_height; /* for the map, m */
    double cam_z;          /* camera above floor, m */
    double tile, tile_px, tile_py; /* tile pitch and phase */
    double cx, cy, yaw;    /* camera optical centre and heading (image top) in the map */
    double cz;             /* camera optical centre above the floor (the mount's z, rocked) */
    double R[9];           /* camera (forward, left, up) to map, row-major */
    double roll, pitch;    /* the camera's tilt from vertical (its own x and y axes) */
    double motion, motion_dir; /* motion blur: camera travel during exposure, m */
    double motion_turn;        /* motion blur: the camera's turn during exposure, rad */
    double shutter_dx, shutter_dy, shutter_turn; /* a rolling shutter: the camera's travel (m, map
                                  frame) and turn (rad) from the first row's exposure to the
                                  last's; the pose is the middle row's (0: a global shutter) */
    double halo_amp, halo_sigma;
    double gain, vignette;     /* exposure (1: the paper near the white point), vignetting */
    render_sensor se;          /* optics' blur, sensor, tone curve */
    double sheet_w, sheet_h;   /* the landmarks' sheet, m (0: as wide as the landmark, A4's ratio) */
    double ceiling;            /* the ceiling's brightness, times the default tile's */
    double ink;                /* the landmarks' ink radiance (RENDER_INK: black; more: grey) */
    double ramp, ramp_dir;     /* light falling off across the frame: fraction, direction */
    double shadow, shadow_at, shadow_dir; /* a shadow (a wall beside the ceiling): depth, edge, side */
    int twin;                  /* 1: landmarks drawn as AprilTags (render_ceiling_tags_open) */
    double lower[RL_MAX_IDS];  /* --lower: how far the landmarks of each id hang below the ceiling, m */
    int n;
    render_object obj[RENDER_MAX_OBJ];
} render_scene;

/* Add an object; -1 when the scene is full. */
int render_scene_add(render_scene *s, render_obj_kind k, double x, double y, double rot, double a, double b, int id);

#endif
