/* rl_mapfile: map YAML files <-> rl_map.
 *
 *   family: ring5          # shared/landmark-spec.md
 *   diameter: 0.210        # printed outer diameter, metres
 *   ceiling_height: 2.750  # ceiling above the floor, metres
 *   landmarks:
 *     - {id: 25, x: 0.305, y: 0.305}
 *
 * Errors name the file, line and key: missing keys, non-numbers, ids
 * outside the family, duplicate ids, too many landmarks.
 *
 *   rl_map site;
 *   char err[256];
 *   if (rl_mapfile_load("map.yaml", &site, err, sizeof err) == RL_OK)
 *       use(site.count, site.lm[0].id);
 */
#ifndef RL_MAPFILE_H
#define RL_MAPFILE_H

#include <stddef.h>
#include "rl_map.h"

RL_CHECK rl_err rl_mapfile_load(const char *path, rl_map *map, char *err, size_t errlen);
RL_CHECK rl_err rl_mapfile_save(const char *path, const rl_map *map, char *err, size_t errlen);

#endif
