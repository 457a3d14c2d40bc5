/* ringloc site-check: what ringloc will do on a site's own ceiling, from
 * photos taken there with the robot's camera: the false landmarks it
 * reports on them as they are, and the recognition rates when landmarks
 * are placed into them the way printed sheets would look there. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "rl_annotate.h"
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_composite.h"
#include "rl_outfile.h"
#include "rl_png.h"
#include "rl_print.h"
#include "rl_report.h"
#include "rl_site.h"


static const char *help =
    "usage: ringloc site-check [--family ring5] [--map MAP.yaml]\n"
    "                          [--radius-px R | --camera CAM.yaml --diameter 0.21 --distance 1.87]\n"
    "                          [--sheet PAPER] [--rounds 3] [--seed 1] [--local auto|always|never]\n"
    "                          [--out DIR] [--json] PHOTO_DIR|PHOTO.png...\n\n"
    "Take photos of your own ceiling with the robot's camera (PNG, no landmarks up\n"
    "yet) and see what ringloc will do there:\n"
    "  1. the false landmarks it reports on the photos as they are (smoke detectors,\n"
    "     sprinklers, downlights...), per id;\n"
    "  2. the rates at which it identifies landmarks of your family and size placed\n"
    "     into the photos the way the sheets you print would look there (the sheet's\n"
    "     margins, paper about as bright as the ceiling around it, darker or\n"
    "     lighter, grey ink, perspective, glare next to lamps, lens blur, sensor\n"
    "     noise, all laid in light as a camera forms it): wholly inside the image,\n"
    "     within one radius of a light, and cut by the image border (up to half\n"
    "     outside), and per id; a kind with none placed has no rate (\"-\", null in\n"
    "     JSON): no lamp in the photos, or a sheet too large to lie within a\n"
    "     radius of one without covering it (A3, the default for 210 mm\n"
    "     landmarks: give --sheet letter to see the rate next to lamps);\n"
    "  3. which ids to leave out of the map because the site's own objects look\n"
    "     like them.\n\n"
    "  --family NAME     landmark family (default ring5; the map's with --map)\n"
    "  --map FILE        place and recognize only the map's ids\n"
    "  --radius-px R     landmark radius in the image (default: from the camera,\n"
    "                    diameter and distance; 25.7 px for the paper's set-up)\n"
    "  --camera FILE     calibration of the robot's camera (focal length)\n"
    "  --diameter M      printed outer diameter (default 0.21 m)\n"
    "  --distance M      camera to ceiling (default 1.87 m)\n"
    "  --sheet PAPER     the sheets the landmarks are printed on: letter, a4, a3,\n"
    "                    tabloid or WxH in mm (default: the paper 'ringloc gen'\n"
    "                    prints the diameter on; A3 for 0.21 m)\n"
    "  --rounds N        times each photo is used, with new places (default 3)\n"
    "  --seed S          placements and looks (default 1)\n"
    "  --local POLICY    local pass: auto, always or never (default: the firmware's)\n"
    "  --gamma G|auto    the camera's tone curve, grey = light^(1/G): 2.2 for\n"
    "                    sRGB-like cameras, 1 for one that outputs linear light; the\n"
    "                    marks are laid in light through it (2.2 for auto, the\n"
    "                    default) and recognized as detect --gamma says\n"
    "  --mix light|grey  how the sheets' blur mixes: light (default), as optics and\n"
    "                    motion do, or grey levels, after the curve, as a camera that\n"
    "                    scales, bins, compresses or sharpens after its curve does\n"
    "                    (ringloc reads both without a wrong id: docs/results.md)\n"
    "  --out DIR         write the composited frames with their truth (YAML) and an\n"
    "                    annotated image of every photo with a false landmark\n"
    "  --json            one JSON object instead of the table\n";

#define MAX_PHOTOS 20000

typedef struct {
    long placed[3], found[3], wrong[3];
    long false_as_is, false_composited, photos, frames;
    long false_by_id[256], wrong_by_id[256];
    long placed_by_id[256], found_by_id[256]; /* every kind of place */
    double us_total;
} tally;

/* The photos: every PNG of a folder (sorted), or the files given. */
static int list_photos(const char *C, int argc, char **argv, char ***out)
{
    char **list = malloc(sizeof(char *) * MAX_PHOTOS), err[512];
    int n = 0, i, j;
    if (list == NULL)
        return -1;
    for (i = 0; i < argc; i++) {
        struct stat st;
        char **in;
        int k;
        if (stat(argv[i], &st) != 0)
            snprintf(err, sizeof err, "%s: no such file or folder", argv[i]);
        else if (!S_ISDIR(st.st_mode) || rl_png_list(argv[i], &in, &k, err, sizeof err) == RL_OK)
            err[0] = '\0';
        if (err[0]) {
            rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
            rl_png_list_free(list, n);
            return -1;
        }
        if (!S_ISDIR(st.st_mode)) {
            if (n < MAX_PHOTOS)
                list[n++] = strdup(argv[i]);
            continue;
        }
        for (j = 0; j < k; j++) {
            if (n < MAX_PHOTOS)
                list[n++] = in[j];
            else
                free(in[j]);
        }
        free(in);
    }
    *out = list;
    return n;
}

static const char *stem(const char *path, char *buf, size_t len)
{
    const char *b = strrchr(path, '/'), *dot;
    b = b ? b + 1 : path;
    dot = strrchr(b, '.');
    snprintf(buf, len, "%.*s", dot ? (int)(dot - b) : (int)strlen(b), b);
    return buf;
}


/* A detection at the place of a false landmark the photo already had. */
static int seen_as_is(const rl_result *as_is, const rl_detection *d)
{
    int i;
    for (i = 0; i < as_is->n_landmarks; i++)
        if (hypot(d->u - as_is->landmarks[i].u, d->v - as_is->landmarks[i].v) < 0.5 * d->radius)
            return 1;
    return 0;
}

typedef struct {
    const char *C, *out;
    rl_heap_recog *hr;
    rl_composite_config cc;
    const int *ids;
    int n_ids, rounds;
    rl_family fam;
    int unwritten;  /* files under --out that could not be written (each named) */
} check;

/* A file under --out that failed: its line, and counted for the exit status. */
static void not_written(check *k, const char *err)
{
    rl_cli_fail(k->C, RL_EXIT_FAIL, "%s", err);
    k->unwritten++;
}

static void write_truth(check *k, const char *path, const char *image, const rl_site_mark *m, int n)
{
    static const char *kinds[] = {"complete", "near_light", "cut"};
    rl_outfile o;
    char err[1200];
    int i;
    if (rl_outfile_open(&o, path, err, sizeof err) != RL_OK) {
        not_written(k, err);
        return;
    }
    fprintf(o.f, "image: %s\nlandmarks:\n", image);
    for (i = 0; i < n; i++)
        fprintf(o.f, "  - {id: %d, u: %.3f, v: %.3f, radius: %.3f, kind: %s, visible: %.3f}\n",
                m[i].id, m[i].u, m[i].v, m[i].r, kinds[m[i].kind], m[i].visible);
    if (rl_outfile_commit(&o, err, sizeof err) != RL_OK)
        not_written(k, err);
}

/* The photo as it is: every landmark reported there is false. */
static void photo_as_is(check *k, const char *path, const rl_image *img, rl_result *as_is,
                        tally *t)
{
    double us;
    int i;
    char err[512], name[256], out[1200];
    if (rl_report_run(k->hr, img, as_is, &us) != RL_OK)
        return;
    t->us_total += us;
    t->frames++;
    t->false_as_is += as_is->n_landmarks;
    for (i = 0; i < as_is->n_landmarks; i++)
        t->false_by_id[as_is->landmarks[i].id & 255]++;
    if (k->out && as_is->n_landmarks > 0) {
        snprintf(out, sizeof out, "%s/false_%s.png", k->out, stem(path, name, sizeof name));
        if (rl_annotate_png(out, img, as_is, &k->fam, path, err, sizeof err) != RL_OK)
            not_written(k, err);
    }
}

/* One composited frame: marks placed, recognized, judged from their truth. */
static void photo_composited(check *k, const char *path, const rl_image *photo, int round,
                             const rl_result *as_is, uint8_t *buf, rl_result *res, tally *t)
{
    rl_site_mark marks[RL_COMPOSITE_MAX];
    rl_image img = rl_image_view(photo->width, photo->height, photo->width, buf);
    int y, n, i;
    double us;
    for (y = 0; y < photo->height; y++)
        memcpy(buf + (size_t)y * (size_t)photo->width,
               photo->data + (size_t)y * (size_t)photo->stride, (size_t)photo->width);
    n = rl_composite_plan(&img, &k->cc, k->ids, k->n_ids, marks);
    rl_composite_draw(&img, &k->cc, marks, n, rl_composite_ring, &k->fam);
    if (rl_report_run(k->hr, &img, res, &us) != RL_OK)
        return;
    t->us_total += us;
    t->frames++;
    for (i = 0; i < n; i++) {
        t->placed[marks[i].kind]++;
        t->placed_by_id[marks[i].id & 255]++;
    }
    for (i = 0; i < res->n_landmarks; i++) {
        const rl_detection *d = &res->landmarks[i];
        int m = rl_composite_mark_at(marks, n, d->u, d->v);
        if (m < 0) {
            t->false_composited += !seen_as_is(as_is, d);
        } else if (d->id == marks[m].id) {
            t->found[marks[m].kind]++;
            t->found_by_id[d->id & 255]++;
        } else {
            t->wrong[marks[m].kind]++;
            t->wrong_by_id[d->id & 255]++;
        }
    }
    if (k->out) {
        char name[256], png[1200], yaml[1200], err[512];
        stem(path, name, sizeof name);
        snprintf(png, sizeof png, "%s/%s_r%d.png", k->out, name, round);
        snprintf(yaml, sizeof yaml, "%s/%s_r%d.yaml", k->out, name, round);
        if (rl_png_write_gray(png, &img, err, sizeof err) != RL_OK)
            not_written(k, err);
        write_truth(k, yaml, png, marks, n);
    }
}

/* 0 if path is an existing folder. */
static int access_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode) ? 0 : -1;
}

static double pct(long a, long b)
{
    return b > 0 ? 100.0 * a / b : 0.0;
}

static double ms_per_frame(const tally *t)
{
    return t->frames ? t->us_total / t->frames / 1000.0 : 0.0;
}

/* An id to leave out of the map: the site's own objects pass for it, or
 * landmarks placed there were misread as it. */
static int leave_out(const tally *t, int id)
{
    return t->false_by_id[id] || t->wrong_by_id[id];
}

static void print_table(const tally *t, const check *k, FILE *f)
{
    static const char *rows[] = {"wholly inside", "within 1 R of a light", "cut by the border"};
    int i, any = 0;
    fprintf(f, "site-check: %ld photos, %d rounds, radius %.1f px, seed %llu, %.2f ms per frame\n",
            t->photos, k->rounds, k->cc.radius_px, (unsigned long long)k->cc.seed,
            ms_per_frame(t));
    fprintf(f, "%-24s %8s %10s %8s %6s\n", "landmarks placed", "placed", "identified", "rate", "wrong");
    for (i = 0; i < 3; i++) {
        char rate[16] = "-"; /* none placed: no rate (no lamp, or a sheet too large beside one) */
        if (t->placed[i] > 0)
            snprintf(rate, sizeof rate, "%.1f%%", pct(t->found[i], t->placed[i]));
        fprintf(f, "%-24s %8ld %10ld %8s %6ld\n", rows[i], t->placed[i], t->found[i], rate, t->wrong[i]);
    }
    fprintf(f, "identified per id (placed, all kinds):");
    for (i = 0; i < 256; i++)
        if (t->placed_by_id[i])
            fprintf(f, "%s %d %.0f%% (%ld)", i % 10 == 0 && i ? "\n " : "", i,
                    pct(t->found_by_id[i], t->placed_by_id[i]), t->placed_by_id[i]);
    fprintf(f, "\nfalse landmarks on the photos as they are: %ld", t->false_as_is);
    for (i = 0; i < 256; i++)
        if (t->false_by_id[i])
            fprintf(f, "%sid %d: %ld", any++ ? ", " : " (", i, t->false_by_id[i]);
    fprintf(f, "%s\nfalse landmarks elsewhere on the composited photos: %ld\n", any ? ")" : "",
            t->false_composited);
    fprintf(f, "ids to leave out of the map:");
    for (i = any = 0; i < 256; i++)
        if (leave_out(t, i))
            fprintf(f, " %d%s", i, (any++, t->false_by_id[i] ? " (site objects look like it)" : " (misread)"));
    fprintf(f, "%s\n", any ? "" : " none");
}

static void print_json(const tally *t, const check *k, FILE *f)
{
    static const char *keys[] = {"complete", "near_light", "cut"};
    int i, any = 0;
    fprintf(f, "{\"photos\": %ld, \"rounds\": %d, \"radius_px\": %.2f, \"seed\": %llu, \"ms_per_frame\": %.3f",
            t->photos, k->rounds, k->cc.radius_px, (unsigned long long)k->cc.seed,
            ms_per_frame(t));
    for (i = 0; i < 3; i++)
        if (t->placed[i] > 0)
            fprintf(f, ", \"%s\": {\"placed\": %ld, \"identified\": %ld, \"rate\": %.4f, \"wrong\": %ld}",
                    keys[i], t->placed[i], t->found[i], pct(t->found[i], t->placed[i]) / 100.0, t->wrong[i]);
        else
            fprintf(f, ", \"%s\": {\"placed\": 0, \"identified\": 0, \"rate\": null, \"wrong\": %ld}",
                    keys[i], t->wrong[i]);
    fprintf(f, ", \"per_id\": {");
    for (i = 0; i < 256; i++)
        if (t->placed_by_id[i])
            fprintf(f, "%s\"%d\": {\"placed\": %ld, \"identified\": %ld}", any++ ? ", " : "", i,
                    t->placed_by_id[i], t->found_by_id[i]);
    any = 0;
    fprintf(f, "}, \"false_as_is\": %ld, \"false_composited\": %ld, \"false_ids\": {", t->false_as_is,
            t->false_composited);
    for (i = 0; i < 256; i++)
        if (t->false_by_id[i])
            fprintf(f, "%s\"%d\": %ld", any++ ? ", " : "", i, t->false_by_id[i]);
    fprintf(f, "}, \"leave_out\": [");
    for (i = any = 0; i < 256; i++)
        if (leave_out(t, i))
            fprintf(f, "%s%d", any++ ? ", " : "", i);
    fprintf(f, "]}\n");
}

/* The progress line (on a terminal's one line) ended before anything
 * else is written to stderr. */
static void end_progress(int *open)
{
    if (*open)
        fputc('\n', stderr);
    *open = 0;
}

/* Photo p readable and large enough to hold a landmark (two diameters
 * each way) into *img; else one line naming it, and 0. */
static int read_photo(const check *k, const char *path, rl_image *img)
{
    char err[512];
    int side = (int)ceil(4 * k->cc.radius_px);
    if (rl_png_read_gray(path, img, err, sizeof err) != RL_OK)
        return !rl_cli_fail(k->C, RL_EXIT_FAIL, "%s (skipped)", err);
    if (img->width < side || img->height < side) {
        rl_cli_fail(k->C, RL_EXIT_FAIL, "%s: %dx%d is too small for landmarks of radius %.1f px (at least %dx%d; skipped)",
                    path, img->width, img->height, k->cc.radius_px, side, side);
        rl_png_free(img);
        return 0;
    }
    return 1;
}

static int run_check(check *k, char **photos, int n, int json)
{
    static rl_result as_is, res;
    tally *t = calloc(1, sizeof *t);
    uint8_t *buf = NULL;
    int p, round, skipped = 0, progress = 0;
    if (t == NULL)
        return rl_cli_fail(k->C, RL_EXIT_FAIL, "out of memory");
    for (p = 0; p < n; p++) {
        rl_image img;
        end_progress(&progress);
        if (!read_photo(k, photos[p], &img)) {
            skipped++;
            continue;
        }
        free(buf);
        if ((buf = malloc((size_t)img.width * (size_t)img.height)) == NULL) {
            rl_png_free(&img);
            break;
        }
        t->photos++;
        photo_as_is(k, photos[p], &img, &as_is, t);
        for (round = 0; round < k->rounds; round++)
            photo_composited(k, photos[p], &img, round, &as_is, buf, &res, t);
        rl_png_free(&img);
        if ((p + 1) % 20 == 0 && !json) {
            fprintf(stderr, "site-check: %d of %d photos", p + 1, n);
            progress = 1;
        }
    }
    end_progress(&progress);
    free(buf);
    if (t->photos == 0) {
        free(t);
        return rl_cli_fail(k->C, RL_EXIT_FAIL, "no readable PNG photo");
    }
    (json ? print_json : print_table)(t, k, stdout);
    free(t);
    if (skipped > 0) /* the figures hold for the photos read; the run did not read them all */
        return rl_cli_fail(k->C, RL_EXIT_FAIL, "%d of %d files skipped (named above)", skipped, n);
    if (k->unwritten > 0)
        return rl_cli_fail(k->C, RL_EXIT_FAIL, "%s: %d files not written (named above)", k->out, k->unwritten);
    return 0;
}

/* What the command line asks for. */
typedef struct {
    const char *family, *map, *camera; /* --family (default ring5), --map, --camera */
    double diameter, distance;         /* printed diameter, camera to ceiling (0.21, 1.87 m) */
    double radius_px;                  /* --radius-px (0: from the camera) */
    const char *sheet_name;            /* --sheet (NULL: the paper gen prints on) */
    const char *out;                   /* --out DIR */
    int rounds, seed, json;
    int mix_grey;                      /* --mix grey */
    rl_recog_config rc;                /* --local, --gamma (rl_recog_defaults) */
} sitecheck_opts;

static void sitecheck_opts_defaults(sitecheck_opts *o)
{
    memset(o, 0, sizeof *o);
    o->family = "ring5";
    o->diameter = 0.21;
    o->distance = 1.87;
    o->rounds = 3;
    o->seed = 1;
    rl_recog_defaults(&o->rc);
}

/* The command line into o: -1 to go on, or the exit code (0 after --help). */
static int sitecheck_args(const char *C, int argc, char **argv, sitecheck_opts *o)
{
    static const struct option opts[] = {
        {"family", required_argument, 0, 'f'}, {"map", required_argument, 0, 'm'},
        {"radius-px", required_argument, 0, 'r'}, {"camera", required_argument, 0, 'c'},
        {"diameter", required_argument, 0, 'D'}, {"distance", required_argument, 0, 'Z'},
        {"rounds", required_argument, 0, 'n'}, {"seed", required_argument, 0, 'S'},
        {"local", required_argument, 0, 'L'}, {"out", required_argument, 0, 'o'},
        {"json", no_argument, 0, 'j'}, {"sheet", required_argument, 0, 'P'},
        {"gamma", required_argument, 0, 'Y'}, {"mix", required_argument, 0, 'X'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    int c, ok;
    sitecheck_opts_defaults(o);
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        ok = 1;
        switch (c) {
        case 'f': o->family = optarg; break;
        case 'm': o->map = optarg; break;
        case 'c': o->camera = optarg; break;
        case 'o': o->out = optarg; break;
        case 'j': o->json = 1; break;
        case 'P': o->sheet_name = optarg; break;
        case 'X':
            if (strcmp(optarg, "light") != 0 && strcmp(optarg, "grey") != 0)
                ok = rl_cli_fail(C, RL_EXIT_USAGE, "--mix: '%s' is not light or grey", optarg) == 0;
            o->mix_grey = strcmp(optarg, "grey") == 0;
            break;
        case 'r': ok = rl_cli_double(C, "--radius-px", optarg, 4, 1000, &o->radius_px); break;
        case 'D': ok = rl_cli_double(C, "--diameter", optarg, 0.001, 5, &o->diameter); break;
        case 'Z': ok = rl_cli_double(C, "--distance", optarg, 0.05, 100, &o->distance); break;
        case 'n': ok = rl_cli_int(C, "--rounds", optarg, 1, 100, &o->rounds); break;
        case 'S': ok = rl_cli_int(C, "--seed", optarg, 0, 2147483647L, &o->seed); break;
        case 'Y':
        case 'L': ok = rl_cli_recog_option(C, c, optarg, &o->rc, &o->family) >= 0; break;
        case 'h': fputs(help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
        if (!ok)
            return RL_EXIT_USAGE;
    }
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "give a folder of photos or PNG files (see --help)");
    return -1;
}

/* The ids to place and recognize: the map's, or every id of the family;
 * the camera's focal length when the radius is not given. 0, or the exit
 * code. */
static int sitecheck_site(const char *C, sitecheck_opts *o, check *k, int *ids)
{
    static rl_site site;
    rl_site_files files;
    rl_calib cam;
    char err[768];
    int i;
    rl_site_files_init(&files);
    files.map = o->map;
    files.calibration = o->radius_px > 0 ? NULL : o->camera;
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (site.has_map) {
        k->fam = site.map.family;
        for (i = 0; i < site.map.count; i++)
            ids[i] = site.map.lm[i].id;
        k->n_ids = site.map.count;
        rl_recog_use_map(&o->rc, &site.map, ids);
    } else {
        if (rl_family_parse(o->family, &k->fam) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_USAGE, "--family: '%s' is not ring2 .. ring8", o->family);
        o->rc.family = k->fam;
        k->n_ids = rl_family_count(&k->fam);
        for (i = 0; i < k->n_ids; i++)
            ids[i] = i + 1;
    }
    k->ids = ids;
    /* the landmark radius in the image: given, or from the camera's focal
     * length, the printed diameter and the distance to the ceiling */
    if (o->radius_px > 0)
        return 0;
    if (site.has_calib)
        cam = site.calib;
    else
        rl_calib_defaults(&cam, 640, 480, 70.0 * M_PI / 180.0);
    o->radius_px = 0.5 * (cam.fx + cam.fy) * 0.5 * o->diameter / o->distance;
    return 0;
}

/* The sheets the landmarks are placed on: --sheet, or the paper gen
 * prints the diameter on. 0, or the exit code. */
static int sitecheck_sheet(const char *C, const sitecheck_opts *o, rl_paper *sheet)
{
    if (o->sheet_name && !rl_paper_parse(o->sheet_name, sheet))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--sheet: '%s' is not %s or WxH in mm", o->sheet_name,
                           rl_paper_names());
    if (!o->sheet_name && rl_paper_fitting(o->diameter, RL_PRINT_MARGIN_MM) == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--diameter %.3f m fits no paper: give --sheet", o->diameter);
    if (!o->sheet_name)
        *sheet = *rl_paper_fitting(o->diameter, RL_PRINT_MARGIN_MM);
    if (fmin(sheet->w_mm, sheet->h_mm) < 1000 * o->diameter)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--sheet: %.0fx%.0f mm is narrower than the landmark (%.0f mm)",
                           sheet->w_mm, sheet->h_mm, 1000 * o->diameter);
    return 0;
}

/* How landmarks are laid into the photos. */
static void sitecheck_composite(const sitecheck_opts *o, const rl_paper *sheet, rl_composite_config *cc)
{
    rl_composite_defaults(cc);
    cc->radius_px = o->radius_px;
    cc->gamma = o->rc.gamma > 0 ? o->rc.gamma : 2.2; /* the photos' camera: sRGB unless told */
    cc->mix_grey = o->mix_grey;
    cc->sheet_w = sheet->w_mm / 500.0 / o->diameter; /* in radii */
    cc->sheet_h = sheet->h_mm / 500.0 / o->diameter;
    cc->seed = (uint64_t)o->seed;
}

int rl_cmd_sitecheck(int argc, char **argv)
{
    const char *C = "site-check";
    static sitecheck_opts o;
    static int ids[RL_MAX_MAP_LANDMARKS]; /* a map's, repeats and all */
    int n, i, rc;
    char **photos;
    rl_paper sheet;
    rl_heap_recog hr;
    check k;
    memset(&k, 0, sizeof k);
    k.C = C;
    if ((rc = sitecheck_args(C, argc, argv, &o)) >= 0 || (rc = sitecheck_site(C, &o, &k, ids)) != 0)
        return rc;
    k.out = o.out;
    k.rounds = o.rounds;
    if (k.out && mkdir(k.out, 0777) != 0 && access_dir(k.out) != 0)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: cannot create the folder", k.out);
    if ((rc = sitecheck_sheet(C, &o, &sheet)) != 0)
        return rc;
    sitecheck_composite(&o, &sheet, &k.cc);
    if ((n = list_photos(C, argc - optind, argv + optind, &photos)) < 0)
        return RL_EXIT_FAIL;
    if (n == 0) {
        free(photos);
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: no PNG photos", argv[optind]);
    }
    rl_heap_recog_init(&hr, &o.rc);
    k.hr = &hr;
    rc = run_check(&k, photos, n, o.json);
    rl_heap_recog_free(&hr);
    for (i = 0; i < n; i++)
        free(photos[i]);
    free(photos);
    return rc;
}
