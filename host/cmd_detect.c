/* ringloc detect: recognize landmarks in PNG files, one JSON line each. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_annotate.h"
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_pngrun.h"
#include "rl_report.h"
#include "rl_site.h"

static const char *detect_help =
    "usage: ringloc detect [--family ring5] [--map MAP.yaml] [--annotate OUT.png]\n"
    "                      [--local auto|always|never] [--min-score 0.8] IMAGE...\n\n"
    "Recognize ring landmarks in each image (8/16-bit gray, RGB or palette PNG) and\n"
    "print one JSON object per image per line:\n"
    "  {\"image\": \"a.png\", \"width\": 640, \"height\": 480, \"elapsed_us\": 412.0,\n"
    "   \"landmarks\": [{\"id\": 25, \"code\": \"11001\", \"u\": 301.42, \"v\": 122.07,\n"
    "   \"radius\": 25.83, \"score\": 0.93, \"runner_up\": 0.71, \"pass\": \"global\",\n"
    "   \"complete\": true}],\n"
    "   \"unidentified\": 1, \"dropped\": {\"regions\": 0, \"lights\": 0,\n"
    "   \"candidates\": 0, \"landmarks\": 0}}\n"
    "radius: measured across both edges of the outer black band where the code\n"
    "leaves one clear (unbiased by blur). runner_up: how close the nearest other\n"
    "reading came (another id through the curve, or a zone twin read as if the\n"
    "camera had mixed grey levels after its curve, or light before it); an id\n"
    "two formations read differently is not reported (docs/design.md), nor one\n"
    "too small to tell its twins apart (code zone 1 under 1.2 px: ring5 under\n"
    "14.2 px radius); both count as unidentified. elapsed_us is the recognition\n"
    "time in-process, file I/O excluded; dropped\n"
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
    "                    curve (blur and motion mix light); an id is reported only\n"
    "                    if its zone twins do not read as well with grey levels\n"
    "                    mixed after the curve (scaling, JPEG, sharpening)\n";


typedef struct {
    const char *annotate;     /* --annotate, or NULL */
    int several;              /* more than one image: annotations named after each */
    const rl_family *family;
    long failures;
} detect_sink;

/* A frame's JSON line, and its annotated image when asked for. */
static rl_err detect_put(void *ctx, const rl_run_report *rep)
{
    detect_sink *d = (detect_sink *)ctx;
    const char *image = rep->frame->name;
    char name[1024], err[512];
    rl_report_json_open(stdout, image, rep->res, d->family, rep->recog_us);
    fputs("}\n", stdout);
    fflush(stdout);
    if (d->annotate == NULL)
        return RL_OK;
    rl_cli_annotate_name(name, sizeof name, d->annotate, image, d->several);
    if (rl_annotate_png(name, &rep->frame->img, rep->res, d->family, image, err, sizeof err) != RL_OK) {
        rl_cli_fail("detect", RL_EXIT_FAIL, "%s", err);
        d->failures++;
    }
    return RL_OK;
}

/* --family against the map's. 0 after an error line. */
static int family_agrees(const char *C, const char *family, const rl_recog_config *cfg, const rl_site *site)
{
    if (family && site->has_map && cfg->family.bits != site->map.family.bits)
        return !rl_cli_fail(C, RL_EXIT_USAGE, "--family %s disagrees with %s (ring%d)", family, site->files.map,
                            site->map.family.bits);
    return 1;
}

int rl_cmd_detect(int argc, char **argv)
{
    static const struct option opts[] = {
        {"family", required_argument, 0, 'f'}, {"map", required_argument, 0, 'm'},
        {"annotate", required_argument, 0, 'a'}, {"local", required_argument, 0, 'L'},
        {"min-score", required_argument, 0, 's'}, {"gamma", required_argument, 0, 'Y'},
        {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    const char *C = "detect", *family = NULL;
    static rl_site site;
    rl_site_files files;
    rl_recog_config cfg;
    rl_pngrun pr;
    detect_sink d;
    long failed;
    int c;
    char err[768];

    memset(&d, 0, sizeof d);
    rl_site_files_init(&files);
    rl_recog_defaults(&cfg);
    cfg.band_radius = 1; /* radii a survey can take its scale from */
    optind = 1;
    while ((c = rl_cli_getopt_recog(C, argc, argv, opts, &cfg, &family)) != -1) {
        switch (c) {
        case 'm': files.map = optarg; break;
        case 'a': d.annotate = optarg; break;
        case 'h': fputs(detect_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "no images given (see --help)");
    if (family && rl_family_parse(family, &cfg.family) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--family: '%s' is not a family (ring2 .. ring%d)",
                           family, RL_MAX_BITS);
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (!family_agrees(C, family, &cfg, &site))
        return RL_EXIT_USAGE;
    if (rl_site_prepare(&site, &cfg, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    d.several = argc - optind > 1;
    d.family = &site.recog.cfg.family;
    rl_pngrun_defaults(&pr, C);
    pr.put = detect_put;
    pr.ctx = &d;
    failed = rl_pngrun_files(&pr, &site, argv + optind, argc - optind);
    rl_site_free(&site);
    return failed + d.failures ? RL_EXIT_FAIL : 0;
}
