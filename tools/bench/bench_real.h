/* bench_real: ringloc and AprilTag 3 on real photos with landmarks and
 * tags composited at the same places (ringloc-bench --real).
 *
 *   rl_bench_real("photos/", 3, 1, 25.7, td, tf);
 */
#ifndef BENCH_REAL_H
#define BENCH_REAL_H

#include <apriltag/apriltag.h>

/* Print the comparison table for the PNG photos of dir; 0 on success. */
int rl_bench_real(const char *dir, int rounds, int seed, double radius, apriltag_detector_t *td,
                  apriltag_family_t *tf);

#endif
