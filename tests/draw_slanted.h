/* draw_slanted: a landmark drawn still and seen slanted, for the tests of
 * the moved read (test_motion, test_twins_slanted): the truth by
 * construction, from the family's zone radii (rl_templates_value_at).
 *
 *   static uint8_t pix[120 * 120];
 *   rl_image img = draw_slanted(pix, 120, 120, 23, 60.3, 59.6, 20, 0.03, 0.85);
 */
#ifndef DRAW_SLANTED_H
#define DRAW_SLANTED_H
#include <stdint.h>
#include "rl_image.h"

/* Landmark id of the 5-ring family drawn into pix (w x h, stride w) at
 * (cx, cy), radius r px, focus sigma (share of r), its x axis shrunk to
 * sx of its radius (minor over major); paper 220, ink 30 (linear light).
 * Returns the view of pix. */
rl_image draw_slanted(uint8_t *pix, int w, int h, int id, double cx, double cy, double r, double sigma,
                      double sx);

#endif
