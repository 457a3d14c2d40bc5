#define _GNU_SOURCE
#include "bench_stages.h"

#include <stdio.h>
#include <string.h>
#include <time.h>
#include "rl_hist.h"

#define UNIT_REPEAT 5

uint64_t rl_bench_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

/* The hook: the time since the last call is the stage it announced. */
static void enter(void *ctx, rl_stage s)
{
    rl_bench_stages *st = ctx;
    uint64_t now = rl_bench_ns();
    if (st->open)
        st->ns[st->cur] += (double)(now - st->t0);
    st->open = s != RL_STAGE_DONE;
    st->runs += s == RL_STAGE_DONE;
    st->cur = s;
    st->t0 = rl_bench_ns(); /* the hook's own time is left out */
}

void rl_bench_stages_start(rl_bench_stages *st, rl_recog_config *cfg)
{
    memset(st, 0, sizeof *st);
    cfg->stage_hook.enter = enter;
    cfg->stage_hook.ctx = st;
}

void rl_bench_stages_add(rl_bench_stages *st, rl_stage s, double ns)
{
    st->ns[s] += ns;
}

void rl_bench_stages_unit(rl_bench_stages *st, const rl_image *img)
{
    static rl_hist h;
    double best = 0;
    int k;
    for (k = 0; k < UNIT_REPEAT; k++) {
        uint64_t t0 = rl_bench_ns();
        double t;
        rl_hist_compute(img, &h);
        t = (double)(rl_bench_ns() - t0);
        if (k == 0 || t < best)
            best = t;
    }
    st->unit_ns += best;
    st->units++;
}

void rl_bench_stages_count(rl_bench_stages *st, const rl_result *res)
{
    st->reads += res->n_candidates;
    st->tried += res->local_tried;
    st->taken += res->local_found;
    st->landmarks += res->n_landmarks;
    st->counted++;
}

void rl_bench_stages_print(const rl_bench_stages *st, const char *what, double peer_us)
{
    double unit = st->units ? st->unit_ns / st->units / 1000.0 : 0.0, total = 0, runs = st->runs ? (double)st->runs : 1;
    int s;
    if (st->fastest_of > 0)
        printf("stages, %s: mean per frame of each frame's fastest of %d runs (%ld frames); one whole-frame "
               "histogram pass %.1f us\n", what, st->fastest_of, st->runs, unit);
    else
        printf("stages, %s: mean per frame over %ld runs; one whole-frame histogram pass %.1f us\n", what, st->runs,
               unit);
    printf("  %-22s %10s %10s\n", "stage", "us", "hist passes");
    for (s = 0; s < RL_STAGE_DONE; s++) {
        double us = st->ns[s] / runs / 1000.0;
        total += us;
        if (us > 0)
            printf("  %-22s %10.1f %10.2f\n", rl_stage_name((rl_stage)s), us, unit > 0 ? us / unit : 0.0);
    }
    printf("  %-22s %10.1f %10.2f\n", "total", total, unit > 0 ? total / unit : 0.0);
    if (peer_us > 0)
        printf("  %-22s %10.1f %10.2f   (AprilTag / ringloc: %.1fx)\n", "AprilTag 3", peer_us,
               unit > 0 ? peer_us / unit : 0.0, total > 0 ? peer_us / total : 0.0);
    if (st->counted > 0) {
        double c = (double)st->counted;
        printf("  candidates a frame: %.2f read (global pass, second labellings), %.2f local tries (%.2f taken), "
               "%.2f landmarks\n", st->reads / c, st->tried / c, st->taken / c, st->landmarks / c);
    }
}
