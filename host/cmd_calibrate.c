/* ringloc calibrate-offsets: the paper's pixel-to-offset maps. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_mapfile.h"
#include "rl_offsetsfile.h"
#include "rl_png.h"
#include "rl_report.h"
#include "rl_robotfile.h"

static const char *calib_help =
    "usage: ringloc calibrate-offsets --map MAP.yaml --robot ROBOT.yaml --pose X,Y,YAW\n"
    "                                 [--degree 2] --out OFFSETS.yaml IMAGE...\n\n"
    "The paper's alternative to the pinhole model: from images of landmarks at\n"
    "known map positions taken with the robot at a known pose, fit the physical\n"
    "offset of a ceiling point from the optical axis as a polynomial in its pixel\n"
    "coordinates (one per axis). 'ringloc locate --offsets FILE' then uses it.\n"
    "Degree 1, 2 or 3 needs at least 5, 8 or 12 identified landmarks over all\n"
    "images (shift the robot between shots for more).\n";

#define MAX_SAMPLES 2048

/* The landmark of `id` nearest (x, y): the one a camera there sees, on a
 * map that repeats ids too; -1 if the map has none. */
static int nearest_of_id(const rl_map *map, int id, double x, double y)
{
    int i, best = -1;
    double best_d = 0;
    for (i = 0; i < map->count; i++) {
        double d = hypot(map->lm[i].x - x, map->lm[i].y - y);
        if (map->lm[i].id == id && (best < 0 || d < best_d)) {
            best = i;
            best_d = d;
        }
    }
    return best;
}

int rl_cmd_calibrate(int argc, char **argv)
{
    static const struct option opts[] = {
        {"map", required_argument, 0, 'm'}, {"robot", required_argument, 0, 'r'},
        {"pose", required_argument, 0, 'p'}, {"degree", required_argument, 0, 'd'},
        {"out", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    const char *C = "calibrate-offsets", *map_path = NULL, *robot_path = NULL, *out = NULL;
    static double U[MAX_SAMPLES], V[MAX_SAMPLES], F[MAX_SAMPLES], L[MAX_SAMPLES];
    static rl_map map;
    static rl_result res;
    double px = 0, py = 0, pyaw = 0, cx, cy, cyaw;
    int have_pose = 0, c, i, j, n = 0, ids[RL_MAX_IDS];
    rl_offsets o;
    rl_mount mount;
    rl_recog_config cfg;
    rl_heap_recog hr;
    char err[512], tail;

    memset(&o, 0, sizeof o);
    o.degree = 2;
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        switch (c) {
        case 'm': map_path = optarg; break;
        case 'r': robot_path = optarg; break;
        case 'p':
            if (sscanf(optarg, "%lf,%lf,%lf%c", &px, &py, &pyaw, &tail) != 3)
                return rl_cli_fail(C, RL_EXIT_USAGE, "--pose: '%s' is not X,Y,YAW (metres, radians)", optarg);
            if (!(fabs(px) <= RL_MAP_MAX_COORD && fabs(py) <= RL_MAP_MAX_COORD && fabs(pyaw) <= 7))
                return rl_cli_fail(C, RL_EXIT_USAGE, "--pose: %s is out of range (|x|, |y| <= %g m, "
                                   "|yaw| <= 7 rad)", optarg, RL_MAP_MAX_COORD);
            have_pose = 1;
            break;
        case 'd':
            if (!rl_cli_int(C, "--degree", optarg, 1, 3, &o.degree))
                return RL_EXIT_USAGE;
            if (o.degree < 1 || o.degree > 3)
                return rl_cli_fail(C, RL_EXIT_USAGE, "--degree: %d is not 1, 2 or 3", o.degree);
            break;
        case 'o': out = optarg; break;
        case 'h': fputs(calib_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (!map_path || !robot_path || !have_pose || !out)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--map, --robot, --pose and --out are required (see --help)");
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "no images given (see --help)");
    if (rl_mapfile_load(map_path, &map, err, sizeof err) != RL_OK ||
        rl_robotfile_load(robot_path, &mount, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    o.distance = map.ceiling_height - mount.z;
    if (!(o.distance > 0))
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: the camera is not below the ceiling of %s", robot_path, map_path);
    /* the camera's pose from the robot's */
    cyaw = pyaw + mount.yaw;
    cx = px + cos(pyaw) * mount.x - sin(pyaw) * mount.y;
    cy = py + sin(pyaw) * mount.x + cos(pyaw) * mount.y;
    rl_recog_defaults(&cfg);
    rl_recog_use_map(&cfg, &map, ids);
    cfg.local = RL_LOCAL_ALWAYS;
    rl_heap_recog_init(&hr, &cfg);
    for (i = optind; i < argc; i++) {
        rl_image img;
        double us;
        if (rl_png_read_gray(argv[i], &img, err, sizeof err) != RL_OK) {
            rl_heap_recog_free(&hr);
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
        }
        o.u0 = (img.width - 1) / 2.0;
        o.v0 = (img.height - 1) / 2.0;
        o.scale = img.width / 2.0;
        if (rl_report_run(&hr, &img, &res, &us) != RL_OK) {
            rl_png_free(&img);
            rl_heap_recog_free(&hr);
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s: recognition failed", argv[i]);
        }
        for (j = 0; j < res.n_landmarks && n < MAX_SAMPLES; j++) {
            int k = nearest_of_id(&map, res.landmarks[j].id, cx, cy);
            double dx, dy;
            if (k < 0)
                continue;
            dx = map.lm[k].x - cx;
            dy = map.lm[k].y - cy;
            U[n] = res.landmarks[j].u;
            V[n] = res.landmarks[j].v;
            F[n] = cos(cyaw) * dx + sin(cyaw) * dy;
            L[n] = -sin(cyaw) * dx + cos(cyaw) * dy;
            n++;
        }
        rl_png_free(&img);
    }
    rl_heap_recog_free(&hr);
    if (rl_offsets_fit(&o, U, V, F, L, n) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%d landmarks identified in the images; degree %d needs at least %d "
                                            "spread over the view", n, o.degree, rl_offsets_terms(o.degree) + 2);
    if (rl_offsetsfile_save(out, &o, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    {
        double s2 = 0;
        for (j = 0; j < n; j++) {
            double f, l;
            rl_offsets_eval(&o, U[j], V[j], &f, &l);
            s2 += (f - F[j]) * (f - F[j]) + (l - L[j]) * (l - L[j]);
        }
        fprintf(stderr, "ringloc calibrate-offsets: %d landmarks, degree %d, RMS fit error %.1f mm -> %s\n",
                n, o.degree, 1000 * sqrt(s2 / n), out);
    }
    return 0;
}
