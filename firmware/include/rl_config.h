/* rl_config: every compile-time limit of the recognition core, in one place.
 *
 * Each can be overridden with -D at build time (a board's defaults file is
 * the place for that). Each bounds a fixed-size array somewhere in the
 * core; what a limit leaves out of a frame is counted in rl_result.dropped
 * (or, for the labeller's runs, reported as RL_ELIMIT), never overrun and
 * never cut silently.
 *
 *   static rl_detection kept[RL_MAX_LANDMARKS];   // room for every landmark of a frame
 *   use(kept, RL_MAX_IDS);
 */
#ifndef RL_CONFIG_H
#define RL_CONFIG_H

/* Largest image width or height accepted (bounds per-row index arrays). */
#ifndef RL_MAX_IMAGE_DIM
#define RL_MAX_IMAGE_DIM 8192
#endif

/* Most code zones of a family (the spec's ring2..ring8). */
#ifndef RL_MAX_BITS
#define RL_MAX_BITS 8
#endif

/* Most landmarks reported per frame (size of the result array). */
#ifndef RL_MAX_LANDMARKS
#define RL_MAX_LANDMARKS 64
#endif

/* Most candidate landmark regions (CLRs) examined per frame. */
#ifndef RL_MAX_CANDIDATES
#define RL_MAX_CANDIDATES 256
#endif

/* Most connected dark regions kept per frame after speck removal. */
#ifndef RL_MAX_REGIONS
#define RL_MAX_REGIONS 4096
#endif

/* Light-source regions recorded per frame (for the local pass and drawing). */
#ifndef RL_MAX_LIGHTS
#define RL_MAX_LIGHTS 32
#endif

/* Dark runs the labeller holds, as pixels per run: w*h/8 runs is ~1 byte
 * per pixel of workspace and 80 dark segments per 640-pixel row. */
#ifndef RL_PIXELS_PER_RUN
#define RL_PIXELS_PER_RUN 8
#endif

/* Most landmarks in one map (a map may repeat ids: 60 m x 40 m at 0.61 m
 * is about 6,500); an rl_map is 40 bytes per landmark of this. */
#ifndef RL_MAX_MAP_LANDMARKS
#define RL_MAX_MAP_LANDMARKS 8192
#endif

/* Most distinct ids a recognizer is told to look for (the largest family,
 * ring8, has 254). */
#ifndef RL_MAX_IDS
#define RL_MAX_IDS 256
#endif

#endif
