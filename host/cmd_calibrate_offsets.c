/* ringloc calibrate-offsets: the paper's pixel-to-offset maps. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_offsetsfile.h"
#include "rl_pngrun.h"
#include "rl_site.h"

static const char *calib_help =
    "usage: ringloc calibrate-offsets --map MAP.yaml --robot ROBOT.yaml --pose X,Y,YAW\n"
    "                                 [--degree 2] --out OFFSETS.yaml IMAGE...\n\n"
    "The paper's alternative to the pinhole model: from images of landmarks at\n"
    "known map positions taken with the robot at a known pose, fit the physical\n"
    "offset of a ceiling point from the optical axis as a polynomial in its pixel\n"
    "coordinates (one per axis). 'ringloc locate --offsets FILE' then uses it.\n"
    "Degree 1, 2 or 3 needs at least 5, 8 or 12 identified landmarks over all\n"
    "images (shift the robot between shots for more); every image of one size.\n\n"
    "  --map FILE       landmark map YAML\n"
    "  --robot FILE     robot YAML: camera_mount {x, y, z, yaw}\n"
    "  --pose X,Y,YAW   the robot's pose in the map while the images were taken\n"
    "                   (metres, radians)\n"
    "  --degree N       the polynomials' degree: 1, 2 (default) or 3\n"
    "  --out FILE       the offset maps to write (written whole or not at all)\n";

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

/* The robot's known pose, and the samples its images give. */
typedef struct {
    const rl_site *site;
    double px, py, pyaw;      /* --pose */
    double cx, cy, cyaw;      /* the camera's pose, from the robot's */
    rl_offsets o;
    int n;
    int width, height;        /* the images' size (one calibration is for one size) */
    char other[600];          /* an image of another size, or "" */
    double U[MAX_SAMPLES], V[MAX_SAMPLES], F[MAX_SAMPLES], L[MAX_SAMPLES];
} offsets_fit;

/* The camera's pose from the robot's and the mount. */
static void camera_pose(offsets_fit *f)
{
    const rl_mount *m = &f->site->mount;
    f->cyaw = f->pyaw + m->yaw;
    f->cx = f->px + cos(f->pyaw) * m->x - sin(f->pyaw) * m->y;
    f->cy = f->py + sin(f->pyaw) * m->x + cos(f->pyaw) * m->y;
}

/* Each identified landmark of a frame: its pixel and its offset from the
 * camera (forward, left) in the map. */
static rl_err offsets_put(void *ctx, const rl_run_report *rep)
{
    offsets_fit *f = (offsets_fit *)ctx;
    const rl_map *map = &f->site->map;
    int j;
    if (f->width == 0) {
        f->width = rep->frame->img.width;
        f->height = rep->frame->img.height;
    } else if (rep->frame->img.width != f->width || rep->frame->img.height != f->height) {
        if (!f->other[0])
            snprintf(f->other, sizeof f->other, "%.400s: image is %dx%d but the first image is %dx%d (the maps "
                     "are for one size)", rep->frame->name, rep->frame->img.width, rep->frame->img.height, f->width,
                     f->height);
        return RL_OK;
    }
    f->o.u0 = (rep->frame->img.width - 1) / 2.0;
    f->o.v0 = (rep->frame->img.height - 1) / 2.0;
    f->o.scale = rep->frame->img.width / 2.0;
    for (j = 0; j < rep->res->n_landmarks && f->n < MAX_SAMPLES; j++) {
        int k = nearest_of_id(map, rep->res->landmarks[j].id, f->cx, f->cy);
        double dx, dy;
        if (k < 0)
            continue;
        /* its offset as it would be at the ceiling's distance (a landmark
         * hung lower is seen as far out as one that much further out on
         * the ceiling) */
        dx = (map->lm[k].x - f->cx) * (map->ceiling_height - f->site->mount.z) /
             (rl_map_height(map, k) - f->site->mount.z);
        dy = (map->lm[k].y - f->cy) * (map->ceiling_height - f->site->mount.z) /
             (rl_map_height(map, k) - f->site->mount.z);
        f->U[f->n] = rep->res->landmarks[j].u;
        f->V[f->n] = rep->res->landmarks[j].v;
        f->F[f->n] = cos(f->cyaw) * dx + sin(f->cyaw) * dy;
        f->L[f->n] = -sin(f->cyaw) * dx + cos(f->cyaw) * dy;
        f->n++;
    }
    return RL_OK;
}

/* RMS of the fit over its samples, metres. */
static double fit_rms(const offsets_fit *f)
{
    double s2 = 0;
    int j;
    for (j = 0; j < f->n; j++) {
        double fw, l;
        rl_offsets_eval(&f->o, f->U[j], f->V[j], &fw, &l);
        s2 += (fw - f->F[j]) * (fw - f->F[j]) + (l - f->L[j]) * (l - f->L[j]);
    }
    return sqrt(s2 / f->n);
}

/* --pose X,Y,YAW; 0 after a usage error line. */
static int parse_pose(const char *C, const char *arg, offsets_fit *f)
{
    static const char *form = "X,Y,YAW (metres, radians)";
    double v[3];
    int n;
    if (!rl_cli_doubles(C, "--pose", arg, form, v, 3, &n))
        return 0;
    if (n != 3)
        return !rl_cli_fail(C, RL_EXIT_USAGE, "--pose: '%s' is not %s", arg, form);
    f->px = v[0];
    f->py = v[1];
    f->pyaw = v[2];
    if (!(fabs(f->px) <= RL_MAP_MAX_COORD && fabs(f->py) <= RL_MAP_MAX_COORD && fabs(f->pyaw) <= 7))
        return !rl_cli_fail(C, RL_EXIT_USAGE, "--pose: %s is out of range (|x|, |y| <= %g m, |yaw| <= 7 rad)", arg,
                            RL_MAP_MAX_COORD);
    return 1;
}

typedef struct {
    rl_site_files files;
    const char *out;
    int have_pose;
} offsets_args;

/* The options; 0 to go on, else the exit code (--help: 0 with *done). */
static int parse_args(const char *C, int argc, char **argv, offsets_args *a, offsets_fit *f, int *done)
{
    static const struct option opts[] = {
        {"map", required_argument, 0, 'm'}, {"robot", required_argument, 0, 'r'},
        {"pose", required_argument, 0, 'p'}, {"degree", required_argument, 0, 'd'},
        {"out", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    int c;
    *done = 0;
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        switch (c) {
        case 'm': a->files.map = optarg; break;
        case 'r': a->files.robot = optarg; break;
        case 'p':
            if (!parse_pose(C, optarg, f))
                return RL_EXIT_USAGE;
            a->have_pose = 1;
            break;
        case 'd':
            if (!rl_cli_int(C, "--degree", optarg, 1, 3, &f->o.degree))
                return RL_EXIT_USAGE;
            break;
        case 'o': a->out = optarg; break;
        case 'h': fputs(calib_help, stdout); *done = 1; return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (!a->files.map || !a->files.robot || !a->have_pose || !a->out)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--map, --robot, --pose and --out are required (see --help)");
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "no images given (see --help)");
    return 0;
}

int rl_cmd_calibrate_offsets(int argc, char **argv)
{
    const char *C = "calibrate-offsets";
    static rl_site site;
    static offsets_fit f;
    offsets_args a;
    rl_recog_config cfg;
    rl_pngrun pr;
    char err[768];
    int code, done;
    long failed;

    memset(&a, 0, sizeof a);
    memset(&f, 0, sizeof f);
    rl_site_files_init(&a.files);
    f.o.degree = 2;
    if ((code = parse_args(C, argc, argv, &a, &f, &done)) != 0 || done)
        return code;
    rl_recog_defaults(&cfg);
    cfg.local = RL_LOCAL_ALWAYS;
    if (rl_site_load(&site, &a.files, err, sizeof err) != RL_OK || rl_site_prepare(&site, &cfg, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    f.site = &site;
    f.o.distance = site.map.ceiling_height - site.mount.z;
    camera_pose(&f);
    rl_pngrun_defaults(&pr, C);
    pr.put = offsets_put;
    pr.ctx = &f;
    failed = rl_pngrun_files(&pr, &site, argv + optind, argc - optind);
    rl_site_free(&site);
    if (failed > 0)
        return RL_EXIT_FAIL; /* each file said why */
    if (f.other[0])
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", f.other);
    if (rl_offsets_fit(&f.o, f.U, f.V, f.F, f.L, f.n) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%d landmarks identified in the images; degree %d needs at least %d "
                                            "spread over the view", f.n, f.o.degree, rl_offsets_terms(f.o.degree) + 2);
    if (rl_offsetsfile_save(a.out, &f.o, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    fprintf(stderr, "ringloc calibrate-offsets: %d landmarks, degree %d, RMS fit error %.1f mm -> %s\n", f.n,
            f.o.degree, 1000 * fit_rms(&f), a.out);
    return 0;
}
