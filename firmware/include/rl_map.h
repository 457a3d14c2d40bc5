/* rl_map: the landmark map: which ids hang where on the ceiling.
 *
 * Map frame per docs/landmark-spec.md (metres, REP-103). Filled by the
 * host's YAML loader or by firmware configuration; the core only reads it.
 *
 *   int i = rl_map_find(&map, 25);
 *   if (i >= 0) use(map.lm[i].x, map.lm[i].y);
 */
#ifndef RL_MAP_H
#define RL_MAP_H

#include "rl_config.h"
#include "rl_error.h"
#include "rl_family.h"

typedef struct {
    int id;      /* landmark id in the map's family */
    double x, y; /* centre on the ceiling, map frame, metres */
    double sigma_x, sigma_y; /* their standard deviations from a survey, m; 0: not known */
    double z;    /* its own height above the floor, m (a beam, a lower panel); 0: the map's
                    ceiling_height */
} rl_map_landmark;

typedef struct {
    rl_family family;
    double diameter;       /* printed outer diameter D, metres */
    double ceiling_height; /* ceiling above the floor, metres */
    int count;
    rl_map_landmark lm[RL_MAX_MAP_LANDMARKS];
} rl_map;

/* Index of the first landmark with `id` in the map, or -1. */
int rl_map_find(const rl_map *map, int id);

/* Whether landmark i hangs at the map's ceiling_height (its own z 0). */
static inline int rl_map_at_ceiling(const rl_map *map, int i)
{
    return !(map->lm[i].z > 0.0);
}

/* Height above the floor of landmark i, metres: its own z, else the map's
 * ceiling_height. Inline: rl_track looks at every landmark of a large map
 * each frame. */
static inline double rl_map_height(const rl_map *map, int i)
{
    return rl_map_at_ceiling(map, i) ? map->ceiling_height : map->lm[i].z;
}

/* Each id's height above the floor into h[0 .. RL_MAX_IDS): its
 * landmarks' when they all hang at one height, else (or no such landmark)
 * the map's ceiling_height (a site repeating an id at several heights:
 * which one is seen is not known from the id). One pass over the map. */
void rl_map_id_heights(const rl_map *map, double *h);

/* Largest |x| or |y| of a landmark, metres. */
#define RL_MAP_MAX_COORD 1e5
/* Largest height of a landmark above the floor, metres. */
#define RL_MAP_MAX_HEIGHT 100.0

/* Validate: diameter and height > 0, coordinates within RL_MAP_MAX_COORD,
 * a landmark's own z 0 (the ceiling's) or within 0 .. RL_MAP_MAX_HEIGHT,
 * ids valid in the family, no two landmarks overlapping (centres closer
 * than the diameter). Ids may repeat: a large site reuses a small
 * family's ids (rl_place finds which landmark a frame sees).
 * On failure *bad is the index of the first offending landmark (or -1 for
 * a map-level field). RL_ERANGE for an invalid id or size, RL_EFORMAT for
 * an overlap (rl_map_overlapped names the other landmark). */
RL_CHECK rl_err rl_map_check(const rl_map *map, int *bad);

/* Index of a landmark that overlaps landmark i, or -1. */
int rl_map_overlapped(const rl_map *map, int i);

/* 1 if some id appears more than once. */
int rl_map_repeats_ids(const rl_map *map);

#endif
