/* rl_light: light sources of a frame, as boxes (internal).
 *
 * Pixels at or above the light threshold of the histogram analysis form
 * light regions (lamps and their glare). They are large blobs, so every
 * other row finds them at half the cost.
 *
 *   if (rl_light_find(&lb, &img, res.levels.light, 3, &res) == RL_OK)
 *       use(res.n_lights, res.lights, res.dropped.lights);
 */
#ifndef RL_LIGHT_H
#define RL_LIGHT_H

#include "rl_label.h"
#include "rl_recog.h"

/* Label the light regions of img (pixels >= level; none when level is
 * 256) with lb, whose height must be at least half the image's, and add
 * their boxes to res; what does not fit is counted in res->dropped.lights.
 * RL_ELIMIT from the labeller (more runs than it holds). */
RL_CHECK rl_err rl_light_find(rl_label *lb, const rl_image *img, int level, int min_area,
                              rl_result *res);

#endif
