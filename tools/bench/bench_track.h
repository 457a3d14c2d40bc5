/* bench_track: tracking windows against full frames on an ordered drive
 * (ringloc-bench --track DIR:PREFIX): the drive's frames through the one
 * loop (rl_run, as `ringloc locate` runs them) three times, every frame in
 * full, tracked (rl_track.h), and tracked with at most 3 reads a frame
 * (rl_track_config.max_reads), each frame's recognition time beside one
 * histogram pass over the same frame measured in the same run, then the
 * time of localizing the frame (the place and the pose, rl_run's pose_us)
 * and of the frame with it, in the same passes, and,
 * against the renderer's truth (NAME.yaml), the whole landmarks read
 * right, the wrong ids and the poses within 5 cm, side by side.
 *
 *   rl_bench_track("build/bench/site", "corner_");  // map.yaml, camera.yaml, robot.yaml
 */
#ifndef BENCH_TRACK_H
#define BENCH_TRACK_H

/* Print the figures for dir's frames named PREFIX*.png; 0 on success. */
int rl_bench_track(const char *dir, const char *prefix);

#endif
