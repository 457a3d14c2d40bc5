/* ringloc-soak: the firmware's loop for a long run, with the serial line
 * going away and coming back, measured.
 *
 *   ringloc-soak [--frames 200000] [--reopen-every 3] SITE_DIR
 *
 * SITE_DIR holds what `ringloc-render --path ... --write-map --write-camera
 * --write-robot` writes (map.yaml, camera.yaml, robot.yaml, *.png). The
 * loop (rl_run, as `ringloc-fw` runs it) reads the frames from the PNG
 * camera, looping, as fast as it can; its serial line is a double that
 * vanishes every --reopen-every seconds (writes fail with "no device", and
 * opening fails for 0.3 s) and then comes back. It prints frames per
 * second, heap calls after start-up (malloc and friends are counted through
 * the linker's --wrap), RSS at the 10,000th and the last frame, the frames
 * delivered after each reopening, and every kind of log line seen; it
 * exits 1 when a heap call happened after start-up, RSS grew by 1% or more,
 * or a reopening delivered no frame. */
#define _GNU_SOURCE
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "rl_cli.h"
#include "rl_clock.h"
#include "rl_packet_sink.h"
#include "rl_run.h"
#include "rl_site.h"

/* ---- heap calls, counted once the loop has started ---- */
static volatile int counting;
static volatile long heap_calls;
void *__real_malloc(size_t n);
void *__real_calloc(size_t a, size_t b);
void *__real_realloc(void *p, size_t n);
void __real_free(void *p);
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t a, size_t b);
void *__wrap_realloc(void *p, size_t n);
void __wrap_free(void *p);
void *__wrap_malloc(size_t n) { heap_calls += counting; return __real_malloc(n); }
void *__wrap_calloc(size_t a, size_t b) { heap_calls += counting; return __real_calloc(a, b); }
void *__wrap_realloc(void *p, size_t n) { heap_calls += counting; return __real_realloc(p, n); }
void __wrap_free(void *p) { heap_calls += counting && p != NULL; __real_free(p); }

/* ---- the serial line that goes away ---- */
#define MAX_REOPENS 4096
typedef struct {
    uint64_t period_us, gone_until, next_gone;
    int up;
    long reopens, delivered[MAX_REOPENS], bytes;
} line_double;

static rl_err line_open(void *ctx, char *err, size_t errlen)
{
    line_double *l = (line_double *)ctx;
    uint64_t now = rl_clock_now_us();
    if (now < l->gone_until) {
        snprintf(err, errlen, "/dev/ttySOAK: no such device");
        return RL_ENOTFOUND;
    }
    l->up = 1;
    if (l->reopens < MAX_REOPENS)
        l->delivered[l->reopens] = 0;
    l->reopens++;
    l->next_gone = now + l->period_us;
    return RL_OK;
}

static rl_err line_write(void *ctx, const uint8_t *p, size_t n)
{
    line_double *l = (line_double *)ctx;
    uint64_t now = rl_clock_now_us();
    (void)p;
    if (!l->up)
        return RL_ENODEV;
    if (now >= l->next_gone) { /* unplugged: gone for 0.3 s */
        l->up = 0;
        l->gone_until = now + 300000;
        return RL_ENODEV;
    }
    l->bytes += (long)n;
    if (l->reopens <= MAX_REOPENS)
        l->delivered[l->reopens - 1]++;
    return RL_OK;
}

static void line_close(void *ctx)
{
    ((line_double *)ctx)->up = 0;
}

/* ---- log line kinds ---- */
#define MAX_KINDS 32
static char kinds[MAX_KINDS][64];
static long kind_count[MAX_KINDS];
static int n_kinds;

static void log_kind(void *ctx, const char *line)
{
    char k[64];
    int i;
    size_t len = strcspn(line, ";(0123456789");
    (void)ctx;
    snprintf(k, sizeof k, "%.*s", (int)(len < 60 ? len : 60), line);
    for (i = 0; i < n_kinds; i++)
        if (strcmp(kinds[i], k) == 0) {
            kind_count[i]++;
            return;
        }
    if (n_kinds < MAX_KINDS) {
        snprintf(kinds[n_kinds], sizeof kinds[0], "%s", k);
        kind_count[n_kinds++] = 1;
    }
}

static long rss_kb(void)
{
    long pages = 0, rss = 0;
    FILE *f = fopen("/proc/self/statm", "r");
    if (f) {
        if (fscanf(f, "%ld %ld", &pages, &rss) != 2)
            rss = 0;
        fclose(f);
    }
    return rss * (sysconf(_SC_PAGESIZE) / 1024);
}

/* The command line: 0 to go on, or the exit code (its line printed). */
static int soak_args(int argc, char **argv, long *frames, double *every, const char **dir)
{
    static const struct option opts[] = {{"frames", required_argument, 0, 'n'},
                                         {"reopen-every", required_argument, 0, 'r'},
                                         {"help", no_argument, 0, 'h'},
                                         {0, 0, 0, 0}};
    int c;
    while ((c = getopt_long(argc, argv, "h", opts, NULL)) != -1) {
        switch (c) {
        case 'n':
            if (!rl_cli_long(NULL, "--frames", optarg, 20000, 2000000000L, frames))
                return 2;
            break;
        case 'r':
            if (!rl_cli_double(NULL, "--reopen-every", optarg, 0.5, 3600, every))
                return 2;
            break;
        case 'h': fputs("usage: ringloc-soak [--frames 200000] [--reopen-every 3] SITE_DIR\n", stdout); return 0;
        default: return 2;
        }
    }
    if (optind != argc - 1) {
        fprintf(stderr, "ringloc-soak: give SITE_DIR (--frames >= 20000, --reopen-every 0.5 .. 3600 s)\n");
        return 2;
    }
    *dir = argv[optind];
    return -1;
}

/* SITE_DIR's map, camera and robot, and the recognizer for them. */
static int soak_site(const char *dir, rl_site *site)
{
    static rl_site_folder held;
    char err[768];
    rl_site_files files;
    rl_recog_config cfg;
    rl_site_files_folder(&files, &held, dir);
    rl_recog_defaults(&cfg);
    if (rl_site_load(site, &files, err, sizeof err) != RL_OK || rl_site_prepare(site, &cfg, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    return 0;
}

/* The loop's seams: the PNG camera on dir's frames, looping, as fast as
 * it can; the serial line that goes away (its packets through
 * rl_packet_sink); log lines counted by kind. */
static void soak_io(const char *dir, double every, line_double *line, rl_run_io *io)
{
    static char list[4096];
    static rl_cam_config cc;
    static rl_run_camera cam;
    static rl_packet_sink packets;
    static rl_packet_line pl;
    snprintf(list, sizeof list, "%s", dir);
    rl_cam_defaults(&cc);
    cc.backend = "png";
    cc.device = list;
    cc.loop = 1;
    cc.rate = 0;
    memset(io, 0, sizeof *io);
    io->source = rl_run_camera_source(&cam, &cc);
    io->clock = rl_clock_system();
    io->log = log_kind;
    line->period_us = (uint64_t)(every * 1e6);
    memset(&pl, 0, sizeof pl);
    pl.open = line_open;
    pl.write = line_write;
    pl.close = line_close;
    pl.ctx = line;
    io->sink = rl_packet_sink_make(&packets, &pl);
}

/* What the run measured. */
typedef struct {
    double t0, t1;            /* clock at the start and end, us */
    long rss_start, rss_end;  /* kB at frame 10,000 and at the last */
} soak_figures;

/* Run the loop for `frames` frames, counting heap calls after start-up.
 * 0, or 1 when the camera ended. */
static int soak_run(rl_runner *runner, long frames, const char *dir, soak_figures *f)
{
    const rl_run_counts *n = rl_run_counts_of(runner);
    long i;
    f->rss_start = 0;
    f->t0 = (double)rl_clock_now_us();
    for (i = 0; n->frames < frames; i++) {
        if (rl_run_step(runner) == RL_ENOTFOUND)
            return rl_cli_fail(NULL, 1, "%s: the camera ended", dir);
        if (n->frames == 100)
            counting = 1; /* start-up is over: the camera is open, the line up */
        if (n->frames == 10000 && f->rss_start == 0)
            f->rss_start = rss_kb();
        if (n->frames % 20000 == 0 && n->frames > 0 && i > 0)
            fprintf(stderr, "ringloc-soak: %ld of %ld frames\r", n->frames, frames);
    }
    counting = 0;
    f->t1 = (double)rl_clock_now_us();
    f->rss_end = rss_kb();
    return 0;
}

/* The figures, and the verdict: 1 when a heap call happened after
 * start-up, RSS grew by 1% or more, or a reopening delivered no frame. */
static int soak_report(const rl_runner *runner, const line_double *line, const soak_figures *f)
{
    const rl_run_counts *n = rl_run_counts_of(runner);
    long i, empty = 0;
    int bad = 0;
    double secs = (f->t1 - f->t0) / 1e6;
    printf("frames               %ld in %.1f s, %.0f per second (poses %ld, status %ld)\n", n->frames, secs,
           n->frames / secs, n->poses, n->statuses);
    printf("heap calls           %ld after start-up (%.4f per frame)\n", heap_calls,
           (double)heap_calls / (double)n->frames);
    printf("RSS                  %ld kB at frame 10,000, %ld kB at the last (%+.2f%%)\n", f->rss_start,
           f->rss_end, 100.0 * (double)(f->rss_end - f->rss_start) / (double)f->rss_start);
    printf("serial reopenings    %ld; frames delivered after each:", line->reopens);
    for (i = 0; i < line->reopens && i < MAX_REOPENS; i++) {
        if (i < 12 || i == line->reopens - 1)
            printf(" %ld", line->delivered[i]);
        else if (i == 12)
            printf(" ...");
        /* the last one may be cut short by the end of the run */
        empty += line->delivered[i] == 0 && i < line->reopens - 1;
    }
    printf("\nlog line kinds      ");
    for (i = 0; i < n_kinds; i++)
        printf(" \"%s\" x%ld%s", kinds[i], kind_count[i], i + 1 < n_kinds ? "," : "");
    printf("\n");
    if (heap_calls > 0) { printf("FAIL: heap calls after start-up\n"); bad = 1; }
    if (f->rss_start <= 0 || f->rss_end > f->rss_start * 1.01) { printf("FAIL: RSS grew by 1%% or more\n"); bad = 1; }
    if (line->reopens < 2 || empty > 0) { printf("FAIL: %ld reopenings delivered no frame\n", empty); bad = 1; }
    return bad;
}

int main(int argc, char **argv)
{
    static rl_site site;
    static rl_result res;
    static rl_runner runner;
    static line_double line;
    rl_run_config rc;
    rl_run_io io;
    soak_figures fig = {0, 0, 0, 0};
    long frames = 200000;
    double every = 3.0;
    const char *dir = NULL;
    int r;
    rl_cli_start("ringloc-soak");
    if ((r = soak_args(argc, argv, &frames, &every, &dir)) >= 0 || (r = soak_site(dir, &site)) != 0)
        return r;
    soak_io(dir, every, &line, &io);
    rl_run_defaults(&rc);
    rc.log_interval_us = 0; /* every line, for its kind */
    rl_run_init(&runner, &rc, &io, &site, &res);
    if ((r = soak_run(&runner, frames, dir, &fig)) != 0)
        return r;
    rl_run_close(&runner);
    fprintf(stderr, "\n");
    r = soak_report(&runner, &line, &fig);
    rl_site_free(&site);
    return r;
}
