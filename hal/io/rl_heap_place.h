/* rl_heap_place: the place finder's index (rl_place) on the heap, for a
 * map that repeats ids; none for a map whose ids are unique (rl_pose_solve
 * finds their landmarks by id, as always). The one place where it is set
 * up, for the firmware and the host tools alike.
 *
 *   rl_heap_place hp;
 *   rl_pose pose;
 *   rl_place_found found;
 *   rl_mount mount;
 *   rl_mount_defaults(&mount, 0.88);
 *   if (rl_heap_place_init(&hp, &map, NULL) == RL_OK &&
 *       rl_heap_place_solve(&hp, &cam, &map, &mount, res.landmarks, res.n_landmarks, NULL, NULL, &pose,
 *                           &found) == RL_OK)
 *       use(pose.x, found.status);
 *   rl_heap_place_free(&hp);
 */
#ifndef RL_HEAP_PLACE_H
#define RL_HEAP_PLACE_H

#include "rl_place.h"

typedef struct {
    rl_place *pl; /* NULL: the map's ids are unique */
    void *mem;
} rl_heap_place;

/* Build the index when the map repeats ids (cfg NULL: defaults).
 * RL_ENOMEM, or RL_EINVAL for a map rl_place refuses. */
RL_CHECK rl_err rl_heap_place_init(rl_heap_place *hp, const rl_map *map, const rl_place_config *cfg);

/* The pose: rl_place_solve with the index, rl_pose_solve without (found
 * then says RL_PLACE_FOUND with each id's landmark, or RL_PLACE_NONE). */
RL_CHECK rl_err rl_heap_place_solve(const rl_heap_place *hp, const rl_calib *cam, const rl_map *map,
                                    const rl_mount *mount, const rl_detection *lm, int n,
                                    const rl_offsets *offsets, const rl_place_prior *prior, rl_pose *pose,
                                    rl_place_found *found);

void rl_heap_place_free(rl_heap_place *hp);

/* "found", "tracked", "ambiguous" or "none". */
const char *rl_place_status_name(int status);

#endif
