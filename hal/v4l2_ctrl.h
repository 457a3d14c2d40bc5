/* v4l2_ctrl: exposure and gain through V4L2 controls, and the list of a
 * device's controls for --probe. Internal to the V4L2 camera.
 *
 *   v4l2_dev d;
 *   char info[96], why[128];
 *   if (v4l2_dev_open(&d, NULL, "/dev/video0", why, sizeof why) == RL_OK &&
 *       v4l2_ctrl_apply(&d, 10000, 0, info, sizeof info, why, sizeof why) == RL_OK)
 *       use(info);                                  // "exposure 10000 us, gain auto"
 */
#ifndef V4L2_CTRL_H
#define V4L2_CTRL_H

#include <stddef.h>
#include "rl_cam.h"
#include "v4l2_dev.h"

/* exposure_us 0: automatic, else manual at that time (V4L2 counts 100 us);
 * gain 0: automatic, else manual at that value. RL_OK with what was set
 * in info; RL_EUNSUPPORTED with what naming the control the device does
 * not offer or the range a value is outside. */
RL_CHECK rl_err v4l2_ctrl_apply(const v4l2_dev *d, int exposure_us, double gain, char *info,
                                size_t ilen, char *what, size_t wlen);

/* One line per control: name, range, step, default and current value. */
void v4l2_ctrl_list(const v4l2_dev *d, rl_cam_line_fn line, void *ctx);

#endif
