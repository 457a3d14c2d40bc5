/* rl_place_index: the place finder's index of a map, inside rl_place.
 *
 * Map pairs closer than the reach, sorted by their unordered id pair and
 * then by distance (a bucket per id pair), and the map's landmarks by grid
 * cell. Internal to the core.
 *
 *   extern const rl_place *pl;
 *   const rl_place_pair *q, *end;
 *   rl_place_index_pairs(pl, 3, 17, 0.80, 0.90, &q, &end);  // ids 3 and 17, 0.8 .. 0.9 m apart
 *   for (; q < end; q++)
 *       use(q->a, q->b);                                     // map indexes, id(a) <= id(b)
 *   use(rl_place_index_near(pl, 12.2, 3.05, 0.15, 17));      // a landmark of id 17 within 0.15 m
 */
#ifndef RL_PLACE_INDEX_H
#define RL_PLACE_INDEX_H

#include <stdint.h>
#include "rl_place.h"

typedef struct {
    uint16_t a, b; /* map indexes: id(a) <= id(b) */
    uint16_t d_mm; /* their distance, mm */
} rl_place_pair;

struct rl_place {
    const rl_map *map;
    rl_place_config cfg; /* reach and gate resolved */
    size_t bytes;
    int n_ids;           /* the family's ids: buckets for n_ids (n_ids + 1) / 2 id pairs */
    uint32_t *bucket;    /* [n_buckets + 1]: first pair of each id pair */
    rl_place_pair *pair; /* [n_pairs] */
    long n_pairs;
    double x0, y0, cell; /* the grid: cell (i, j) covers x0 + i cell .. */
    int gw, gh;
    uint16_t *cell_first; /* [gw gh + 1]: first of each cell's landmarks in cell_lm */
    uint16_t *cell_lm;    /* [map count]: map indexes by cell */
    double z_lo, z_hi;    /* the landmarks' lowest and highest heights (rl_map_height), m */
};

/* The pairs of ids ia, ib (either order) with distance in [lo, hi] m. */
void rl_place_index_pairs(const rl_place *pl, int ia, int ib, double lo, double hi, const rl_place_pair **first,
                          const rl_place_pair **end);

/* The map landmark nearest (x, y) within r, of id `id` (0: any id); -1 if
 * none. */
int rl_place_index_near(const rl_place *pl, double x, double y, double r, int id);

/* Up to max map landmarks of id `id` within r of (x, y) into out; how
 * many there are (may exceed max). */
int rl_place_index_within(const rl_place *pl, double x, double y, double r, int id, int *out, int max);

#endif
