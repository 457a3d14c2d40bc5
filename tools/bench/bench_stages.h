/* bench_stages: the recognizer's stages (rl_stage.h) timed through its
 * hook, and printed per frame in microseconds and in histogram passes:
 * the time of one histogram of the whole frame (every pixel), measured on
 * the same frames in the same run, a unit that does not depend on the
 * machine.
 *
 *   rl_bench_stages st;
 *   rl_bench_stages_start(&st, &cfg);          // before the recognizer is made
 *   ... recognize frames; rl_bench_stages_unit(&st, &img) once per frame ...
 *   ... rl_bench_stages_count(&st, &res) after a frame's run, for the candidate counts ...
 *   rl_bench_stages_print(&st, "640x480 twins", apriltag_us);
 */
#ifndef BENCH_STAGES_H
#define BENCH_STAGES_H

#include <stdint.h>
#include "rl_image.h"
#include "rl_recog.h"

typedef struct {
    double ns[RL_STAGE_DONE]; /* summed over every run */
    long runs;                /* frames recognized (RL_STAGE_DONE calls) */
    int fastest_of;           /* 0: ns sums every run; n: each frame's fastest of n runs */
    double unit_ns;           /* summed whole-frame histogram passes */
    long units;
    long reads, tried, taken, landmarks, counted; /* rl_bench_stages_count's sums */
    rl_stage cur;
    uint64_t t0;
    int open;
} rl_bench_stages;

/* Zero st and put its hook into cfg. */
void rl_bench_stages_start(rl_bench_stages *st, rl_recog_config *cfg);

/* Monotonic nanoseconds. */
uint64_t rl_bench_ns(void);

/* Add ns to stage s (the caller's own stages: pose, place). */
void rl_bench_stages_add(rl_bench_stages *st, rl_stage s, double ns);

/* One whole-frame histogram pass over img, timed (the least of a few). */
void rl_bench_stages_unit(rl_bench_stages *st, const rl_image *img);

/* A frame's candidates, from its result: the CLRs read as the global pass
 * and the second labellings read them, the local pass's tries and those
 * it took, the landmarks reported. */
void rl_bench_stages_count(rl_bench_stages *st, const rl_result *res);

/* The table: each stage's time per frame (us; the mean over runs, or of
 * each frame's fastest run, as fastest_of says) and in histogram
 * passes, the total, and a peer's time per frame (AprilTag 3; 0: none)
 * beside it; then the candidates a frame, when counted. */
void rl_bench_stages_print(const rl_bench_stages *st, const char *what, double peer_us);

#endif
