/* render_ceiling: the light a point of the ceiling sends to the camera:
 * tiles and T-bars, the objects on them (landmarks printed per
 * docs/landmark-spec.md, or AprilTag 36h11 twins; lights that saturate;
 * clutter) and the halo lights cast around them.
 *
 * A frame looks up a point's objects in a grid over what it sees (5 cm
 * cells, each listing the objects that can cover it and the lights whose
 * halo can reach it, in the scene's order), so a sample looks at a few
 * objects, not all, and the tiles' value noise in its lattices' hashes
 * made once for the view: the picture is the same, bit for bit.
 *
 *   static render_grid g;                          // large: keep it static (zeroed)
 *   double view[4] = {x0, y0, x1, y1};             // what the frame sees, m
 *   if (render_ceiling_grid(&s, view, 0.05, &g) == 0)
 *       use(render_ceiling_radiance(&s, &g, 1.0, 2.0));
 *   render_ceiling_grid_free(&g);
 */
#ifndef RENDER_CEILING_H
#define RENDER_CEILING_H

#include "render_random.h"
#include "render_scene.h"

#define RENDER_GRID_CELL 0.05 /* m */
#define RENDER_GRID_MAX 256   /* cells each way; a larger view looks at every object */
#define RENDER_GRID_CELLS (RENDER_GRID_MAX * RENDER_GRID_MAX + 1) /* and one for samples outside it */

/* An object in a cell's list: where it is and how far it reaches there
 * (1.5 times its size, or a light's halo). */
typedef struct {
    double x, y, reach;
    const render_object *o;
} render_grid_entry;

typedef struct {
    double x0, y0;
    int nx, ny; /* 0: no grid (every sample in the one cell outside it); only a grid made by
                 * render_ceiling_grid lists anything (a zeroed one meets no object) */
    /* cell c's objects that can cover a point of it, at[cover[c] .. cover[c + 1]),
     * and the lights whose halo can reach it, at[glow[c] .. glow[c + 1]); cell
     * nx * ny, outside the grid, lists them all */
    int cover[RENDER_GRID_CELLS + 1], glow[RENDER_GRID_CELLS + 1];
    render_grid_entry *at; /* malloc'ed */
    /* the tiles' value noise over the grid at its three scales: their shading, fissures and pits */
    render_noise coarse, fine, pits;
} render_grid;

/* The AprilTag 36h11 bitmaps a twin scene draws: made once (0, or -1),
 * the family freed at the end (the bitmaps live until exit: libapriltag
 * does not export image_u8_destroy). */
int render_ceiling_tags_open(void);
void render_ceiling_tags_close(void);

/* The grid over view (x0, y0, x1, y1), widened by margin, in g zeroed or
 * made before (its memory reused frame after frame; freed once, by
 * render_ceiling_grid_free): 0, or -1 out of memory (g holds nothing to
 * free then). */
int render_ceiling_grid(const render_scene *s, const double *view, double margin, render_grid *g);
void render_ceiling_grid_free(render_grid *g);

/* The radiance at map point (X, Y): 1 is the paper near the white point. */
double render_ceiling_radiance(const render_scene *s, const render_grid *g, double X, double Y);

/* Radiance of object o (one that hangs below the ceiling) at (X, Y) on its
 * own plane, or -1 where it is not. */
double render_ceiling_object(const render_scene *s, const render_object *o, double X, double Y);

/* Distance from (X, Y) to a light's rectangle (0 inside). */
double render_ceiling_light_gap(const render_object *o, double X, double Y);

#endif
