#include "rl_map.h"

#include <math.h>

int rl_map_find(const rl_map *map, int id)
{
    int i;
    for (i = 0; i < map->count; i++)
        if (map->lm[i].id == id)
            return i;
    return -1;
}

void rl_map_id_heights(const rl_map *map, double *h)
{
    unsigned char seen[RL_MAX_IDS] = {0}; /* 1: one height so far, 2: several */
    int i;
    for (i = 0; i < RL_MAX_IDS; i++)
        h[i] = map->ceiling_height;
    for (i = 0; i < map->count; i++) {
        int id = map->lm[i].id;
        double z = rl_map_height(map, i);
        if (id < 0 || id >= RL_MAX_IDS || seen[id] == 2)
            continue;
        if (seen[id] == 0) {
            seen[id] = 1;
            h[id] = z;
        } else if (h[id] != z) {
            seen[id] = 2;
            h[id] = map->ceiling_height;
        }
    }
}

/* Whether landmarks i and j overlap: centres closer than the diameter. */
static int overlap(const rl_map *map, int i, int j)
{
    double dx = map->lm[i].x - map->lm[j].x, dy = map->lm[i].y - map->lm[j].y, d = map->diameter;
    return fabs(dx) < d && fabs(dy) < d && dx * dx + dy * dy < d * d;
}

rl_err rl_map_check(const rl_map *map, int *bad)
{
    int i, j;
    *bad = -1;
    if (!(map->diameter > 0.0) || !(map->ceiling_height > 0.0) || map->count < 0 ||
        map->count > RL_MAX_MAP_LANDMARKS)
        return RL_ERANGE;
    for (i = 0; i < map->count; i++) {
        *bad = i;
        if (!rl_family_valid(&map->family, map->lm[i].id) ||
            !(fabs(map->lm[i].x) <= RL_MAP_MAX_COORD) || !(fabs(map->lm[i].y) <= RL_MAP_MAX_COORD) ||
            !(map->lm[i].z >= 0.0 && map->lm[i].z <= RL_MAP_MAX_HEIGHT))
            return RL_ERANGE;
    }
    for (i = 0; i < map->count; i++)
        for (j = 0; j < i; j++)
            if (overlap(map, i, j)) {
                *bad = i;
                return RL_EFORMAT;
            }
    *bad = -1;
    return RL_OK;
}

int rl_map_overlapped(const rl_map *map, int i)
{
    int j;
    for (j = 0; j < map->count; j++)
        if (j != i && overlap(map, i, j))
            return j;
    return -1;
}

int rl_map_repeats_ids(const rl_map *map)
{
    unsigned char seen[256 / 8] = {0};
    int i;
    for (i = 0; i < map->count; i++) {
        unsigned id = (unsigned)map->lm[i].id;
        if (id >= 256)
            continue; /* not in any family: rl_map_check refuses it */
        if (seen[id >> 3] & (1u << (id & 7)))
            return 1;
        seen[id >> 3] |= (unsigned char)(1u << (id & 7));
    }
    return 0;
}
