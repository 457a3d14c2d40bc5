/* rl_mapfile: map YAML files <-> rl_map.
 *
 *   family: ring5          # docs/landmark-spec.md
 *   diameter: 0.210        # printed outer diameter, metres
 *   ceiling_height: 2.750  # ceiling above the floor, metres
 *   landmarks:
 *     - {id: 25, x: 0.305, y: 0.305}
 *     - {id: 7, x: 0.915, y: 0.305, sigma_x: 0.0004, sigma_y: 0.0003}
 *
 * sigma_x, sigma_y (optional): a surveyed position's standard deviations.
 * Errors name the file, line and key: missing keys, non-numbers, ids
 * outside the family, overlapping landmarks, too many landmarks. Ids may
 * repeat (a large site reuses a small family's ids).
 *
 *   rl_map site;
 *   char err[256];
 *   if (rl_mapfile_load("map.yaml", &site, err, sizeof err) == RL_OK)
 *       use(site.count, site.lm[0].id);
 */
#ifndef RL_MAPFILE_H
#define RL_MAPFILE_H

#include <stddef.h>
#include <stdio.h>
#include "rl_map.h"

RL_CHECK rl_err rl_mapfile_load(const char *path, rl_map *map, char *err, size_t errlen);
RL_CHECK rl_err rl_mapfile_save(const char *path, const rl_map *map, char *err, size_t errlen);

/* The same format a line at a time, for maps of any size (a survey's):
 * the header (up to "landmarks:"), then one line per landmark. */
void rl_mapfile_put_header(FILE *f, const rl_family *fam, double diameter, double ceiling_height);
void rl_mapfile_put_landmark(FILE *f, const rl_map_landmark *lm);

#endif
