/* rl_plan: the paper's landmark design method as a calculator.
 *
 * From how many landmarks a site needs, the camera and its distance to the
 * ceiling, choose the family (fewest code rings with enough ids), the
 * printed diameter (the narrowest code ring, zone 1, at least min_ring_px
 * wide in the image) and the largest square-grid pitch that keeps at least
 * two whole landmarks in view at any robot position and heading.
 *
 *   rl_plan_input in;
 *   rl_plan_result out;
 *   rl_plan_defaults(&in);
 *   in.landmarks = 30;
 *   if (rl_plan_compute(&in, &out) == RL_OK)
 *       printf("%g m\n", out.diameter);
 */
#ifndef RL_PLAN_H
#define RL_PLAN_H

#include "rl_config.h"
#include "rl_error.h"

typedef struct {
    int landmarks;       /* ids the site needs */
    int width, height;   /* image size, px */
    double fx;           /* focal length, px */
    double distance;     /* camera optical centre to ceiling, m */
    double min_ring_px;  /* narrowest code ring width wanted in the image, px (default 2) */
    double max_diameter; /* largest printable diameter, m (default 0.210, A4) */
    double step;         /* diameter is rounded up to a multiple of this, m (default 0.005) */
} rl_plan_input;

typedef struct {
    int bits;                        /* family ringN */
    double px_per_m;                 /* image scale on the ceiling plane */
    double view_w, view_h;           /* ceiling area in view, m */
    double diameter_min;             /* exact minimum diameter, m */
    double diameter;                 /* recommended printed diameter, m */
    double radius_px;                /* recommended landmark's radius in the image */
    double ring_px[RL_MAX_BITS + 1]; /* [0] outer ring width, [k] code zone k width
                                        (zone N: the central disk's radius) */
    double pitch_max;                /* largest pitch found with >= 2 whole landmarks in view */
    double pitch;                    /* recommended: 95% of pitch_max, down to 5 mm */
} rl_plan_result;

void rl_plan_defaults(rl_plan_input *in);

/* RL_ERANGE when no family has enough ids (more than 254) or the needed
 * diameter exceeds max_diameter (out is still filled); RL_EINVAL for
 * non-positive inputs. */
RL_CHECK rl_err rl_plan_compute(const rl_plan_input *in, rl_plan_result *out);

/* Fewest grid points of pitch p inside a w x h rectangle over sampled
 * positions (samples per axis of one cell) and headings (1 degree steps). */
int rl_plan_min_in_view(double p, double w, double h, int samples);

#endif
