/* ringloc fuse's output and its live mode, for cmd_fuse.c: the fused pose
 * as a JSON line, each frame's fate as a line, and the loop that fuses
 * odometry lines from a stream with pose frames from a device as both
 * come, printing the pose at every odometry sample.
 *
 *   static rl_fuse f;                // initialised (rl_fuse_init)
 *   unsigned long frames = 0;
 *   int dev_fd = 3;                  // an open serial device (rl_serial_open)
 *   int rc = rl_fuse_live("fuse", &f, 0, dev_fd, "/dev/ttyUSB1", 115200, stdout, NULL, &frames);
 *   // 0 when the odometry ended, the device closed or a signal came
 */
#ifndef CMD_FUSE_LIVE_H
#define CMD_FUSE_LIVE_H

#include <stdio.h>
#include "rl_fuse.h"

/* p as one JSON line */
void rl_fuse_print_pose(FILE *out, const rl_fuse_pose *p);

/* the fate decided since the last call (*seen: the events seen), if any,
 * as a line 'seq capture_s fate d2 clock_reset' of fates (NULL: none) */
void rl_fuse_log_fate(const rl_fuse *f, unsigned long *seen, FILE *fates);

/* Odometry lines ('t x y yaw', times on CLOCK_MONOTONIC, increasing) from
 * odo_fd and pose frames from dev_fd (stamped on arrival with
 * CLOCK_MONOTONIC, baud for their bytes' time) until the odometry ends,
 * the device closes or SIGINT/SIGTERM; the pose at each odometry sample
 * printed and flushed, *frames counting the pose frames. 0, or an exit
 * code after the error line (a malformed or backward odometry line, a
 * device that fails). */
int rl_fuse_live(const char *C, rl_fuse *f, int odo_fd, int dev_fd, const char *dev_name, int baud,
                 FILE *out, FILE *fates, unsigned long *frames);

#endif
