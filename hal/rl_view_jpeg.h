/* rl_view_jpeg: a grey frame as a JPEG for the live web view, scaled down
 * to the width a browser asks for (box filter: each output pixel the
 * mean of the pixels it covers). One encoder per server thread, made at
 * start; the JPEG it gives stays valid until the next encode or free.
 *
 *   static uint8_t grey[640 * 480];
 *   const uint8_t *jpeg;
 *   size_t n;
 *   rl_view_jpeg *j = rl_view_jpeg_new(640, 480);
 *   if (j && rl_view_jpeg_encode(j, grey, 640, 480, 320, &jpeg, &n) == RL_OK)
 *       use(jpeg, n);                   // 320 x 240
 *   rl_view_jpeg_free(j);
 */
#ifndef RL_VIEW_JPEG_H
#define RL_VIEW_JPEG_H

#include <stddef.h>
#include <stdint.h>
#include "rl_error.h"

#define RL_VIEW_JPEG_QUALITY 80
#define RL_VIEW_JPEG_MIN_WIDTH 16 /* narrower asks are answered at this width */

typedef struct rl_view_jpeg rl_view_jpeg;

/* An encoder for frames of at most w x h; NULL when out of memory. */
rl_view_jpeg *rl_view_jpeg_new(int w, int h);
void rl_view_jpeg_free(rl_view_jpeg *j);

/* Encode the packed w x h grey image at out_w wide (clamped to
 * RL_VIEW_JPEG_MIN_WIDTH .. w; the height keeps the aspect). *jpeg, *n:
 * the encoder's buffer. RL_EINVAL for a size beyond the encoder's, RL_EIO
 * when libturbojpeg fails. */
RL_CHECK rl_err rl_view_jpeg_encode(rl_view_jpeg *j, const uint8_t *grey, int w, int h, int out_w,
                                    const uint8_t **jpeg, size_t *n);

/* The JPEG the last successful encode gave (NULL before one). */
const uint8_t *rl_view_jpeg_data(const rl_view_jpeg *j);

#endif
