/* ringloc-bench --real DIR: real ceiling photos with landmarks placed in
 * them (host/rl_composite.h), and AprilTag 36h11 tags of the same size at
 * the same places with the same looks, through ringloc and AprilTag 3
 * side by side: identification rates by kind of place, wrong and false
 * detections, time per frame. The photos' own false landmarks are counted
 * on the photos as they are. */
#define _GNU_SOURCE
#include "bench_real.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <apriltag/tag36h11.h>
#include "rl_clock.h"
#include "rl_composite.h"
#include "rl_png.h"
#include "rl_report.h"
#include "bench_stages.h"

typedef struct {
    long placed[3], found[3], wrong, false_det;
    double us;
    long frames;
} score;

static image_u8_t *tag_images[64];

/* tag36h11's bitmap as a pattern: 10 x 10 cells, the black border's 8
 * cells spanning the landmark's diameter. */
static double tag_pattern(const void *ctx, int id, double x, double y)
{
    int ci = (int)floor(x / 0.25 + 5), cj = (int)floor(y / 0.25 + 5);
    const image_u8_t *im = tag_images[id % 64];
    (void)ctx;
    if (ci < 0 || cj < 0 || ci >= 10 || cj >= 10)
        return 0.0;
    return im->buf[cj * im->stride + ci] < 128 ? 1.0 : 0.0;
}



static void judge(score *s, const rl_site_mark *m, int n, int id, double u, double v)
{
    int k = rl_composite_mark_at(m, n, u, v);
    if (k < 0)
        s->false_det++;
    else if (m[k].id == id)
        s->found[m[k].kind]++;
    else
        s->wrong++;
}

static void print_row(const char *what, const score *a, const score *b, int kind)
{
    printf("%-24s %9.1f%% %11.1f%%   (%ld placed)\n", what,
           a->placed[kind] ? 100.0 * a->found[kind] / a->placed[kind] : 0.0,
           b->placed[kind] ? 100.0 * b->found[kind] / b->placed[kind] : 0.0, a->placed[kind]);
}


/* One photo, one round: rings and tags at the same places. */
static void one_frame(const rl_image *photo, rl_composite_config *cc, const int *ids, int n_ids,
                      rl_heap_recog *hr, apriltag_detector_t *td, uint8_t *a, uint8_t *b,
                      score *ring, score *tag, rl_bench_stages *st)
{
    static rl_result res;
    rl_site_mark marks[RL_COMPOSITE_MAX];
    rl_image ia = rl_image_view(photo->width, photo->height, photo->width, a);
    rl_image ib = rl_image_view(photo->width, photo->height, photo->width, b);
    rl_family fam = {5};
    int y, n, i;
    double us;
    uint64_t t0;
    zarray_t *dets;
    for (y = 0; y < photo->height; y++) {
        memcpy(a + (size_t)y * (size_t)photo->width, photo->data + (size_t)y * (size_t)photo->stride,
               (size_t)photo->width);
        memcpy(b + (size_t)y * (size_t)photo->width, photo->data + (size_t)y * (size_t)photo->stride,
               (size_t)photo->width);
    }
    n = rl_composite_plan(&ia, cc, ids, n_ids, marks);
    rl_composite_draw(&ia, cc, marks, n, rl_composite_ring, &fam);
    rl_composite_draw(&ib, cc, marks, n, tag_pattern, NULL);
    for (i = 0; i < n; i++) {
        ring->placed[marks[i].kind]++;
        tag->placed[marks[i].kind]++;
    }
    rl_bench_stages_unit(st, &ia);
    if (rl_report_run(hr, &ia, &res, &us) == RL_OK) {
        ring->us += us;
        ring->frames++;
        rl_bench_stages_count(st, &res);
        for (i = 0; i < res.n_landmarks; i++)
            judge(ring, marks, n, res.landmarks[i].id, res.landmarks[i].u, res.landmarks[i].v);
    }
    t0 = rl_clock_now_us();
    {
        image_u8_t im = {ib.width, ib.height, ib.stride, ib.data};
        dets = apriltag_detector_detect(td, &im);
    }
    tag->us += (double)(rl_clock_now_us() - t0);
    tag->frames++;
    for (i = 0; i < zarray_size(dets); i++) {
        apriltag_detection_t *det;
        zarray_get(dets, i, &det);
        judge(tag, marks, n, det->id, det->c[0], det->c[1]);
    }
    apriltag_detections_destroy(dets);
}

int rl_bench_real(const char *dir, int rounds, int seed, double radius, apriltag_detector_t *td,
                  apriltag_family_t *tf)
{
    static rl_result res;
    static rl_bench_stages st, as_is; /* the composited frames' stages; the photos' own run apart */
    char **names;
    score ring, tag;
    rl_composite_config cc;
    rl_recog_config cfg;
    rl_heap_recog hr;
    int ids[30], n, p, r, i, photos = 0;
    long false_as_is = 0;
    uint8_t *a = NULL, *b = NULL;
    char err[512];
    memset(&ring, 0, sizeof ring);
    memset(&tag, 0, sizeof tag);
    for (i = 0; i < 30; i++)
        ids[i] = i + 1;
    for (i = 0; i < 64; i++)
        tag_images[i] = apriltag_to_image(tf, (uint32_t)i);
    if (rl_png_list(dir, &names, &n, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-bench: %s\n", err);
        return 1;
    }
    if (n == 0) {
        fprintf(stderr, "ringloc-bench: %s: no PNG photos\n", dir);
        return 1;
    }
    rl_composite_defaults(&cc);
    cc.radius_px = radius;
    cc.seed = (uint64_t)seed;
    rl_recog_defaults(&cfg);
    rl_bench_stages_start(&st, &cfg);
    rl_heap_recog_init(&hr, &cfg);
    for (p = 0; p < n; p++) {
        rl_image img;
        if (rl_png_read_gray(names[p], &img, err, sizeof err) != RL_OK) {
            fprintf(stderr, "ringloc-bench: %s (skipped)\n", err);
            continue;
        }
        free(a);
        free(b);
        a = malloc((size_t)img.width * (size_t)img.height);
        b = malloc((size_t)img.width * (size_t)img.height);
        if (a == NULL || b == NULL)
            return 1;
        as_is = st;
        if (rl_heap_recog_run(&hr, &img, &res) == RL_OK)
            false_as_is += res.n_landmarks;
        st = as_is;
        for (r = 0; r < rounds; r++)
            one_frame(&img, &cc, ids, 30, &hr, td, a, b, &ring, &tag, &st);
        rl_png_free(&img);
        photos++;
        if (photos % 20 == 0)
            fprintf(stderr, "ringloc-bench: %d of %d photos\r", photos, n);
    }
    fprintf(stderr, "\n");
    rl_png_list_free(names, n);
    if (photos == 0) {
        fprintf(stderr, "ringloc-bench: %s: no readable PNG photo\n", dir);
        return 1;
    }
    printf("real photos: %s, %d photos x %d rounds, landmarks of radius %.1f px, seed %d\n", dir,
           photos, rounds, radius, seed);
    printf("%-24s %10s %12s\n", "identified", "ringloc", "AprilTag 3");
    print_row("wholly inside", &ring, &tag, 0);
    print_row("within 1 R of a light", &ring, &tag, 1);
    print_row("cut by the border", &ring, &tag, 2);
    printf("%-24s %10ld %12ld\n", "wrong ids", ring.wrong, tag.wrong);
    printf("%-24s %10ld %12ld\n", "false (composited)", ring.false_det, tag.false_det);
    printf("%-24s %10ld\n", "false (photos as they are)", false_as_is);
    printf("%-24s %10.3f %12.3f   (AprilTag / ringloc: %.1fx)\n", "ms per frame",
           ring.frames ? ring.us / ring.frames / 1000 : 0.0, tag.frames ? tag.us / tag.frames / 1000 : 0.0,
           ring.us > 0 ? (tag.us / tag.frames) / (ring.us / ring.frames) : 0.0);
    rl_bench_stages_print(&st, "real photos with landmarks placed in them", tag.frames ? tag.us / tag.frames : 0.0);
    free(a);
    free(b);
    rl_heap_recog_free(&hr);
    return 0;
}
