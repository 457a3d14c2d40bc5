/* rl_composite: printed landmarks placed into real ceiling photographs,
 * with the truth of where they are (host side: allocates).
 *
 * The photo is the site as the robot's camera sees it; a mark is put
 * there the way a printed sheet would look: a white sheet of the size the
 * user prints (letter, A4, A3: its margins are the quiet zone), whose paper
 * is about as bright as the ceiling around it (darker or lighter), ink
 * that is dark grey rather than black, an ellipse and a rotation (perspective, a sheet not
 * quite square to the camera), veiling glare that lifts the ink next to a
 * lamp, lens blur and sensor noise. All of it in light, as a camera
 * forms it: the photo's grey levels are turned into light through its
 * tone curve (gamma), the sheet is laid and blurred there, and the result
 * goes back through the curve with the sensor's noise (photon noise, and
 * read noise that the curve stretches in the dark). With mix_grey the
 * blur mixes the sheet's grey levels instead (through the curve first),
 * as a camera that scales, bins, compresses or sharpens after its curve
 * does. Each id once in a
 * frame, as a map holds it. Marks are placed in three kinds of
 * places: wholly inside and away from lights, within one radius of a
 * light, and cut by the image border (up to half outside).
 *
 *   rl_composite_config cc;
 *   rl_site_mark marks[RL_COMPOSITE_MAX];
 *   rl_composite_defaults(&cc);
 *   cc.radius_px = 25.0;
 *   n = rl_composite_plan(&img, &cc, ids, 30, marks);
 *   rl_composite_draw(&img, &cc, marks, n, rl_composite_ring, &fam);
 */
#ifndef RL_COMPOSITE_H
#define RL_COMPOSITE_H

#include <stdint.h>
#include "rl_family.h"
#include "rl_image.h"

#define RL_COMPOSITE_MAX 16

typedef enum { RL_SITE_COMPLETE = 0, RL_SITE_NEAR_LIGHT = 1, RL_SITE_CUT = 2 } rl_site_kind;

typedef struct {
    int id;
    double u, v, r;         /* centre and outer radius, px (the long axis) */
    double aspect, angle;   /* short/long axis, long axis direction (rad) */
    double turn;            /* the sheet's rotation in its plane (rad) */
    rl_site_kind kind;
    double visible;         /* fraction of the disk inside the image */
    /* how it looks */
    double paper_gain;      /* paper over the local ceiling level */
    double ink;             /* ink's light over paper's */
    double veil;            /* light of glare added to the ink, fraction of full scale */
    double blur;            /* lens blur, Gaussian sigma px */
    double noise;           /* sensor noise, sigma DN of grey (photon noise, nearly even) */
    double read_noise;      /* read noise, DN of light (stretched in the dark by the curve) */
} rl_site_mark;

typedef struct {
    double radius_px;       /* landmark radius in the image (default 25) */
    double sheet_w, sheet_h;/* the sheet's sides, in landmark radii (default 2.6 x 2.6) */
    double gamma;           /* the photos' tone curve (default 2.2, sRGB-like) */
    int mix_grey;           /* 1: the blur mixes grey levels, after the curve (a camera
                               that scales, bins, compresses or sharpens after it);
                               0 (default): light, as optics do */
    int complete, near_light, cut; /* marks per photo of each kind (4, 2, 2) */
    double blur_min, blur_max;     /* px (0.4, 1.1) */
    double ink_min, ink_max;       /* ink's light over paper's (0.02, 0.08) */
    double noise_max;              /* DN (3) */
    double aspect_min;             /* (0.85) */
    uint64_t seed;                 /* (1) */
    uint64_t state;                /* the generator, advanced by plan */
} rl_composite_config;

void rl_composite_defaults(rl_composite_config *cc);

/* Choose where marks go in photo img and how they look (ids drawn from
 * ids[0..n_ids)); returns how many (up to RL_COMPOSITE_MAX). A photo with
 * no lamp gets no near-light marks. */
int rl_composite_plan(const rl_image *img, rl_composite_config *cc, const int *ids, int n_ids,
                      rl_site_mark *marks);

/* A pattern: the darkness (0 paper .. 1 ink) of mark id at (x, y) in units
 * of the radius in the sheet's frame; the sheet is white outside it. */
typedef double (*rl_composite_pattern)(const void *ctx, int id, double x, double y);

/* The ring landmark of family *(const rl_family *)ctx. */
double rl_composite_ring(const void *ctx, int id, double x, double y);

/* Draw the marks into img (changed in place). */
void rl_composite_draw(rl_image *img, const rl_composite_config *cc, const rl_site_mark *marks,
                       int n, rl_composite_pattern pattern, const void *ctx);

/* The mark a detection at (u, v) belongs to (within half its radius), or
 * -1: how a composited frame is judged against its truth. */
int rl_composite_mark_at(const rl_site_mark *marks, int n, double u, double v);

/* Fraction of a disk of radius r at (u, v) inside a W x H image. */
double rl_composite_visible(int W, int H, double u, double v, double r);

#endif
