/* render_look: how each set's frames look: exposure, vignetting, blur,
 * motion, halo around lights, noise and the sensor, light falling off
 * across the frame, grey ink, the landmarks' sheets; drawn per frame from
 * the set's ranges (the render_random stream).
 *
 *   static render_scene s;
 *   render_look_apply(&s, RENDER_SET_DEGRADED);   // blur 1.1 px, 4 px motion, ...
 */
#ifndef RENDER_LOOK_H
#define RENDER_LOOK_H

#include "render_scene.h"
#include "render_set.h"

/* s's looks for a frame of set kind (RENDER_SET_PATH: the plain look of
 * a drive). RENDER_SET_LENS also changes s->cam's distortion. */
void render_look_apply(render_scene *s, render_set kind);

#endif
