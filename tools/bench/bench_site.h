/* bench_site: the place finder on a large site (ringloc-bench --site):
 * the index's bytes per map landmark and build time, and the cost of
 * finding the place per frame with no prior and with the last pose,
 * beside the same frames' recognition and pose solve.
 *
 *   rl_bench_site("build/bench/site");   // map.yaml, camera.yaml, robot.yaml, random_NNN.png
 */
#ifndef BENCH_SITE_H
#define BENCH_SITE_H

/* Print the figures for the site of dir; 0 on success. */
int rl_bench_site(const char *dir);

#endif
