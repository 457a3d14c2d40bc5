/* rl_ident: landmark identification by template matching (Pearson's
 * correlation), the paper's identification step.
 *
 * Every pixel of a candidate within 1.2 R of its centre is compared with
 * every template: Pearson's r over those pixels between their darkness
 * (255 - I) and the template's darkness at the same radius. Landmarks are
 * rotationally symmetric, so the template at a pixel depends only on its
 * distance from the centre: pixels are gathered into RL_PROFILE_BINS
 * radial bins (count, sum) plus the sum of squares of every pixel, and one
 * pass over the bins scores each template. Because the sum of squares is
 * taken per pixel, anything that varies around a ring (asymmetric clutter,
 * a wrong centre) still lowers r exactly as in a 2-D correlation.
 *
 * Templates are kept at RL_BLUR_LEVELS blurs (Gaussian, fractions of R),
 * so defocus and motion blur match a blurred template instead of being
 * misread as another code. Pixels outside the image are simply not in the
 * bins: a landmark cut by the border is matched against templates cut the
 * same way. Pearson's r is invariant to gain and offset, so no binary image
 * is needed; the fitted gain is reported as the contrast.
 *
 *   rl_ident id;
 *   rl_ident_init(&id, &ws, &fam, NULL, 0);     // every id of the family
 *   rl_profile p;
 *   rl_ident_profile(&img, cx, cy, r, &p);
 *   rl_match m;
 *   rl_ident_match(&id, &p, &m);                // m.id, m.score, m.second
 */
#ifndef RL_IDENT_H
#define RL_IDENT_H

#include <stdint.h>
#include "rl_config.h"
#include "rl_error.h"
#include "rl_family.h"
#include "rl_image.h"
#include "rl_workspace.h"

/* Radial bins of a profile: at R = 24 px a bin is 0.45 px wide, so bin
 * quantization costs under 0.01 of correlation. */
#define RL_PROFILE_BINS 64
/* A profile covers radii 0 .. RL_PROFILE_EXTENT * R (the quiet zone's start). */
#define RL_PROFILE_EXTENT 1.2
/* Template blurs, as Gaussian sigma in units of R. */
#define RL_BLUR_LEVELS 4

typedef struct {
    double n[RL_PROFILE_BINS];  /* pixels per bin */
    double sx[RL_PROFILE_BINS]; /* sum of darkness per bin */
    double sxx;                 /* sum of squared darkness over all pixels */
    double total;               /* pixels in all bins */
} rl_profile;

typedef struct {
    rl_family fam;
    int n;          /* ids */
    int *ids;       /* the ids */
    float *tmpl;    /* RL_PROFILE_BINS x stride darkness, 0..1 (bin-major); column
                       i * RL_BLUR_LEVELS + b is id i at blur b, the rest pads */
    int stride;     /* columns per bin */
} rl_ident;

typedef struct {
    int id;          /* best template's id, or -1 */
    double score;    /* its Pearson correlation */
    double second;   /* best correlation of any other id */
    double contrast; /* fitted darkness difference between the template's black
                        and white, grey levels */
    int blur;        /* blur level of the best template */
} rl_match;

/* Bytes rl_ident_init takes for n ids. */
size_t rl_ident_bytes(int n);

/* Compute the templates of `ids` (every id of the family when ids is NULL)
 * into ws. RL_ERANGE for an id outside the family. */
RL_CHECK rl_err rl_ident_init(rl_ident *id, rl_ws *ws, const rl_family *fam, const int *ids,
                              int n_ids);

/* Darkness template of `id` at normalized radius rho with Gaussian blur
 * sigma (units of R); 0 white .. 1 black. */
double rl_ident_template_at(const rl_family *fam, int id, double rho, double sigma);

/* Template value of the i-th id at a blur level in bin k. */
float rl_ident_template_bin(const rl_ident *id, int i, int blur, int k);

/* Gather the pixels of img within RL_PROFILE_EXTENT * r of (cx, cy). */
void rl_ident_profile(const rl_image *img, double cx, double cy, double r, rl_profile *p);

/* Angular sectors for glare normalization: glare adds a smooth light
 * field that varies with direction, so each sector is rescaled by its own
 * black and white levels. */
#define RL_SECTORS 16

/* Polar cells reach beyond the profile (1.2 R) so that a larger radius or
 * a shifted centre still finds its outermost pixels: 68 bins reach
 * 1.275 R. Further out, a search's outermost quiet-zone bins are only
 * partly filled, which Pearson's r takes as pixels not seen. */
#define RL_POLAR_BINS 68
/* Zero cells before and after a sector's bins (whole vectors of 4). */
#define RL_POLAR_PAD 4
#define RL_POLAR_CELLS (RL_POLAR_BINS + 2 * RL_POLAR_PAD)

/* A candidate gathered once into RL_SECTORS x RL_POLAR_BINS polar cells
 * (raw count, sum, sum of squares), from which the sector-normalized
 * profile for any small shift of the centre, or change of radius, is
 * derived without touching the image again: a shift d moves the pixels
 * of sector s (direction u_s) to radius rho - d . u_s, and a radius scale
 * f divides every radius by f. */
typedef struct {
    double cx, cy, r;
    /* bin k of a sector at [RL_POLAR_PAD + k]; the pads are zero */
    float n[RL_SECTORS][RL_POLAR_CELLS]; /* pixels */
    float s[RL_SECTORS][RL_POLAR_CELLS]; /* sum of darkness */
    float q[RL_SECTORS][RL_POLAR_CELLS]; /* sum of squared darkness */
    /* while gathering: count, sum and sum of squares of grey levels packed
     * in one integer per cell (one add per pixel), from a table per level;
     * the float cells above then hold raw sums until normalized */
    uint64_t acc[RL_SECTORS][RL_POLAR_CELLS];
    uint64_t lut[256];
    double ux[RL_SECTORS], uy[RL_SECTORS]; /* sector directions */
    double lo[RL_SECTORS], hi[RL_SECTORS]; /* sector black and white */
    int usable[RL_SECTORS];                /* sector has enough contrast */
    int merged_usable[RL_SECTORS / 2];     /* after the octants' sectors are summed
                                              into the first half of the arrays */
} rl_polar;

/* Gather a candidate into polar cells and normalize each sector by its
 * own black and white; sectors with less than min_contrast grey levels
 * between them (washed out) are left out. After this the first
 * RL_SECTORS / 2 rows of cells hold the normalized darkness (count, sum,
 * sum of squares) of each octant, its two sectors summed, and ux, uy the
 * octants' middle directions. */
void rl_ident_polar(const rl_image *img, double cx, double cy, double r, int light,
                    double min_contrast, rl_polar *pol);

/* The profile of pol with the centre moved by (dx, dy) px and the radius
 * multiplied by scale (1 = as gathered). */
void rl_ident_polar_profile(const rl_polar *pol, double dx, double dy, double scale,
                            rl_profile *p);

/* Score only the templates of the given ids (a short list), at one blur
 * level (0 .. RL_BLUR_LEVELS - 1) or all (blur < 0). */
void rl_ident_match_ids(const rl_ident *id, const rl_profile *p, const int *ids, int n,
                        int blur, rl_match *m);

/* Score every template against a profile. */
void rl_ident_match(const rl_ident *id, const rl_profile *p, rl_match *m);

/* Pearson's correlation of a and b over the cells where mask != 0 (all
 * when NULL); 0 when either side is constant. The direct formula, for
 * tests and tools. */
double rl_pearson(const uint8_t *a, const uint8_t *b, const uint8_t *mask, int n);

#endif
