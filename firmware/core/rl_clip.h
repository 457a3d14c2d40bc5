/* rl_clip: a small landmark whose light side the camera clipped
 * (internal: rl_twins_check's).
 *
 * A camera that raises its exposure after its tone curve (auto exposure,
 * a gain on grey levels) clips the paper at full scale: the light half of
 * every blurred edge goes to white, a dark band narrows from both sides
 * and its outer edge moves in. A small landmark's read comes out 6-10%
 * short, and the thick band of its outer ring and a dark code zone 1
 * looks like the outer ring alone: its zone twin with zone 1 light (16
 * apart in ring5) fits through both formations, so the twins' rules keep
 * it (fifteenth session: a 21 read as 1, a 23 as 7, a 19 as 3 at 14-15 px,
 * `--set lens --isp ae:1,jpeg:85`; docs/results.md). A clip is a
 * monotone curve, which the rank read (rl_rank) does not see.
 *
 *   int refused = rl_clip_refuses(rec, &img, res.levels.light, &res.landmarks[0]);
 */
#ifndef RL_CLIP_H
#define RL_CLIP_H

#include "rl_image.h"
#include "rl_recog_state.h"

/* The share of a landmark's pixels (its disk to RL_CLIP_REACH of its
 * radius: paper round it too) at RL_CLIP_LEVEL from which its light side
 * counts as clipped: the three wrong reads had 0.28-0.48; unclipped
 * frames' landmarks none. */
#define RL_CLIP_SHARE 0.05
#define RL_CLIP_REACH 1.3
/* The grey level a clip leaves (8-bit full scale). */
#define RL_CLIP_LEVEL 255

/* The share of the pixels of the disk of radius r round (u, v), in the
 * frame, at `level` or over, from every row_step-th row (0 when none is
 * in the frame): a clipped light side (RL_CLIP_LEVEL, RL_CLIP_REACH * r)
 * and a lamp over a landmark (rl_twins' RL_TWINS_UNFIT_LAMP). */
double rl_clip_disk_share(const rl_image *img, double u, double v, double r, int level, int row_step);

/* 1 when d's light side is clipped (its disk to RL_CLIP_REACH at
 * RL_CLIP_LEVEL: rl_clip_disk_share at RL_CLIP_SHARE or
 * more) and the rank read, through any monotone curve, does not keep its
 * id (rl_twins_rank_keeps; light: the frame's light level). */
int rl_clip_refuses(const rl_recog *rec, const rl_image *img, int light, const rl_detection *d);

#endif
