/* rl_mjpeg: MJPEG camera frames to grey (libturbojpeg). One decoder per
 * camera, made at open; decoding writes into the caller's frame.
 *
 *   static uint8_t grey[640 * 480];
 *   const uint8_t *jpeg = frame.data;   // n bytes of a camera's MJPEG frame
 *   size_t n = 1000;
 *   rl_mjpeg *j = rl_mjpeg_new();
 *   char err[128];
 *   if (j && rl_mjpeg_grey(j, jpeg, n, 640, 480, grey, err, sizeof err) == RL_OK)
 *       use(grey);
 *   rl_mjpeg_free(j);
 */
#ifndef RL_MJPEG_H
#define RL_MJPEG_H

#include <stddef.h>
#include <stdint.h>
#include "rl_error.h"

typedef struct rl_mjpeg rl_mjpeg;

rl_mjpeg *rl_mjpeg_new(void); /* NULL when out of memory */
void rl_mjpeg_free(rl_mjpeg *j);

/* Decode n bytes of JPEG to width x height grey (packed) in grey.
 * RL_EFORMAT (err says why) when it is not a whole JPEG of that size. */
RL_CHECK rl_err rl_mjpeg_grey(rl_mjpeg *j, const uint8_t *jpeg, size_t n, int width, int height,
                              uint8_t *grey, char *err, size_t errlen);

#endif
