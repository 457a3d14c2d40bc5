/* ringloc plan: lay out a site. The calculator (the family, diameter and
 * pitch a site needs), and its two layouts: --grid, a map of ids 1, 2, ...
 * row by row; --area, a large site's ids from one small family, repeated
 * so that every view is unique (rl_site_plan). */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_mapfile.h"
#include "rl_outfile.h"
#include "rl_plan.h"
#include "rl_print.h"
#include "rl_site.h"
#include "rl_site_plan.h"

static const char *plan_help =
    "usage: ringloc plan --landmarks N (--camera CAM.yaml | --resolution WxH --hfov DEG)\n"
    "                    (--distance M | --ceiling-height H --camera-height Z)\n"
    "                    [--min-ring-px 2] [--paper a4]\n"
    "                    [--grid COLSxROWS --pitch P [--map-out map.yaml] [--pdf FILE]]\n"
    "                    [--force]\n"
    "       ringloc plan --area WxH --pitch P (camera options) --ceiling-height H --camera-height Z\n"
    "                    [--family ring5] [--hamming 2] [--min-view 3] [--seed S]\n"
    "                    [--map-out map.yaml] [--pdf FILE] [--force]\n\n"
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
    "  --map-out FILE       map YAML to write with --grid or --area (default map.yaml,\n"
    "                       which is not replaced when there already: name it, or\n"
    "                       give --force)\n"
    "  --force              replace an existing map.yaml without --map-out\n"
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

/* What the command line asks for. */
typedef struct {
    rl_plan_input in;             /* the calculator's inputs (rl_plan_defaults) */
    const char *camera;           /* --camera, or NULL: --resolution and --hfov */
    const char *paper_name;       /* --paper (default a4) */
    double hfov, ceiling, cam_z;  /* -1: not given */
    double pitch, diameter;       /* -1: not given (diameter: the plan's) */
    int cols, rows;               /* --grid (0: none) */
    const char *map_out, *pdf;    /* NULL: map.yaml, no PDF */
    double area_w, area_h;        /* --area (0: none) */
    const char *family;           /* --family (NULL: ring5) */
    int hamming;                  /* 1, or 2: even-parity ids only */
    int min_view;                 /* 0: not given (3) */
    unsigned long seed;           /* 0: not given (1) */
    int force;                    /* --force: the default map.yaml may be replaced */
} plan_opts;

static void plan_opts_defaults(plan_opts *o)
{
    memset(o, 0, sizeof *o);
    rl_plan_defaults(&o->in);
    o->paper_name = "a4";
    o->hfov = o->ceiling = o->cam_z = o->pitch = o->diameter = -1;
    o->hamming = 1;
}

/* --area WxH in metres */
static int parse_area(const char *C, const char *s, plan_opts *o)
{
    int used = -1;
    if (sscanf(s, "%lfx%lf%n", &o->area_w, &o->area_h, &used) != 2 || s[used] != '\0' || !(o->area_w > 0) ||
        !(o->area_h > 0) || o->area_w > 10000 || o->area_h > 10000)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--area: '%s' is not a size in metres like 60x40", s);
    return 0;
}

/* One option into o: 0, or the exit code (its error line printed). */
static int plan_option(const char *C, int c, const char *arg, plan_opts *o)
{
    int sd, ok = 1;
    switch (c) {
    case 'n': ok = rl_cli_int(C, "--landmarks", arg, 1, 1000000, &o->in.landmarks); break;
    case 'c': o->camera = arg; break;
    case 'r': ok = rl_cli_size(C, "--resolution", arg, RL_MAX_IMAGE_DIM, &o->in.width, &o->in.height); break;
    case 'f': ok = rl_cli_double(C, "--hfov", arg, 1, 179, &o->hfov); break;
    case 'd': ok = rl_cli_double(C, "--distance", arg, 0.05, 100, &o->in.distance); break;
    case 'H': ok = rl_cli_double(C, "--ceiling-height", arg, 0.05, 100, &o->ceiling); break;
    case 'Z': ok = rl_cli_double(C, "--camera-height", arg, 0, 100, &o->cam_z); break;
    case 'm': ok = rl_cli_double(C, "--min-ring-px", arg, 0.5, 100, &o->in.min_ring_px); break;
    case 'p': o->paper_name = arg; break;
    case 'g': ok = rl_cli_size(C, "--grid", arg, 10000, &o->cols, &o->rows); break;
    case 'P': ok = rl_cli_double(C, "--pitch", arg, 0.01, 100, &o->pitch); break;
    case 'o': o->map_out = arg; break;
    case 'F': o->pdf = arg; break;
    case 'W': o->force = 1; break;
    case 'D': ok = rl_cli_double(C, "--diameter", arg, 0.001, 5, &o->diameter); break;
    case 'A': return parse_area(C, arg, o);
    case 'y': o->family = arg; break;
    case 'M': ok = rl_cli_int(C, "--hamming", arg, 1, 2, &o->hamming); break;
    case 'K': ok = rl_cli_int(C, "--min-view", arg, 3, 100, &o->min_view); break;
    case 'S':
        ok = rl_cli_int(C, "--seed", arg, 0, 1000000000, &sd);
        o->seed = ok ? (unsigned long)sd : 0;
        break;
    default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
    }
    return ok ? 0 : RL_EXIT_USAGE;
}

/* The command line into o: -1 to go on, or the exit code (0 after --help). */
static int plan_args(const char *C, int argc, char **argv, plan_opts *o)
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
        {"seed", required_argument, 0, 'S'},       {"force", no_argument, 0, 'W'},
        {"help", no_argument, 0, 'h'},             {0, 0, 0, 0}};
    int c, r;
    plan_opts_defaults(o);
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        if (c == 'h') {
            fputs(plan_help, stdout);
            return 0;
        }
        if ((r = plan_option(C, c, optarg, o)) != 0)
            return r;
    }
    if (optind < argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "unexpected argument '%s'", argv[optind]);
    return -1;
}

/* The image size and focal length: the calibration's, or --hfov's. */
static int plan_camera(const char *C, plan_opts *o)
{
    static rl_site site;
    rl_site_files files;
    char err[768];
    if (o->camera == NULL) {
        if (!(o->hfov > 0 && o->hfov < 179))
            return rl_cli_fail(C, RL_EXIT_USAGE, "give --camera FILE, or --hfov DEG (0 .. 179) "
                                                 "with --resolution WxH");
        o->in.fx = (o->in.width / 2.0) / tan(o->hfov * M_PI / 360.0);
        return 0;
    }
    rl_site_files_init(&files);
    files.calibration = o->camera;
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    o->in.width = site.calib.width;
    o->in.height = site.calib.height;
    o->in.fx = site.calib.fx;
    return 0;
}

/* The distance to the ceiling and how many ids the site needs: 0, or the
 * exit code. */
static int plan_needs(const char *C, plan_opts *o)
{
    rl_family fam;
    if (o->ceiling > 0 && o->cam_z >= 0 && o->in.distance <= 0)
        o->in.distance = o->ceiling - o->cam_z;
    if (!(o->in.distance > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "give --distance M, or --ceiling-height above "
                                             "--camera-height (the camera must be below the ceiling)");
    if (o->area_w > 0) {
        if (o->cols > 0)
            return rl_cli_fail(C, RL_EXIT_USAGE, "give --area or --grid, not both");
        if (rl_family_parse(o->family ? o->family : "ring5", &fam) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_USAGE, "--family: '%s' is not ring2 .. ring%d", o->family, RL_MAX_BITS);
        o->in.landmarks = rl_family_count(&fam); /* the plan's diameter for this family */
    } else if (o->family != NULL || o->hamming != 1 || o->min_view || o->seed) {
        return rl_cli_fail(C, RL_EXIT_USAGE, "--family, --hamming, --min-view and --seed go with --area");
    }
    if (o->cols > 0 && o->in.landmarks == 0)
        o->in.landmarks = (long)o->cols * o->rows > 1000000 ? 1000001 : o->cols * o->rows;
    if (o->in.landmarks <= 0)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--landmarks: how many landmarks does the site need?");
    if (!(o->in.min_ring_px > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--min-ring-px must be positive");
    return 0;
}

/* The calculator's figures; 0, or the exit code when the diameter does
 * not fit the paper. */
static int print_plan(const char *C, const rl_plan_input *in, const rl_plan_result *out, rl_err e,
                      const rl_paper *paper)
{
    int k;
    printf("ringloc plan: %d landmarks, %dx%d camera, fx %.1f px, %.3f m to the ceiling\n",
           in->landmarks, in->width, in->height, in->fx, in->distance);
    printf("  ceiling in view    %.3f x %.3f m (%.1f px per metre)\n", out->view_w, out->view_h,
           out->px_per_m);
    printf("  family             ring%d (%d ids, %d code rings)\n", out->bits, (1 << out->bits) - 2,
           out->bits);
    printf("  printed diameter   %.3f m (at least %.4f m for %.1f px code rings)\n", out->diameter,
           out->diameter_min, in->min_ring_px);
    if (e == RL_ERANGE)
        return rl_cli_fail(C, RL_EXIT_FAIL,
                           "%.3f m does not fit %s paper (at most %.3f m): use a larger --paper, a "
                           "smaller --min-ring-px, or a camera closer to the ceiling",
                           out->diameter, paper->name, in->max_diameter);
    printf("  in the image       %.1f px across; ring widths (px): outer %.2f", 2 * out->radius_px,
           out->ring_px[0]);
    for (k = 1; k <= out->bits; k++)
        printf(k == out->bits ? " | centre disk %d radius %.2f" : " | code %d %.2f", k, out->ring_px[k]);
    printf("\n");
    if (out->pitch_max <= 0) {
        printf("  grid pitch         none: two whole landmarks never fit in view at this size\n");
    } else {
        printf("  grid pitch         at most %.3f m keeps two whole landmarks in view at any "
               "position and heading;\n                     recommended %.3f m\n",
               out->pitch_max, out->pitch);
    }
    return 0;
}

/* The map's landmarks, one PDF page each. */
static int write_pdf(const char *C, const char *pdf, const rl_paper *paper, const rl_map *map)
{
    static int ids[RL_MAX_MAP_LANDMARKS];
    char err[512];
    int i;
    for (i = 0; i < map->count; i++)
        ids[i] = map->lm[i].id;
    if (rl_print_pdf(pdf, paper, &map->family, ids, map->lm, map->count, map->diameter, err, sizeof err) !=
        RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    return 0;
}

/* --grid CxR: the check that it fits, then its map (ids 1, 2, ... row by
 * row from the origin) and PDF. */
static int plan_grid(const char *C, const plan_opts *o, const rl_plan_result *out, const rl_paper *paper)
{
    static rl_map map;
    const char *map_out = o->map_out ? o->map_out : "map.yaml";
    char err[512];
    int i, j;
    if (o->pitch <= 0)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--grid needs --pitch P (recommended %.3f)", out->pitch);
    if (!(o->ceiling > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--grid needs --ceiling-height (it goes into the map)");
    if ((long)o->cols * o->rows > (1 << out->bits) - 2 || (long)o->cols * o->rows > RL_MAX_MAP_LANDMARKS)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--grid %dx%d needs %d ids; ring%d has %d", o->cols, o->rows,
                           o->cols * o->rows, out->bits, (1 << out->bits) - 2);
    if (o->pitch > out->pitch_max && out->pitch_max > 0)
        fprintf(stderr, "ringloc plan: note: pitch %.3f m is above %.3f m: some places will see "
                        "fewer than two landmarks\n", o->pitch, out->pitch_max);
    if (o->diameter > 0 && o->diameter > o->in.max_diameter)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--diameter %.3f m does not fit %s paper", o->diameter, paper->name);
    if (rl_family_init(&map.family, out->bits) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "internal error: family");
    map.diameter = o->diameter > 0 ? o->diameter : out->diameter;
    map.ceiling_height = o->ceiling;
    map.count = 0;
    for (j = 0; j < o->rows; j++)
        for (i = 0; i < o->cols; i++) {
            rl_map_landmark *lm = &map.lm[map.count];
            lm->id = map.count + 1;
            lm->x = i * o->pitch;
            lm->y = j * o->pitch;
            lm->sigma_x = lm->sigma_y = lm->z = 0;
            map.count++;
        }
    if (rl_mapfile_save(map_out, &map, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    printf("  map                %s: %dx%d landmarks %.3f m apart\n", map_out, o->cols, o->rows, o->pitch);
    if (o->pdf == NULL)
        return 0;
    if (write_pdf(C, o->pdf, paper, &map) != 0)
        return RL_EXIT_FAIL;
    printf("  pdf                %s: %d pages\n", o->pdf, map.count);
    return 0;
}

/* The map goes to map.yaml when no --map-out names it: a map already
 * there (a surveyed one, say) is kept unless --force. 0, or the exit code. */
static int default_map_free(const char *C, const plan_opts *o)
{
    struct stat st;
    if (o->map_out != NULL || o->force || lstat("map.yaml", &st) != 0)
        return 0;
    return rl_cli_fail(C, RL_EXIT_FAIL, "map.yaml exists; not replaced (name it with --map-out map.yaml, "
                       "or give --force)");
}

/* --area: what the area is planned with, from the options and the plan. */
typedef struct {
    double width, height, pitch;
    double view_w, view_h;   /* the camera's footprint on the ceiling, m */
    double diameter, ceiling;
    rl_family family;
    int even_parity, min_view;
    unsigned long seed;
    const char *map_out, *pdf; /* pdf may be NULL */
    const rl_paper *paper;
} plan_area;

static void progress(void *ctx, int stage, long failing)
{
    (void)ctx;
    fprintf(stderr, "ringloc plan: views of %d or more landmarks: %ld not unique%s\n", stage, failing,
            failing ? "; ids redrawn" : "");
}

/* Whether path can be written (its temporary made and removed: nothing
 * left behind, the target untouched). */
static int writable(const char *path, char *err, size_t errlen)
{
    rl_outfile o;
    if (rl_outfile_open(&o, path, err, errlen) != RL_OK)
        return 0;
    rl_outfile_abort(&o);
    return 1;
}

/* The planned grid as a map. */
static void to_map(const plan_area *a, const rl_site_plan_result *r, const int *ids, rl_map *map)
{
    int i, j;
    map->family = a->family;
    map->diameter = a->diameter;
    map->ceiling_height = a->ceiling;
    map->count = 0;
    for (j = 0; j < r->rows; j++)
        for (i = 0; i < r->cols; i++) {
            rl_map_landmark *lm = &map->lm[map->count++];
            lm->id = ids[j * r->cols + i];
            lm->x = r->x0 + i * a->pitch;
            lm->y = r->y0 + j * a->pitch;
            lm->sigma_x = lm->sigma_y = 0;
            lm->z = 0;
        }
}

static void print_json(const plan_area *a, const rl_site_plan_input *in, const rl_site_plan_result *r,
                       rl_err e)
{
    printf("{\"area\": [%.3f, %.3f], \"pitch\": %.4f, \"family\": \"ring%d\", \"diameter\": %.4f, "
           "\"view\": [%.3f, %.3f], \"cols\": %d, \"rows\": %d, \"landmarks\": %d, \"ids\": %d, "
           "\"even_parity\": %s, \"min_view\": %d, \"k_achieved\": %d, \"all_unique\": %s, "
           "\"views_checked\": %ld, \"views_not_unique\": %ld, \"smallest_view\": %d, \"rounds\": %d, "
           "\"redrawn\": %ld, \"gap\": %.3f, \"seed\": %lu, \"map\": \"%s\", \"pdf\": %s%s%s, "
           "\"seconds\": %.2f}\n",
           a->width, a->height, a->pitch, a->family.bits, a->diameter, in->view_w, in->view_h, r->cols,
           r->rows, r->cols * r->rows, r->ids_used, in->even_parity ? "true" : "false", in->min_view,
           r->k_achieved, e == RL_OK ? "true" : "false", r->views, r->failing, r->smallest_view, r->rounds,
           r->redrawn, in->gap, in->seed, a->map_out, a->pdf ? "\"" : "", a->pdf ? a->pdf : "null",
           a->pdf ? "\"" : "", r->seconds);
}

/* The area's ids planned (rl_site_plan), the map and PDF written, the
 * figures printed as one JSON line; the exit code. */
static int plan_area_run(const char *C, const plan_area *a)
{
    static rl_map map;
    static int ids[RL_MAX_MAP_LANDMARKS];
    rl_site_plan_input in;
    rl_site_plan_result r;
    char err[512];
    rl_err e;
    long need = (long)(a->width / a->pitch + 1e-9) * (long)(a->height / a->pitch + 1e-9);
    if (need > RL_MAX_MAP_LANDMARKS)
        return rl_cli_fail(C, RL_EXIT_USAGE,
                           "--area %gx%g at pitch %g needs %ld landmarks, more than a map holds (%d)", a->width,
                           a->height, a->pitch, need, RL_MAX_MAP_LANDMARKS);
    rl_site_plan_defaults(&in);
    in.width = a->width;
    in.height = a->height;
    in.pitch = a->pitch;
    in.view_w = a->view_w;
    in.view_h = a->view_h;
    in.diameter = a->diameter;
    in.n_ids = rl_family_count(&a->family);
    in.bits = a->family.bits;
    in.even_parity = a->even_parity;
    in.min_view = a->min_view;
    in.seed = a->seed;
    in.gap = 2 * a->pitch;
    in.progress = progress;
    if (!(a->pitch > a->diameter))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--pitch %g m: landmarks of %g m would overlap", a->pitch,
                           a->diameter);
    if (!(a->view_w - a->diameter > a->pitch) || !(a->view_h - a->diameter > a->pitch))
        return rl_cli_fail(C, RL_EXIT_USAGE,
                           "--pitch %g m: the camera's view (%.2f x %.2f m) holds too few whole landmarks "
                           "to tell places apart",
                           a->pitch, a->view_w, a->view_h);
    if (!writable(a->map_out, err, sizeof err) || (a->pdf && !writable(a->pdf, err, sizeof err)))
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err); /* before a minute of planning */
    e = rl_site_plan(&in, ids, RL_MAX_MAP_LANDMARKS, &r);
    if (e == RL_ERANGE)
        return rl_cli_fail(C, RL_EXIT_FAIL, "ring%d%s has too few ids to keep each id %.2f m from its repeats",
                           a->family.bits, a->even_parity ? " (even parity)" : "", in.gap);
    if (e != RL_OK && e != RL_ELIMIT)
        return rl_cli_fail(C, RL_EXIT_FAIL, "planning failed: %s", rl_strerror(e));
    to_map(a, &r, ids, &map);
    if (rl_mapfile_save(a->map_out, &map, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (a->pdf != NULL) {
        fprintf(stderr, "ringloc plan: writing %d pages to %s\n", map.count, a->pdf);
        if (write_pdf(C, a->pdf, a->paper, &map) != 0)
            return RL_EXIT_FAIL;
    }
    print_json(a, &in, &r, e);
    if (e == RL_ELIMIT)
        fprintf(stderr,
                "ringloc plan: note: every view of %d or more whole landmarks is unique; %ld views of %d .. %d "
                "(near the walls) are not, and a frame showing only those is found by tracking\n",
                r.k_achieved, r.failing, a->min_view, r.k_achieved - 1);
    return 0;
}

/* --area: the site's ids with this plan's view and diameter. */
static int plan_area_mode(const char *C, const plan_opts *o, const rl_plan_result *out, rl_err e,
                          const rl_paper *paper)
{
    plan_area a;
    memset(&a, 0, sizeof a);
    if (rl_family_parse(o->family ? o->family : "ring5", &a.family) != RL_OK || out->bits != a.family.bits)
        return rl_cli_fail(C, RL_EXIT_FAIL, "internal error: the plan chose ring%d", out->bits);
    if (e == RL_ERANGE && !(o->diameter > 0))
        return rl_cli_fail(C, RL_EXIT_FAIL, "ring%d needs %.3f m landmarks, more than %s paper holds (%.3f m)",
                           out->bits, out->diameter, paper->name, o->in.max_diameter);
    if (!(o->pitch > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--area needs --pitch P (the paper's tiles: 0.61)");
    if (!(o->ceiling > 0))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--area needs --ceiling-height (it goes into the map)");
    a.width = o->area_w;
    a.height = o->area_h;
    a.pitch = o->pitch;
    a.view_w = out->view_w;
    a.view_h = out->view_h;
    a.diameter = o->diameter > 0 ? o->diameter : out->diameter;
    a.ceiling = o->ceiling;
    a.even_parity = o->hamming == 2;
    a.min_view = o->min_view ? o->min_view : 3;
    a.seed = o->seed ? o->seed : 1;
    a.map_out = o->map_out ? o->map_out : "map.yaml";
    a.pdf = o->pdf;
    a.paper = paper;
    return plan_area_run(C, &a);
}

int rl_cmd_plan(int argc, char **argv)
{
    const char *C = "plan";
    static plan_opts o;
    const rl_paper *paper;
    rl_plan_result out;
    rl_err e;
    int r;

    if ((r = plan_args(C, argc, argv, &o)) >= 0)
        return r;
    paper = rl_paper_find(o.paper_name);
    if (paper == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--paper: unknown paper '%s' (%s)", o.paper_name, rl_paper_names());
    o.in.max_diameter = rl_print_max_diameter(paper, RL_PRINT_MARGIN_MM);
    if ((r = plan_camera(C, &o)) != 0 || (r = plan_needs(C, &o)) != 0)
        return r;
    e = rl_plan_compute(&o.in, &out);
    if (e == RL_ERANGE && out.bits == 0)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%d landmarks need more than the %d ids of ring%d; "
                                            "reuse ids in separate areas", o.in.landmarks,
                           (1 << RL_MAX_BITS) - 2, RL_MAX_BITS);
    if (e == RL_EINVAL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "inputs must be positive");
    if ((o.area_w > 0 || o.cols > 0) && (r = default_map_free(C, &o)) != 0)
        return r;
    if (o.area_w > 0)
        return plan_area_mode(C, &o, &out, e, paper);
    if ((r = print_plan(C, &o.in, &out, e, paper)) != 0)
        return r;
    return o.cols > 0 ? plan_grid(C, &o, &out, paper) : 0;
}
