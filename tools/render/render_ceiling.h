/* render_ceiling: the light a point of the ceiling sends to the camera:
 * tiles and T-bars, the objects on them (landmarks printed per
 * docs/landmark-spec.md, or AprilTag 36h11 twins; lights that saturate;
 * clutter) and the halo lights cast around them.
 *
 * A frame looks up a point's objects in a grid over what it sees (0.1 m
 * cells, each listing the objects that can touch it, in the scene's
 * order), so a sample looks at a few objects, not all: the picture is the
 * same.
 *
 *   static render_grid g;                          // large: keep it static
 *   double view[4] = {x0, y0, x1, y1};             // what the frame sees, m
 *   if (render_ceiling_grid(&s, view, 0.05, &g) == 0)
 *       use(render_ceiling_radiance(&s, &g, 1.0, 2.0));
 *   free(g.idx);
 */
#ifndef RENDER_CEILING_H
#define RENDER_CEILING_H

#include "render_scene.h"

#define RENDER_GRID_CELL 0.1 /* m */
#define RENDER_GRID_MAX 128  /* cells each way; a larger view looks at every object */

typedef struct {
    double x0, y0;
    int nx, ny;                                      /* 0: no grid */
    int start[RENDER_GRID_MAX * RENDER_GRID_MAX + 1]; /* cell c's objects: idx[start[c] .. start[c + 1]) */
    int *idx;                                        /* malloc'ed; the caller frees it */
} render_grid;

/* The AprilTag 36h11 bitmaps a twin scene draws: made once (0, or -1),
 * the family freed at the end (the bitmaps live until exit: libapriltag
 * does not export image_u8_destroy). */
int render_ceiling_tags_open(void);
void render_ceiling_tags_close(void);

/* The grid over view (x0, y0, x1, y1), widened by margin: 0, or -1 out of
 * memory. */
int render_ceiling_grid(const render_scene *s, const double *view, double margin, render_grid *g);

/* The radiance at map point (X, Y): 1 is the paper near the white point. */
double render_ceiling_radiance(const render_scene *s, const render_grid *g, double X, double Y);

/* Radiance of object o (one that hangs below the ceiling) at (X, Y) on its
 * own plane, or -1 where it is not. */
double render_ceiling_object(const render_scene *s, const render_object *o, double X, double Y);

/* Distance from (X, Y) to a light's rectangle (0 inside). */
double render_ceiling_light_gap(const render_object *o, double X, double Y);

#endif
