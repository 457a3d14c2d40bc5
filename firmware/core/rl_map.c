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
            !(fabs(map->lm[i].x) <= RL_MAP_MAX_COORD) || !(fabs(map->lm[i].y) <= RL_MAP_MAX_COORD))
            return RL_ERANGE;
        for (j = 0; j < i; j++)
            if (map->lm[j].id == map->lm[i].id)
                return RL_EFORMAT;
    }
    *bad = -1;
    return RL_OK;
}
