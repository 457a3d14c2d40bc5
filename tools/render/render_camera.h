/* render_camera: the upward-looking camera that sees a render_scene:
 * where it is (the robot's pose, its mount and tilt, the robot rocking),
 * where a ceiling point falls in its image (pinhole + plumb_bob, the
 * core's own rl_calib model), and the frame it delivers: every pixel's
 * subsamples ray-cast onto the ceiling (moved and turned by the motion
 * blur), vignetting, the light across the frame, then the sensor
 * (render_sensor).
 *
 *   static render_scene s;
 *   render_mount m = {0.12, -0.03, 0.02, 0, 0};
 *   render_camera_default(&s.cam, 640, 480);
 *   render_camera_pose(&s, &m, 1.0, 2.0, 0.3, 0, 0);
 *   if (render_camera_frame(&s, pixels) == 0)       // pixels: 640 x 480 bytes
 *       use(pixels);
 *   render_camera_free();
 */
#ifndef RENDER_CAMERA_H
#define RENDER_CAMERA_H

#include <stdint.h>
#include "render_scene.h"

/* The camera on the robot: offset in the robot frame, yaw, and tilt
 * (roll about the robot's x, pitch about its y), radians. */
typedef struct {
    double x, y, yaw, roll, pitch;
} render_mount;

/* The default camera: 640x480-like, 70 degrees, mild barrel distortion,
 * its principal point a little off centre (scaled to w x h). */
void render_camera_default(rl_calib *cam, int w, int h);

/* The camera's pose in s (R, cx, cy, cz, yaw, pitch, roll) from the
 * robot's pose, its mount (at s->cam_z above the floor) and the robot's
 * rocking (roll rr, pitch rp about its footprint on the floor). */
void render_camera_pose(render_scene *s, const render_mount *m, double rx, double ry, double ryaw, double rr,
                        double rp);

/* A rolling shutter's readout of readout_s seconds while the robot at
 * heading yaw drives forward at speed (m/s) and turns at turn (rad/s): the
 * camera's travel and turn from the first row to the last into s (the
 * frame's pose is its middle row's). All 0: a global shutter. */
void render_camera_shutter(render_scene *s, const render_mount *m, double yaw, double readout_s, double speed,
                           double turn);

/* Map point (X, Y), drop below the ceiling (0: on it) -> pixel (u, v). */
void render_camera_to_pixel(const render_scene *s, double X, double Y, double drop, double *u, double *v);

/* The frame s shows into out (s->cam.width x s->cam.height bytes): 0, or
 * -1 out of memory. Uses the random stream (render_random) for the
 * sensor's noise. */
int render_camera_frame(const render_scene *s, uint8_t *out);

/* The rays cached for the last camera, freed. */
void render_camera_free(void);

#endif
