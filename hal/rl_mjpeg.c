#include "rl_mjpeg.h"

#include <stdio.h>
#include <stdlib.h>
#include <turbojpeg.h>

struct rl_mjpeg {
    tjhandle tj;
};

rl_mjpeg *rl_mjpeg_new(void)
{
    rl_mjpeg *j = (rl_mjpeg *)malloc(sizeof *j);
    if (j == NULL)
        return NULL;
    if ((j->tj = tjInitDecompress()) == NULL) {
        free(j);
        return NULL;
    }
    return j;
}

void rl_mjpeg_free(rl_mjpeg *j)
{
    if (j == NULL)
        return;
    tjDestroy(j->tj);
    free(j);
}

rl_err rl_mjpeg_grey(rl_mjpeg *j, const uint8_t *jpeg, size_t n, int width, int height,
                     uint8_t *grey, char *err, size_t errlen)
{
    int w = 0, h = 0, sub = 0, space = 0;
    if (n < 4 || jpeg[0] != 0xff || jpeg[1] != 0xd8) {
        snprintf(err, errlen, "not a JPEG frame (%lu bytes)", (unsigned long)n);
        return RL_EFORMAT;
    }
    if (tjDecompressHeader3(j->tj, jpeg, (unsigned long)n, &w, &h, &sub, &space) != 0) {
        snprintf(err, errlen, "JPEG header: %s", tjGetErrorStr2(j->tj));
        return RL_EFORMAT;
    }
    if (w != width || h != height) {
        snprintf(err, errlen, "JPEG frame is %dx%d, not %dx%d", w, h, width, height);
        return RL_EFORMAT;
    }
    /* a truncated frame decodes with a warning (grey below the cut):
     * only a clean decode is a frame */
    if (tjDecompress2(j->tj, jpeg, (unsigned long)n, grey, width, width, height, TJPF_GRAY, 0) != 0) {
        snprintf(err, errlen, "JPEG data: %s", tjGetErrorStr2(j->tj));
        return RL_EFORMAT;
    }
    return RL_OK;
}
