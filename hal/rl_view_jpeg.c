#include "rl_view_jpeg.h"

#include <stdlib.h>
#include <turbojpeg.h>

struct rl_view_jpeg {
    tjhandle tj;
    int w, h;
    uint8_t *scaled;         /* w x h at most */
    uint32_t *acc, *cnt;     /* one output row's sums and counts */
    unsigned char *out;      /* libturbojpeg's buffer, grown by it */
    unsigned long out_size;
};

rl_view_jpeg *rl_view_jpeg_new(int w, int h)
{
    rl_view_jpeg *j;
    if (w < 1 || h < 1 || (j = (rl_view_jpeg *)calloc(1, sizeof *j)) == NULL)
        return NULL;
    j->w = w;
    j->h = h;
    j->scaled = (uint8_t *)malloc((size_t)w * (size_t)h);
    j->acc = (uint32_t *)malloc((size_t)w * sizeof *j->acc);
    j->cnt = (uint32_t *)malloc((size_t)w * sizeof *j->cnt);
    j->tj = tjInitCompress();
    if (j->scaled == NULL || j->acc == NULL || j->cnt == NULL || j->tj == NULL) {
        rl_view_jpeg_free(j);
        return NULL;
    }
    return j;
}

void rl_view_jpeg_free(rl_view_jpeg *j)
{
    if (j == NULL)
        return;
    if (j->tj)
        tjDestroy(j->tj);
    tjFree(j->out);
    free(j->scaled);
    free(j->acc);
    free(j->cnt);
    free(j);
}

/* Box filter: source row y goes to output row y * oh / h, column x to
 * x * ow / w; each output pixel is the rounded mean of what fell in it. */
static void scale(rl_view_jpeg *j, const uint8_t *src, int w, int h, int ow, int oh)
{
    int x, y, oy = 0;
    for (x = 0; x < ow; x++)
        j->acc[x] = j->cnt[x] = 0;
    for (y = 0; y < h; y++) {
        const uint8_t *s = src + (size_t)y * (size_t)w;
        int ty = (int)((long)y * oh / h);
        if (ty != oy) {
            for (x = 0; x < ow; x++) {
                j->scaled[(size_t)oy * (size_t)ow + (size_t)x] =
                    (uint8_t)(j->cnt[x] ? (j->acc[x] + j->cnt[x] / 2) / j->cnt[x] : 0);
                j->acc[x] = j->cnt[x] = 0;
            }
            oy = ty;
        }
        for (x = 0; x < w; x++) {
            int tx = (int)((long)x * ow / w);
            j->acc[tx] += s[x];
            j->cnt[tx]++;
        }
    }
    for (x = 0; x < ow; x++)
        j->scaled[(size_t)oy * (size_t)ow + (size_t)x] =
            (uint8_t)(j->cnt[x] ? (j->acc[x] + j->cnt[x] / 2) / j->cnt[x] : 0);
}

rl_err rl_view_jpeg_encode(rl_view_jpeg *j, const uint8_t *grey, int w, int h, int out_w,
                           const uint8_t **jpeg, size_t *n)
{
    const uint8_t *src = grey;
    int ow, oh;
    if (w < 1 || h < 1 || w > j->w || h > j->h || grey == NULL)
        return RL_EINVAL;
    ow = out_w < RL_VIEW_JPEG_MIN_WIDTH ? RL_VIEW_JPEG_MIN_WIDTH : out_w > w ? w : out_w;
    if (ow > w)
        ow = w;
    oh = (int)((long)h * ow / w);
    if (oh < 1)
        oh = 1;
    if (ow != w) {
        scale(j, grey, w, h, ow, oh);
        src = j->scaled;
    }
    if (tjCompress2(j->tj, src, ow, ow, oh, TJPF_GRAY, &j->out, &j->out_size, TJSAMP_GRAY,
                    RL_VIEW_JPEG_QUALITY, 0) != 0)
        return RL_EIO;
    *jpeg = j->out;
    *n = (size_t)j->out_size;
    return RL_OK;
}

const uint8_t *rl_view_jpeg_data(const rl_view_jpeg *j)
{
    return j->out;
}
