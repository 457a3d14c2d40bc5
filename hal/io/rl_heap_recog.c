#include "rl_heap_recog.h"

#include <stdlib.h>
#include <string.h>

void rl_heap_recog_init(rl_heap_recog *hr, const rl_recog_config *cfg)
{
    memset(hr, 0, sizeof *hr);
    hr->cfg = *cfg;
    if (cfg->ids != NULL && cfg->n_ids > 0) {
        int n = cfg->n_ids < RL_MAX_IDS ? cfg->n_ids : RL_MAX_IDS;
        memcpy(hr->ids, cfg->ids, (size_t)n * sizeof(int));
        hr->cfg.ids = hr->ids; /* n_ids stays as given: init reports RL_ELIMIT */
    }
}

void rl_heap_recog_init_map(rl_heap_recog *hr, const rl_recog_config *cfg, const rl_map *map)
{
    rl_recog_config c = *cfg;
    int ids[RL_MAX_IDS];
    rl_recog_use_map(&c, map, ids);
    rl_heap_recog_init(hr, &c);
}

void rl_heap_recog_free(rl_heap_recog *hr)
{
    free(hr->mem);
    hr->mem = NULL;
    hr->rec = NULL;
    hr->width = hr->height = 0;
}

rl_err rl_heap_recog_prepare(rl_heap_recog *hr, int w, int h)
{
    size_t need;
    rl_err e;
    if (hr->rec != NULL && w == hr->width && h == hr->height)
        return RL_OK;
    rl_heap_recog_free(hr);
    need = rl_recog_workspace_size(w, h, &hr->cfg);
    if (need == 0) {
        /* a bad configuration: init checks it before it looks at memory,
         * and says what is wrong */
        unsigned char none;
        e = rl_recog_init(&hr->rec, &hr->cfg, w, h, &none, 0);
        return e != RL_OK ? e : RL_EINVAL;
    }
    if ((hr->mem = malloc(need)) == NULL)
        return RL_ENOMEM;
    memset(hr->mem, 0, need); /* its pages faulted in now, not in the first frame's time */
    hr->size = need;
    if ((e = rl_recog_init(&hr->rec, &hr->cfg, w, h, hr->mem, need)) != RL_OK) {
        rl_heap_recog_free(hr);
        return e;
    }
    hr->width = w;
    hr->height = h;
    return RL_OK;
}

rl_err rl_heap_recog_run(rl_heap_recog *hr, const rl_image *img, rl_result *res)
{
    rl_err e;
    if (img == NULL || !rl_image_valid(img))
        return RL_EINVAL;
    if ((e = rl_heap_recog_prepare(hr, img->width, img->height)) != RL_OK)
        return e;
    return rl_recog_run(hr->rec, img, res);
}
