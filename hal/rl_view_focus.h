/* rl_view_focus: how sharp the landmarks are, a figure to turn a lens by
 * (the live view's focus). Across a landmark's outer edge, on 32 rays from
 * its centre, the steepest grey step per pixel over the step's whole
 * height (the paper outside less the ink inside): 1/px, the contrast
 * divided out, so lighting and exposure do not move it. An edge blurred by
 * a Gaussian of sigma px gives 1 / (sigma sqrt(2 pi)): blur_px inverts it.
 * A frame's focus is the median of its whole landmarks'. Reads the image
 * only; no allocation.
 *
 *   static uint8_t img[480][640];      // a grey frame
 *   rl_detection d;                    // a landmark found in it (rl_recog)
 *   double f, per[RL_MAX_LANDMARKS];
 *   memset(&d, 0, sizeof d);
 *   d.u = 320, d.v = 240, d.radius = 25, d.complete = 1;
 *   f = rl_view_focus_landmark(&img[0][0], 640, 480, &d);   // NaN: not measurable
 *   use(f, rl_view_focus_blur_px(f));
 *   (void)per;
 */
#ifndef RL_VIEW_FOCUS_H
#define RL_VIEW_FOCUS_H

#include <stdint.h>
#include "rl_recog.h"

/* The landmark's edge sharpness in img (w x h grey, packed), 1/px; NaN
 * when the border cuts it, it is smaller than 6 px or its edge shows no
 * contrast. */
double rl_view_focus_landmark(const uint8_t *img, int w, int h, const rl_detection *d);

/* The median of the measurable ones of res's landmarks (NaN: none); each
 * one's into per[i] when per is not NULL (res->n_landmarks of them). */
double rl_view_focus_frame(const uint8_t *img, int w, int h, const rl_result *res, double *per);

/* The Gaussian blur, px, that gives focus f (NaN for f <= 0 or NaN). */
double rl_view_focus_blur_px(double f);

#endif
