/* rl_view_json: what the live web view serves as JSON, written into the
 * caller's buffer: /status.json from a snapshot of the loop (rl_view.h),
 * with the histogram of its image computed here, in the reader's thread,
 * and /map.json from the map. Numbers that are not finite are written as
 * null; strings are escaped. A buffer too small gives 0, never a cut
 * document.
 *
 *   static char buf[RL_VIEW_JSON_STATUS_MAX];
 *   const rl_view_snap *snap = NULL;  // a reader's copy (rl_view_take)
 *   const rl_map *map = NULL;         // the firmware's map
 *   size_t n = 0;
 *   if (snap != NULL)
 *       n = rl_view_json_status(snap, buf, sizeof buf);
 *   if (map != NULL && rl_view_json_map_size(map) <= sizeof buf)
 *       n = rl_view_json_map(map, buf, sizeof buf);
 *   use(n);                           // 0: it did not fit
 */
#ifndef RL_VIEW_JSON_H
#define RL_VIEW_JSON_H

#include <stddef.h>
#include "rl_map.h"
#include "rl_view.h"

/* Enough for any status document (every list at its compile-time limit). */
#define RL_VIEW_JSON_STATUS_MAX (96 * 1024 + RL_MAX_CANDIDATES * 320 + RL_MAX_LANDMARKS * 192 + \
                                 RL_MAX_MAP_LANDMARKS * 96 + \
                                 RL_VIEW_TRACK * 40)

/* The status of snapshot s (docs/view.md lists the fields; with s->geom
 * the map's landmarks where the pose puts them in the image, with
 * s->focus_best the best focus). Returns the length written (no NUL counted; one is written),
 * or 0 when it does not fit in cap. */
size_t rl_view_json_status(const rl_view_snap *s, char *buf, size_t cap);

/* Bytes that are always enough for rl_view_json_map of this map. */
size_t rl_view_json_map_size(const rl_map *m);

/* The map: {"family", "diameter", "ceiling", "landmarks": [{"id", "x",
 * "y"}, ...]}. Returns the length, or 0 when it does not fit in cap. */
size_t rl_view_json_map(const rl_map *m, char *buf, size_t cap);

/* The 256-bin grey histogram of the snapshot's image (all 0 without one). */
void rl_view_json_hist(const rl_view_snap *s, unsigned long hist[256]);

#endif
