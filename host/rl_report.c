#include "rl_report.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

void rl_host_recog_init(rl_host_recog *hr, const rl_recog_config *cfg)
{
    memset(hr, 0, sizeof *hr);
    hr->cfg = *cfg;
}

void rl_host_recog_free(rl_host_recog *hr)
{
    free(hr->mem);
    hr->mem = NULL;
    hr->width = hr->height = 0;
}

double rl_now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e6 + ts.tv_nsec / 1e3;
}

rl_err rl_host_recog_run(rl_host_recog *hr, const rl_image *img, rl_result *res,
                         double *elapsed_us)
{
    double t0;
    rl_err e;
    if (img->width != hr->width || img->height != hr->height) {
        size_t need = rl_recog_workspace_size(img->width, img->height, &hr->cfg);
        if (need == 0)
            return RL_EINVAL;
        free(hr->mem);
        hr->mem = malloc(need);
        hr->width = hr->height = 0;
        if (hr->mem == NULL)
            return RL_ENOMEM;
        hr->size = need;
        if ((e = rl_recog_init(&hr->rec, &hr->cfg, img->width, img->height, hr->mem, need)) != RL_OK)
            return e;
        hr->width = img->width;
        hr->height = img->height;
    }
    t0 = rl_now_us();
    e = rl_recog_run(&hr->rec, img, res);
    if (elapsed_us)
        *elapsed_us = rl_now_us() - t0;
    return e;
}

void rl_json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c < 0x20)
            fprintf(f, "\\u%04x", c);
        else
            fputc(c, f);
    }
    fputc('"', f);
}

void rl_report_json_open(FILE *f, const char *image, const rl_result *res, const rl_family *fam,
                         double elapsed_us)
{
    int i;
    fprintf(f, "{\"image\": ");
    rl_json_string(f, image);
    fprintf(f, ", \"width\": %d, \"height\": %d, \"elapsed_us\": %.1f, \"landmarks\": [",
            res->width, res->height, elapsed_us);
    for (i = 0; i < res->n_landmarks; i++) {
        const rl_detection *d = &res->landmarks[i];
        char code[RL_MAX_BITS + 1];
        if (rl_family_code(fam, d->id, code, sizeof code) != RL_OK)
            code[0] = '\0';
        fprintf(f,
                "%s{\"id\": %d, \"code\": \"%s\", \"u\": %.2f, \"v\": %.2f, \"radius\": %.1f, "
                "\"score\": %.3f, \"pass\": \"%s\", \"complete\": %s}",
                i ? ", " : "", d->id, code, d->u, d->v, d->radius, d->score,
                d->pass == RL_PASS_LOCAL ? "local" : "global", d->complete ? "true" : "false");
    }
    fprintf(f, "], \"unidentified\": %d", res->n_unidentified);
}
