/* v4l2_format: the V4L2 pixel formats the camera takes, best first, and
 * how each gives its luminance: GREY, NV12 and YU12 have a Y plane that
 * is lent as it is; YUYV and UYVY carry Y in every other byte (copied out);
 * MJPEG is decoded (rl_mjpeg). Internal to hal/cam_v4l2.c.
 *
 *   int n;
 *   char name[8];
 *   const v4l2f *best = &v4l2f_all(&n)[0];
 *   size_t stride = v4l2f_min_stride(best, 640);
 *   v4l2f_name(best->fourcc, name);                      // "GREY"
 *   use(name, v4l2f_frame_bytes(best, stride, 480));     // 307200
 */
#ifndef V4L2_FORMAT_H
#define V4L2_FORMAT_H

#include <stddef.h>
#include <stdint.h>

typedef enum { V4L2F_PLANE, V4L2F_PACKED, V4L2F_JPEG } v4l2f_kind;

typedef struct {
    uint32_t fourcc;
    const char *name;
    v4l2f_kind kind;
    int y_offset;        /* packed: the first Y byte of a pixel pair */
    int bytes_per_pixel; /* of the first plane (0: compressed) */
    int chroma_halves;   /* bytes of chroma after the Y plane, in halves of it (NV12, YU12: 1) */
} v4l2f;

/* The formats, best first; n of them. */
const v4l2f *v4l2f_all(int *n);
/* The format of a fourcc, or NULL if ringloc does not take it. */
const v4l2f *v4l2f_find(uint32_t fourcc);
/* Its rank (0 best), large for formats ringloc does not take. */
int v4l2f_rank(uint32_t fourcc);
/* "GREY", "YUYV" ... for any fourcc (unknown ones spelled from their bytes). */
void v4l2f_name(uint32_t fourcc, char out[8]);

/* Bytes a whole frame needs at this stride: what the buffer's mapping
 * and bytesused must reach (0 for compressed formats). */
size_t v4l2f_frame_bytes(const v4l2f *f, size_t stride, int height);
/* The smallest stride that holds a row of width pixels. */
size_t v4l2f_min_stride(const v4l2f *f, int width);

/* Packed formats: the Y bytes of a frame into dst (width x height, packed). */
void v4l2f_copy_luma(const v4l2f *f, const uint8_t *src, size_t stride, int width, int height,
                     uint8_t *dst);

#endif
