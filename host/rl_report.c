#include "rl_report.h"

#include "rl_clock.h"

#include <string.h>

rl_err rl_report_run(rl_heap_recog *hr, const rl_image *img, rl_result *res, double *elapsed_us)
{
    uint64_t t0;
    rl_err e;
    /* a recognizer made for a new size is not part of the time */
    if (img != NULL && rl_image_valid(img) && (e = rl_heap_recog_prepare(hr, img->width, img->height)) != RL_OK)
        return e;
    t0 = rl_clock_now_us();
    e = rl_heap_recog_run(hr, img, res);
    if (elapsed_us)
        *elapsed_us = (double)(rl_clock_now_us() - t0);
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
    fprintf(f, ", \"width\": %d, \"height\": %d, \"elapsed_us\": %.1f, \"gamma\": %.1f, \"landmarks\": [",
            res->width, res->height, elapsed_us, res->gamma);
    for (i = 0; i < res->n_landmarks; i++) {
        const rl_detection *d = &res->landmarks[i];
        char code[RL_MAX_BITS + 1];
        if (rl_family_code(fam, d->id, code, sizeof code) != RL_OK)
            code[0] = '\0';
        fprintf(f,
                "%s{\"id\": %d, \"code\": \"%s\", \"u\": %.2f, \"v\": %.2f, \"radius\": %.2f, "
                "\"score\": %.3f, \"runner_up\": %.3f, \"pass\": \"%s\", \"complete\": %s}",
                i ? ", " : "", d->id, code, d->u, d->v, d->radius, d->score, d->runner_up,
                d->pass == RL_PASS_LOCAL ? "local" : "global", d->complete ? "true" : "false");
    }
    fprintf(f, "], \"unidentified\": %d", res->n_unidentified);
    /* what a compile-time limit left out: nothing is cut silently */
    fprintf(f, ", \"dropped\": {\"regions\": %d, \"lights\": %d, \"candidates\": %d, "
               "\"landmarks\": %d}",
            res->dropped.regions, res->dropped.lights, res->dropped.candidates,
            res->dropped.landmarks);
}
