/* ringloc plan: lay out a site. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rl_calibfile.h"
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_mapfile.h"
#include "rl_plan.h"
#include "rl_plan_area.h"
#include "rl_print.h"

static const char *plan_help =
    "usage: ringloc plan --landmarks N (--camera CAM.yaml | --resolution WxH --hfov DEG)\n"
    "                    (--distance M | --ceiling-height H --camera-height Z)\n"
    "                    [--min-ring-px 2] [--paper a4]\n"
    "                    [--grid COLSxROWS --pitch P [--map-out map.yaml] [--pdf FILE]]\n"
    "       ringloc plan --area WxH --pitch P (camera options) --ceiling-height H --camera-height Z\n"
    "                    [--family ring5] [--hamming 2] [--min-view 3] [--seed S]\n"
    "                    [--map-out map.yaml] [--pdf FILE]\n\n"
    "The paper's design method as a calculator: recommends the family, the printed\n"
    "diameter and a grid pitch that keeps two whole landmarks in view anywhere,\n"
    "and prints the expected pixel size of every ring. With --grid it writes a map\n"
    "YAML (ids 1, 2, ... row by row from x = 0, y = 0) and the matching PDF.\n\n"
    "  --landmarks N        landmarks the site needs (default: the grid's count)\n"
    "  --camera FILE        calibration (ROS camera_info or OpenCV YAML)\n"
    "  --resolution WxH     image size without a calibration (default 640x480)\n"
    "  --hfov DEG           horizontal field of view without a calibration\n"
    "  --distance M         camera to ceiling, metres\n"
    "  --ceiling-height H   ceiling above the floor (needed for a map), metres\n"
    "  --camera-height Z    camera above the floor, metres\n"
    "  --min-ring-px P      narrowest code ring wanted in the image (default 2)\n"
    "  --paper NAME         largest printable size: a4, letter, a3, tabloid (default a4)\n"
    "  --diameter M         use this diameter instead of the recommended one\n"
    "  --grid CxR --pitch P lay out C columns and R rows P metres apart\n"
    "  --map-out FILE       map YAML to write with --grid (default map.yaml)\n"
    "  --pdf FILE           the map's landmarks, a page each, with --grid or --area\n\n"
    "With --area it lays a grid of --pitch over a W x H metre site and gives it ids\n"
    "from one small family, repeated, so that every view the camera can have with\n"
    "at least --min-view whole landmarks shows a constellation (ids and where they\n"
    "are) found nowhere else on the site, even with one id misread: one frame tells\n"
    "the place (rl_place). Writes the map YAML (and the PDF) and prints its figures\n"
    "as one JSON line (k_achieved: the smallest K it reached).\n"
    "  --area WxH           the site's size, metres (e.g. 60x40)\n"
    "  --family ringN       the family to reuse (default ring5)\n"
    "  --hamming 2          only ids two code zones apart (ring5: 15 even-parity ids):\n"
    "                       a single misread zone never gives another valid id\n"
    "  --min-view K         views of K or more whole landmarks are unique (default 3)\n"
    "  --seed S             random ids (default 1)\n";

/* --area: the site's ids (cmd_plan_area.c) with this plan's view and diameter. */
static int plan_area(const char *C, const rl_plan_input *in, const rl_plan_result *out, rl_err e,
                     rl_plan_area *a, int hamming, double pitch, double diameter, double ceiling,
                     const rl_paper *paper, const char *map_out, const char *pdf)
{
    if (out->bits != a->family.bits)
        return rl_cli_fail(C, RL_EXIT_FAIL, "internal error: the plan chose ring%d", out->bits);
    if (e == RL_ERANGE && !(diameter > 0))
        return rl_cli_fail(C, RL_EXIT_FAIL, "ring%d needs %.3f m landmarks, more than %s paper holds (%.3f m)",
                           out->bits, out->diameter, paper->name, in->max_diameter);
    if (!(pitch > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--area needs --pitch P (the paper's tiles: 0.61)");
    if (!(ceiling > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--area needs --ceiling-height (it goes into the map)");
    a->pitch = pitch;
    a->view_w = out->view_w;
    a->view_h = out->view_h;
    a->diameter = diameter > 0 ? diameter : out->diameter;
    a->ceiling = ceiling;
    a->even_parity = hamming == 2;
    a->min_view = a->min_view ? a->min_view : 3;
    a->seed = a->seed ? a->seed : 1;
    a->map_out = map_out ? map_out : "map.yaml";
    a->pdf = pdf;
    a->paper = paper;
    return rl_plan_area_run(C, a);
}

int rl_cmd_plan(int argc, char **argv)
{
    static const struct option opts[] = {
        {"landmarks", required_argument, 0, 'n'},  {"camera", required_argument, 0, 'c'},
        {"resolution", required_argument, 0, 'r'}, {"hfov", required_argument, 0, 'f'},
        {"distance", required_argument, 0, 'd'},   {"ceiling-height", required_argument, 0, 'H'},
        {"camera-height", required_argument, 0, 'Z'}, {"min-ring-px", required_argument, 0, 'm'},
        {"paper", required_argument, 0, 'p'},      {"grid", required_argument, 0, 'g'},
        {"pitch", required_argument, 0, 'P'},      {"map-out", required_argument, 0, 'o'},
        {"pdf", required_argument, 0, 'F'},        {"diameter", required_argument, 0, 'D'},
        {"area", required_argument, 0, 'A'},       {"family", required_argument, 0, 'y'},
        {"hamming", required_argument, 0, 'M'},    {"min-view", required_argument, 0, 'K'},
        {"seed", required_argument, 0, 'S'},
        {"help", no_argument, 0, 'h'},             {0, 0, 0, 0}};
    rl_plan_area area = {0};
    const char *family = NULL;
    int hamming = 1;
    const char *C = "plan", *cam_path = NULL, *paper_name = "a4", *map_out = NULL, *pdf = NULL;
    double hfov = -1, ceiling = -1, cam_z = -1, pitch = -1, diameter = -1;
    int cols = 0, rows = 0, c, k, i, j;
    rl_plan_input in;
    rl_plan_result out;
    const rl_paper *paper;
    rl_err e;
    char err[512];
    static rl_map map;

    rl_plan_defaults(&in);
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        switch (c) {
        case 'n': if (!rl_cli_int(C, "--landmarks", optarg, 1, 1000000, &in.landmarks)) return RL_EXIT_USAGE; break;
        case 'c': cam_path = optarg; break;
        case 'r': if (!rl_cli_size(C, "--resolution", optarg, RL_MAX_IMAGE_DIM, &in.width, &in.height)) return RL_EXIT_USAGE; break;
        case 'f': if (!rl_cli_double(C, "--hfov", optarg, 1, 179, &hfov)) return RL_EXIT_USAGE; break;
        case 'd': if (!rl_cli_double(C, "--distance", optarg, 0.05, 100, &in.distance)) return RL_EXIT_USAGE; break;
        case 'H': if (!rl_cli_double(C, "--ceiling-height", optarg, 0.05, 100, &ceiling)) return RL_EXIT_USAGE; break;
        case 'Z': if (!rl_cli_double(C, "--camera-height", optarg, 0, 100, &cam_z)) return RL_EXIT_USAGE; break;
        case 'm': if (!rl_cli_double(C, "--min-ring-px", optarg, 0.5, 100, &in.min_ring_px)) return RL_EXIT_USAGE; break;
        case 'p': paper_name = optarg; break;
        case 'g': if (!rl_cli_size(C, "--grid", optarg, 10000, &cols, &rows)) return RL_EXIT_USAGE; break;
        case 'P': if (!rl_cli_double(C, "--pitch", optarg, 0.01, 100, &pitch)) return RL_EXIT_USAGE; break;
        case 'o': map_out = optarg; break;
        case 'F': pdf = optarg; break;
        case 'D': if (!rl_cli_double(C, "--diameter", optarg, 0.001, 5, &diameter)) return RL_EXIT_USAGE; break;
        case 'A': {
            int used = -1;
            if (sscanf(optarg, "%lfx%lf%n", &area.width, &area.height, &used) != 2 || optarg[used] != '\0' ||
                !(area.width > 0) ||
                !(area.height > 0) || area.width > 10000 || area.height > 10000)
                return rl_cli_fail(C, RL_EXIT_USAGE, "--area: '%s' is not a size in metres like 60x40", optarg);
            break;
        }
        case 'y': family = optarg; break;
        case 'M': if (!rl_cli_int(C, "--hamming", optarg, 1, 2, &hamming)) return RL_EXIT_USAGE; break;
        case 'K': if (!rl_cli_int(C, "--min-view", optarg, 3, 100, &area.min_view)) return RL_EXIT_USAGE; break;
        case 'S': {
            int sd;
            if (!rl_cli_int(C, "--seed", optarg, 0, 1000000000, &sd))
                return RL_EXIT_USAGE;
            area.seed = (unsigned long)sd;
            break;
        }
        case 'h': fputs(plan_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (optind < argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "unexpected argument '%s'", argv[optind]);
    paper = rl_paper_find(paper_name);
    if (paper == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--paper: unknown paper '%s' (%s)", paper_name,
                           rl_paper_names());
    in.max_diameter = rl_print_max_diameter(paper, RL_PRINT_MARGIN_MM);
    if (cam_path != NULL) {
        rl_calib cam;
        if (rl_calibfile_load(cam_path, &cam, err, sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
        in.width = cam.width;
        in.height = cam.height;
        in.fx = cam.fx;
    } else {
        if (!(hfov > 0 && hfov < 179))
            return rl_cli_fail(C, RL_EXIT_USAGE, "give --camera FILE, or --hfov DEG (0 .. 179) "
                                                 "with --resolution WxH");
        in.fx = (in.width / 2.0) / tan(hfov * M_PI / 360.0);
    }
    if (ceiling > 0 && cam_z >= 0 && in.distance <= 0)
        in.distance = ceiling - cam_z;
    if (!(in.distance > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "give --distance M, or --ceiling-height above "
                                             "--camera-height (the camera must be below the ceiling)");
    if (area.width > 0) {
        if (cols > 0)
            return rl_cli_fail(C, RL_EXIT_USAGE, "give --area or --grid, not both");
        if (rl_family_parse(family ? family : "ring5", &area.family) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_USAGE, "--family: '%s' is not ring2 .. ring%d", family, RL_MAX_BITS);
        in.landmarks = rl_family_count(&area.family); /* the plan's diameter for this family */
    } else if (family != NULL || hamming != 1 || area.min_view || area.seed) {
        return rl_cli_fail(C, RL_EXIT_USAGE, "--family, --hamming, --min-view and --seed go with --area");
    }
    if (cols > 0 && in.landmarks == 0)
        in.landmarks = (long)cols * rows > 1000000 ? 1000001 : cols * rows;
    if (in.landmarks <= 0)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--landmarks: how many landmarks does the site need?");
    if (!(in.min_ring_px > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--min-ring-px must be positive");

    e = rl_plan_compute(&in, &out);
    if (e == RL_ERANGE && out.bits == 0)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%d landmarks need more than the %d ids of ring%d; "
                                            "reuse ids in separate areas", in.landmarks,
                           (1 << RL_MAX_BITS) - 2, RL_MAX_BITS);
    if (e == RL_EINVAL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "inputs must be positive");
    if (area.width > 0)
        return plan_area(C, &in, &out, e, &area, hamming, pitch, diameter, ceiling, paper, map_out, pdf);
    printf("ringloc plan: %d landmarks, %dx%d camera, fx %.1f px, %.3f m to the ceiling\n",
           in.landmarks, in.width, in.height, in.fx, in.distance);
    printf("  ceiling in view    %.3f x %.3f m (%.1f px per metre)\n", out.view_w, out.view_h,
           out.px_per_m);
    printf("  family             ring%d (%d ids, %d code rings)\n", out.bits, (1 << out.bits) - 2,
           out.bits);
    printf("  printed diameter   %.3f m (at least %.4f m for %.1f px code rings)\n", out.diameter,
           out.diameter_min, in.min_ring_px);
    if (e == RL_ERANGE)
        return rl_cli_fail(C, RL_EXIT_FAIL,
                           "%.3f m does not fit %s paper (at most %.3f m): use a larger --paper, a "
                           "smaller --min-ring-px, or a camera closer to the ceiling",
                           out.diameter, paper->name, in.max_diameter);
    printf("  in the image       %.1f px across; ring widths (px): outer %.2f", 2 * out.radius_px,
           out.ring_px[0]);
    for (k = 1; k <= out.bits; k++)
        printf(k == out.bits ? " | centre disk %d radius %.2f" : " | code %d %.2f", k, out.ring_px[k]);
    printf("\n");
    if (out.pitch_max <= 0) {
        printf("  grid pitch         none: two whole landmarks never fit in view at this size\n");
    } else {
        printf("  grid pitch         at most %.3f m keeps two whole landmarks in view at any "
               "position and heading;\n                     recommended %.3f m\n",
               out.pitch_max, out.pitch);
    }
    if (cols <= 0)
        return 0;

    /* --grid: write a map and its PDF */
    if (pitch <= 0)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--grid needs --pitch P (recommended %.3f)", out.pitch);
    if (!(ceiling > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--grid needs --ceiling-height (it goes into the map)");
    if ((long)cols * rows > (1 << out.bits) - 2 || (long)cols * rows > RL_MAX_MAP_LANDMARKS)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--grid %dx%d needs %d ids; ring%d has %d", cols,
                           rows, cols * rows, out.bits, (1 << out.bits) - 2);
    if (pitch > out.pitch_max && out.pitch_max > 0)
        fprintf(stderr, "ringloc plan: note: pitch %.3f m is above %.3f m: some places will see "
                        "fewer than two landmarks\n", pitch, out.pitch_max);
    if (diameter > 0 && diameter > in.max_diameter)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--diameter %.3f m does not fit %s paper", diameter,
                           paper->name);
    if (rl_family_init(&map.family, out.bits) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "internal error: family");
    map.diameter = diameter > 0 ? diameter : out.diameter;
    map.ceiling_height = ceiling;
    map.count = 0;
    for (j = 0; j < rows; j++)
        for (i = 0; i < cols; i++) {
            rl_map_landmark *lm = &map.lm[map.count];
            lm->id = map.count + 1;
            lm->x = i * pitch;
            lm->y = j * pitch;
            map.count++;
        }
    if (map_out == NULL)
        map_out = "map.yaml";
    if (rl_mapfile_save(map_out, &map, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    printf("  map                %s: %dx%d landmarks %.3f m apart\n", map_out, cols, rows, pitch);
    if (pdf != NULL) {
        static int ids[RL_MAX_MAP_LANDMARKS];
        for (i = 0; i < map.count; i++)
            ids[i] = map.lm[i].id;
        if (rl_print_pdf(pdf, paper, &map.family, ids, map.lm, map.count, map.diameter, err,
                         sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
        printf("  pdf                %s: %d pages\n", pdf, map.count);
    }
    return 0;
}
