/* The recognizer on arbitrary frames, sizes and strides: the first bytes
 * choose width, height, padding and configuration, the rest are pixels
 * (repeated to fill the frame). It may refuse; it must not crash, read
 * outside the frame or report a non-finite landmark. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rl_recog.h"

static uint8_t frame[320 * 256 + 64 * 256];
static rl_result res;

/* The recognizer of the last input, kept while its size and
 * configuration stay (its templates take milliseconds to make). */
static struct {
    int w, h, bits, local, score;
    void *mem;
    rl_recog *rec;
} kept;

static rl_recog *recognizer(int w, int h, int bits, int local, int score)
{
    rl_recog_config cfg;
    size_t n;
    if (kept.rec && kept.w == w && kept.h == h && kept.bits == bits && kept.local == local &&
        kept.score == score)
        return kept.rec;
    free(kept.mem);
    memset(&kept, 0, sizeof kept);
    rl_recog_defaults(&cfg);
    cfg.local = (rl_local_policy)local;
    cfg.family.bits = bits;
    cfg.min_score = 0.5 + score / 100.0;
    cfg.skip_rivals = 1; /* rl_recog_run never uses them; a recognizer an input */
    n = rl_recog_workspace_size(w, h, &cfg);
    if (n == 0 || (kept.mem = malloc(n)) == NULL)
        return NULL;
    if (rl_recog_init(&kept.rec, &cfg, w, h, kept.mem, n) != RL_OK) {
        free(kept.mem);
        memset(&kept, 0, sizeof kept);
        return NULL;
    }
    kept.w = w;
    kept.h = h;
    kept.bits = bits;
    kept.local = local;
    kept.score = score;
    return kept.rec;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rl_recog *rec;
    size_t i;
    int w, h, pad, k;
    rl_image img;
    if (size < 6)
        return 0;
    w = 1 + data[0] % 320;
    h = 1 + data[1] % 256;
    pad = data[2] % 64;
    rec = recognizer(w, h, 3 + data[4] % 6, data[3] % 3, data[5] % 50);
    data += 6;
    size -= 6;
    if (rec == NULL)
        return 0;
    for (i = 0; i < (size_t)(w + pad) * (size_t)h; i++)
        frame[i] = size ? data[i % size] : 0;
    img = rl_image_view(w, h, w + pad, frame);
    if (rl_recog_run(rec, &img, &res) == RL_OK)
        for (k = 0; k < res.n_landmarks; k++)
            if (!isfinite(res.landmarks[k].u) || !isfinite(res.landmarks[k].v) ||
                !isfinite(res.landmarks[k].radius) || !isfinite(res.landmarks[k].score))
                abort();
    return 0;
}
