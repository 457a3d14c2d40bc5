#include "rl_heap_place.h"

#include <stdlib.h>
#include <string.h>

rl_err rl_heap_place_init(rl_heap_place *hp, const rl_map *map, const rl_place_config *cfg)
{
    rl_place_config def;
    size_t need;
    rl_err e;
    hp->pl = NULL;
    hp->mem = NULL;
    if (!rl_map_repeats_ids(map))
        return RL_OK;
    if (cfg == NULL) {
        rl_place_defaults(&def);
        cfg = &def;
    }
    if ((need = rl_place_size(map, cfg)) == 0)
        return RL_EINVAL;
    if ((hp->mem = malloc(need)) == NULL)
        return RL_ENOMEM;
    if ((e = rl_place_init(&hp->pl, map, cfg, hp->mem, need)) != RL_OK) {
        rl_heap_place_free(hp);
        return e;
    }
    return RL_OK;
}

rl_err rl_heap_place_solve(const rl_heap_place *hp, const rl_calib *cam, const rl_map *map, const rl_mount *mount,
                           const rl_detection *lm, int n, const rl_offsets *offsets, const rl_place_prior *prior,
                           rl_pose *pose, rl_place_found *found)
{
    rl_err e;
    int i;
    if (hp->pl != NULL)
        return rl_place_solve(hp->pl, cam, mount, lm, n, offsets, prior, pose, found);
    memset(found, 0, sizeof *found);
    for (i = 0; i < RL_MAX_LANDMARKS; i++)
        found->match[i] = i < n ? rl_map_find(map, lm[i].id) : -1;
    e = rl_pose_solve(cam, map, mount, lm, n, offsets, pose);
    found->status = e == RL_OK ? RL_PLACE_FOUND : RL_PLACE_NONE;
    found->verified = pose->used;
    if (e == RL_OK) {
        found->x = pose->x;
        found->y = pose->y;
        found->yaw = pose->yaw;
    }
    return e;
}

void rl_heap_place_free(rl_heap_place *hp)
{
    free(hp->mem);
    hp->mem = NULL;
    hp->pl = NULL;
}

const char *rl_place_status_name(int status)
{
    switch (status) {
    case RL_PLACE_FOUND: return "found";
    case RL_PLACE_TRACKED: return "tracked";
    case RL_PLACE_AMBIGUOUS: return "ambiguous";
    default: return "none";
    }
}
