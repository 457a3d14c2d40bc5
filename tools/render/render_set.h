/* render_set: the scenes of each set, what objects hang on the ceiling
 * around the camera:
 * - random scenes around the paper's set-up (ring5, 0.21 m landmarks,
 *   0.61 m tiles): landmarks with unique ids (four, repeated, in
 *   "repeats"), lights, clutter, as much of each as the set has;
 * - the fixed site of a drive (--path): 6 x 5 landmarks a tile apart, on
 *   the grid or as taped up by hand, lights around it;
 * - a large site's map (--site-map): its landmarks in view, and ceiling
 *   things in some of the gaps, the same in every frame.
 *
 *   static render_scene s;               // camera, diameter, tile, pose set
 *   render_set_site_layout(0.61, 0, 0, 0, 0);
 *   render_set_fill(&s, RENDER_SET_PATH); // the fixed site's landmarks in view
 */
#ifndef RENDER_SET_H
#define RENDER_SET_H

#include "rl_map.h"
#include "render_scene.h"

/* (the kinds' numbers seed the frames: new ones go at the end) */
typedef enum { RENDER_SET_CLEAN, RENDER_SET_CLUTTERED, RENDER_SET_GLARE, RENDER_SET_BORDER, RENDER_SET_CLUTTER_ONLY,
               RENDER_SET_DIM, RENDER_SET_BLUR, RENDER_SET_MOTION, RENDER_SET_ILLUM, RENDER_SET_DEGRADED,
               RENDER_SET_LENS, RENDER_SET_PATH, RENDER_SET_MOVING, RENDER_SET_HELDOUT, RENDER_SET_REPEATS,
               RENDER_SET_COUNT } render_set;

/* The set called name (a drive's "path" is none), or -1. */
int render_set_by_name(const char *name);

/* Where the fixed site's landmarks hang: on the grid `tile` apart, or
 * (irregular) each shifted by up to 15 cm and the whole layout turned 5
 * degrees; landmark move_id (0: none) then moved by (mdx, mdy).
 * Independent of the frames' random numbers. */
void render_set_site_layout(double tile, int irregular, int move_id, double mdx, double mdy);

/* The fixed site as a map, with s's family, diameter and ceiling. */
void render_set_site_map(const render_scene *s, rl_map *map);

/* Frames under map (kept: it must outlive the frames) instead of the
 * fixed site. */
void render_set_use_map(const rl_map *map);

/* s's objects for a frame of set kind at s's camera pose (random ones
 * from the render_random stream). */
void render_set_fill(render_scene *s, render_set kind);

/* A landmark on its sheet at (x, y), rotated as taped, both hanging drop
 * below the ceiling (0: on it). */
void render_set_add_landmark(render_scene *s, double x, double y, int id, double drop);

#endif
