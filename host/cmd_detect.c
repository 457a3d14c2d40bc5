/* ringloc detect: recognize landmarks in PNG files, one JSON line each. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_annotate.h"
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_mapfile.h"
#include "rl_png.h"
#include "rl_report.h"

static const char *detect_help =
    "usage: ringloc detect [--family ring5] [--map MAP.yaml] [--annotate OUT.png]\n"
    "                      [--local auto|always|never] [--min-score 0.8] IMAGE...\n\n"
    "Recognize ring landmarks in each image (8/16-bit gray, RGB or palette PNG) and\n"
    "print one JSON object per image per line:\n"
    "  {\"image\": \"a.png\", \"width\": 640, \"height\": 480, \"elapsed_us\": 412.0,\n"
    "   \"landmarks\": [{\"id\": 25, \"code\": \"11001\", \"u\": 301.42, \"v\": 122.07,\n"
    "   \"radius\": 25.83, \"score\": 0.93, \"pass\": \"global\", \"complete\": true}],\n"
    "   \"unidentified\": 1, \"dropped\": {\"regions\": 0, \"lights\": 0,\n"
    "   \"candidates\": 0, \"landmarks\": 0}}\n"
    "radius: measured across both edges of the outer black band where the code\n"
    "leaves one clear (unbiased by blur). elapsed_us is the recognition time\n"
    "in-process, file I/O excluded; dropped\n"
    "counts what the compile-time limits left out (0 on ordinary frames). An\n"
    "unreadable image gives an error line on stderr and the run goes on.\n\n"
    "  --family NAME     landmark family (default ring5; the map's with --map)\n"
    "  --map FILE        report only ids in this map (YAML)\n"
    "  --annotate FILE   write the image with lights, candidates, centres and ids\n"
    "                    drawn (FILE-<image name>.png for several images)\n"
    "  --local POLICY    local pass: always (default), auto (the paper's: when fewer\n"
    "                    than 2 were identified) or never\n"
    "  --min-score R     Pearson correlation needed to accept an id (default 0.80)\n"
    "  --gamma G|auto    the camera's tone curve, grey = light^(1/G): 2.2 for\n"
    "                    sRGB-like cameras (V4L2, libcamera, webcams), 1 for one that\n"
    "                    outputs linear light (machine-vision cameras with gamma off);\n"
    "                    auto (default) learns which of the two the landmarks read\n"
    "                    best through (\"gamma\" in the JSON). Identification undoes the\n"
    "                    curve: blur and motion mix light, not grey levels\n";


int rl_cli_recog_option(const char *cmd, int c, const char *arg, rl_recog_config *cfg,
                        const char **family)
{
    switch (c) {
    case 'f': *family = arg; return 1;
    case 'L':
        if (strcmp(arg, "auto") == 0) cfg->local = RL_LOCAL_AUTO;
        else if (strcmp(arg, "always") == 0) cfg->local = RL_LOCAL_ALWAYS;
        else if (strcmp(arg, "never") == 0) cfg->local = RL_LOCAL_NEVER;
        else return rl_cli_fail(cmd, RL_EXIT_USAGE, "--local: '%s' is not auto, always or never", arg), -1;
        return 1;
    case 'Y': /* --gamma */
        if (strcmp(arg, "auto") == 0) {
            cfg->gamma = 0;
            return 1;
        }
        return rl_cli_double(cmd, "--gamma", arg, 1.0, 3.0, &cfg->gamma) ? 1 : -1;
    case 's':
        if (!rl_cli_double(cmd, "--min-score", arg, 0.01, 1.0, &cfg->min_score))
            return -1;
        if (!(cfg->min_score > 0 && cfg->min_score <= 1))
            return rl_cli_fail(cmd, RL_EXIT_USAGE, "--min-score: %s is outside (0, 1]", arg), -1;
        return 1;
    }
    return 0;
}


void rl_cli_annotate_name(char *buf, size_t len, const char *out, const char *image, int several)
{
    const char *base = strrchr(image, '/'), *dot, *odot = strrchr(out, '.');
    int stem;
    if (!several) {
        snprintf(buf, len, "%s", out);
        return;
    }
    base = base ? base + 1 : image;
    dot = strrchr(base, '.');
    stem = dot ? (int)(dot - base) : (int)strlen(base);
    if (odot && !strchr(odot, '/'))
        snprintf(buf, len, "%.*s-%.*s%s", (int)(odot - out), out, stem, base, odot);
    else
        snprintf(buf, len, "%s-%.*s.png", out, stem, base);
}

int rl_cmd_detect(int argc, char **argv)
{
    static const struct option opts[] = {
        {"family", required_argument, 0, 'f'}, {"map", required_argument, 0, 'm'},
        {"annotate", required_argument, 0, 'a'}, {"local", required_argument, 0, 'L'},
        {"min-score", required_argument, 0, 's'}, {"gamma", required_argument, 0, 'Y'},
        {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    const char *C = "detect", *family = NULL, *map_path = NULL, *annotate = NULL;
    rl_recog_config cfg;
    rl_heap_recog hr;
    static rl_result res;
    static rl_map map;
    int c, i, failures = 0, ids[RL_MAX_IDS];
    char err[512], name[1024];

    rl_recog_defaults(&cfg);
    cfg.band_radius = 1; /* radii a survey can take its scale from */
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        int r = rl_cli_recog_option(C, c, optarg, &cfg, &family);
        if (r < 0)
            return RL_EXIT_USAGE;
        if (r > 0)
            continue;
        switch (c) {
        case 'm': map_path = optarg; break;
        case 'a': annotate = optarg; break;
        case 'h': fputs(detect_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "no images given (see --help)");
    if (family && rl_family_parse(family, &cfg.family) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--family: '%s' is not a family (ring2 .. ring%d)",
                           family, RL_MAX_BITS);
    if (map_path) {
        if (rl_mapfile_load(map_path, &map, err, sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
        if (family && cfg.family.bits != map.family.bits)
            return rl_cli_fail(C, RL_EXIT_USAGE, "--family %s disagrees with %s (ring%d)", family,
                               map_path, map.family.bits);
        if (map.count == 0)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s: the map has no landmarks", map_path);
        rl_recog_use_map(&cfg, &map, ids);
    }
    rl_heap_recog_init(&hr, &cfg);
    for (i = optind; i < argc; i++) {
        rl_image img;
        double us = 0;
        rl_err e;
        if (rl_png_read_gray(argv[i], &img, err, sizeof err) != RL_OK) {
            rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
            failures++;
            continue;
        }
        e = rl_report_run(&hr, &img, &res, &us);
        if (e != RL_OK) {
            rl_cli_fail(C, RL_EXIT_FAIL, "%s: recognition failed: %s", argv[i], rl_strerror(e));
            failures++;
            rl_png_free(&img);
            continue;
        }
        rl_report_json_open(stdout, argv[i], &res, &cfg.family, us);
        fputs("}\n", stdout);
        fflush(stdout);
        if (annotate) {
            rl_cli_annotate_name(name, sizeof name, annotate, argv[i], argc - optind > 1);
            if (rl_annotate_png(name, &img, &res, &cfg.family, argv[i], err, sizeof err) != RL_OK) {
                rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
                failures++;
            }
        }
        rl_png_free(&img);
    }
    rl_heap_recog_free(&hr);
    return failures ? RL_EXIT_FAIL : 0;
}
