/* rl_template: rasterized landmark templates for identification.
 *
 * A template is the landmark's darkness (0 white .. 255 black) drawn at a
 * chosen centre and radius into a caller-provided image, with anti-aliased
 * coverage at zone boundaries. Pixel centres are at integer coordinates
 * (docs/landmark-spec.md). A landmark cut by the image border is drawn
 * with a cut: a half-plane beyond which nothing is visible, optionally
 * written to a visibility mask, so that matching can use only what the
 * camera saw.
 *
 *   uint8_t px[48 * 48];
 *   rl_image t = rl_image_view(48, 48, 48, px);
 *   if (rl_raster_square(&fam, 25, NULL, &t, NULL) == RL_OK)   // the landmark fills t
 *       use(px[24 * 48 + 24]);
 */
#ifndef RL_RASTER_H
#define RL_RASTER_H

#include "rl_error.h"
#include "rl_family.h"
#include "rl_image.h"

/* Half-plane cut: a point (x, y) is visible when nx*x + ny*y <= d. */
typedef struct {
    double nx, ny, d;
} rl_raster_cut;

/* A cut that keeps the part of a template on one side of a vertical or
 * horizontal line: side 0 keeps x <= at, 1 keeps x >= at, 2 keeps
 * y <= at, 3 keeps y >= at. */
rl_raster_cut rl_raster_cut_side(int side, double at);

/* Draw landmark `id` centred at (cx, cy) with radius r px into `dark`
 * (every pixel written; outside the disk is 0). With `cut`, pixels whose
 * centre is beyond the cut are written 0 and marked 0 in `mask` (255 =
 * visible; mask may be NULL, same size as dark). RL_ERANGE for an invalid
 * id, RL_EINVAL for r <= 0 or bad views. */
RL_CHECK rl_err rl_raster_draw(const rl_family *fam, int id, double cx, double cy, double r,
                             const rl_raster_cut *cut, rl_image *dark, rl_image *mask);

/* The landmark filling a square view (diameter = side, as a CLR cut out by
 * its outer ring's bounding box and scaled). */
RL_CHECK rl_err rl_raster_square(const rl_family *fam, int id, const rl_raster_cut *cut,
                               rl_image *dark, rl_image *mask);

#endif
