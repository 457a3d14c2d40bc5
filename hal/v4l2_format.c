#include "v4l2_format.h"

#include <linux/videodev2.h>
#include <stdio.h>

static const v4l2f formats[] = {
    {V4L2_PIX_FMT_GREY, "GREY", V4L2F_PLANE, 0, 1, 0},
    {V4L2_PIX_FMT_NV12, "NV12", V4L2F_PLANE, 0, 1, 1},
    {V4L2_PIX_FMT_YUV420, "YU12", V4L2F_PLANE, 0, 1, 1},
    {V4L2_PIX_FMT_YUYV, "YUYV", V4L2F_PACKED, 0, 2, 0},
    {V4L2_PIX_FMT_UYVY, "UYVY", V4L2F_PACKED, 1, 2, 0},
    {V4L2_PIX_FMT_MJPEG, "MJPG", V4L2F_JPEG, 0, 0, 0},
};
#define N_FORMATS ((int)(sizeof formats / sizeof formats[0]))

const v4l2f *v4l2f_all(int *n)
{
    *n = N_FORMATS;
    return formats;
}

const v4l2f *v4l2f_find(uint32_t fourcc)
{
    int i;
    for (i = 0; i < N_FORMATS; i++)
        if (formats[i].fourcc == fourcc)
            return &formats[i];
    return NULL;
}

int v4l2f_rank(uint32_t fourcc)
{
    int i;
    for (i = 0; i < N_FORMATS; i++)
        if (formats[i].fourcc == fourcc)
            return i;
    return 1000;
}

void v4l2f_name(uint32_t fourcc, char out[8])
{
    int i;
    for (i = 0; i < 4; i++) {
        char ch = (char)((fourcc >> (8 * i)) & 0xff);
        out[i] = ch >= 32 && ch < 127 ? ch : '?';
    }
    out[4] = '\0';
}

size_t v4l2f_frame_bytes(const v4l2f *f, size_t stride, int height)
{
    size_t plane = stride * (size_t)height;
    if (f->kind == V4L2F_JPEG)
        return 0;
    return plane + (plane / 2) * (size_t)f->chroma_halves;
}

size_t v4l2f_min_stride(const v4l2f *f, int width)
{
    return (size_t)width * (size_t)f->bytes_per_pixel;
}

void v4l2f_copy_luma(const v4l2f *f, const uint8_t *src, size_t stride, int width, int height,
                     uint8_t *dst)
{
    int x, y;
    for (y = 0; y < height; y++) {
        const uint8_t *s = src + (size_t)y * stride + f->y_offset;
        uint8_t *d = dst + (size_t)y * (size_t)width;
        for (x = 0; x < width; x++)
            d[x] = s[2 * x];
    }
}
