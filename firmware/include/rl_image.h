/* rl_image: non-owning views of 8-bit grayscale images.
 *
 * A view never owns its pixels; whoever filled `data` frees it. Rows are
 * `stride` bytes apart (stride >= width), and every function honours it,
 * so a view can be a window into a larger frame or a camera buffer.
 *
 *   static uint8_t camera_buffer[480 * 672];      // rows padded to 672 bytes
 *   rl_image view = rl_image_view(640, 480, 672, camera_buffer);
 *   rl_image roi;
 *   if (rl_image_sub(&view, 100, 50, 64, 64, &roi) == RL_OK)
 *       use(roi.data[0], roi.stride);              // 672: a window keeps the stride
 */
#ifndef RL_IMAGE_H
#define RL_IMAGE_H

#include <stddef.h>
#include <stdint.h>
#include "rl_error.h"

typedef struct {
    int width;      /* pixels per row */
    int height;     /* rows */
    int stride;     /* bytes from one row to the next, >= width */
    uint8_t *data;  /* first pixel of the first row; not owned */
} rl_image;

/* Make a view; no checks (use rl_image_valid). */
rl_image rl_image_view(int width, int height, int stride, uint8_t *data);

/* 1 if the view is usable: data set, width/height > 0, stride >= width. */
int rl_image_valid(const rl_image *img);

/* A view of the rectangle (x, y, w, h) of `img`; RL_EINVAL if the rectangle
 * is empty or not entirely inside the image. */
RL_CHECK rl_err rl_image_sub(const rl_image *img, int x, int y, int w, int h,
                             rl_image *out);

/* Pixel at (x, y); the caller guarantees it is inside. */
static inline uint8_t rl_image_at(const rl_image *img, int x, int y)
{
    return img->data[(size_t)y * (size_t)img->stride + (size_t)x];
}

#endif
