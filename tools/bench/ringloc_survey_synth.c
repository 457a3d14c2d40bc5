/* ringloc-survey-synth: a large site's drive as `ringloc detect` JSON
 * lines, for timing the survey (make bench), and the survey's map
 * compared with that site's truth.
 *
 *   ringloc-survey-synth --camera CAM.yaml --out DIR [--cols 50 --rows 40 --frames 20000 --seed 1]
 *   ringloc-survey-synth --compare TRUTH.yaml SURVEY.yaml
 *
 * The site: a grid 0.61 m apart, each landmark up to 15 cm off it, ring6
 * ids repeating (1..60; 61 and 62 once, the origin and the axis). The
 * drive: back and forth over every row, weaving. Each frame's landmarks
 * are projected through the camera (the renderer's, --write-camera, in
 * make bench) onto the image, with 0.1 px of noise on centres and radii;
 * the border cuts those that reach it. */
#include <getopt.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "rl_calibfile.h"
#include "rl_cli.h"
#include "rl_mapfile.h"
#include "rl_outfile.h"
#include "rl_pose_fit.h"
#include "rl_robotfile.h"
#include "rl_site.h"

#define PITCH 0.61
#define HEIGHT 2.75

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double urand(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}
static double nrand(void)
{
    double u = urand() + 1e-12, v = urand();
    return sqrt(-2 * log(u)) * cos(2 * M_PI * v);
}

typedef struct {
    int id;
    double x, y;
} mark;

static int compare(const char *truth_path, const char *survey_path)
{
    /* both files as ringloc writes them: one landmark per line */
    FILE *f[2] = {fopen(truth_path, "r"), fopen(survey_path, "r")};
    static mark m[2][20000];
    int n[2] = {0, 0}, k, i, j, o = -1, a = -1;
    char line[512];
    double ss = 0, th, ox, oy;
    int used = 0;
    for (k = 0; k < 2; k++) {
        if (f[k] == NULL) {
            fprintf(stderr, "ringloc-survey-synth: %s: cannot open\n", k ? survey_path : truth_path);
            return 1;
        }
        while (fgets(line, sizeof line, f[k]) && n[k] < 20000)
            if (sscanf(line, "  - {id: %d, x: %lf, y: %lf", &m[k][n[k]].id, &m[k][n[k]].x, &m[k][n[k]].y) == 3)
                n[k]++;
        fclose(f[k]);
    }
    for (i = 0; i < n[0]; i++) {
        if (m[0][i].id == 61)
            o = i;
        if (m[0][i].id == 62)
            a = i;
    }
    if (o < 0 || a < 0)
        return fprintf(stderr, "ringloc-survey-synth: %s: no landmarks 61 and 62\n", truth_path), 1;
    ox = m[0][o].x, oy = m[0][o].y;
    th = atan2(m[0][a].y - oy, m[0][a].x - ox);
    /* each surveyed landmark against the nearest true one of its id */
    for (j = 0; j < n[1]; j++) {
        double best = 1e9;
        for (i = 0; i < n[0]; i++) {
            double x = m[0][i].x - ox, y = m[0][i].y - oy, X = cos(th) * x + sin(th) * y,
                   Y = -sin(th) * x + cos(th) * y, d = hypot(X - m[1][j].x, Y - m[1][j].y);
            if (m[0][i].id == m[1][j].id && d < best)
                best = d;
        }
        if (best < 0.3) {
            ss += best * best;
            used++;
        }
    }
    printf("{\"true_landmarks\": %d, \"surveyed\": %d, \"matched\": %d, \"rms_mm\": %.2f}\n", n[0], n[1], used,
           used ? 1000 * sqrt(ss / used) : 0.0);
    return 0;
}

/* What the command line asks for. */
typedef struct {
    const char *out, *cmp, *camera; /* --out, --compare, --camera */
    int cols, rows, frames;         /* the site's grid (50 x 40), the drive's frames (20000) */
    unsigned long seed;             /* default 1 */
    double noise, rock;             /* px on centres and radii (0.1); the robot's rocking, rad (0.01) */
} synth_opts;

static void synth_opts_defaults(synth_opts *o)
{
    memset(o, 0, sizeof *o);
    o->cols = 50;
    o->rows = 40;
    o->frames = 20000;
    o->seed = 1;
    o->noise = 0.1;
    o->rock = 0.01;
}

/* One option into o: 1, or 0 with the error line printed. */
static int synth_option(int c, const char *arg, synth_opts *o)
{
    switch (c) {
    case 'o': o->out = arg; return 1;
    case 'c': return rl_cli_int(NULL, "--cols", arg, 2, 20000, &o->cols);
    case 'r': return rl_cli_int(NULL, "--rows", arg, 2, 20000, &o->rows);
    case 'n': return rl_cli_int(NULL, "--frames", arg, 1, 100000000, &o->frames);
    case 's': return rl_cli_ulong(NULL, "--seed", arg, 0, 4294967295ul, &o->seed);
    case 'C': o->cmp = arg; return 1;
    case 'N': return rl_cli_double(NULL, "--noise", arg, 0, 100, &o->noise);
    case 'K': return rl_cli_double(NULL, "--rock", arg, 0, RL_POSE_ROCKING_MAX, &o->rock);
    case 'a': o->camera = arg; return 1;
    default: return 0;
    }
}

/* The command line into o: -1 to go on, or the exit code (0 after --help). */
static int synth_args(int argc, char **argv, synth_opts *o)
{
    static const struct option opts[] = {
        {"out", required_argument, 0, 'o'}, {"cols", required_argument, 0, 'c'},
        {"rows", required_argument, 0, 'r'}, {"frames", required_argument, 0, 'n'},
        {"seed", required_argument, 0, 's'}, {"compare", required_argument, 0, 'C'},
        {"noise", required_argument, 0, 'N'}, {"rock", required_argument, 0, 'K'},
        {"camera", required_argument, 0, 'a'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    int c;
    synth_opts_defaults(o);
    while ((c = getopt_long(argc, argv, "h", opts, NULL)) != -1) {
        if (c == 'h') {
            puts("usage: ringloc-survey-synth --camera CAM.yaml --out DIR [--cols 50] [--rows 40] [--frames 20000]\n"
                 "                            [--seed 1] [--noise 0.1] [--rock 0.01]\n"
                 "       ringloc-survey-synth --compare TRUTH.yaml SURVEY.yaml");
            return 0;
        }
        if (!synth_option(c, optarg, o))
            return 2;
    }
    return -1;
}

/* The site: a grid PITCH apart, each landmark up to 15 cm off it, ids
 * 1..60 repeating, 61 (the origin) and 62 (the axis) once. Its count. */
static int make_site(const synth_opts *o, mark *site)
{
    int i, j, n = 0;
    rng ^= o->seed * 0x2545F4914F6CDD1Dull;
    for (j = 0; j < o->rows; j++)
        for (i = 0; i < o->cols; i++) {
            double r = 0.15 * sqrt(urand()), a = 2 * M_PI * urand();
            mark *m = &site[n++];
            m->x = (i + 0.5) * PITCH + r * cos(a);
            m->y = (j + 0.5) * PITCH + r * sin(a);
            m->id = (int)((unsigned)(i * 7 + j * 23) % 60u) + 1;
        }
    site[(o->rows / 2) * o->cols + 1].id = 61;           /* the origin, near the middle of the left side */
    site[(o->rows / 2) * o->cols + o->cols - 2].id = 62; /* the axis, across the site */
    return n;
}

/* camera.yaml, robot.yaml and the site's truth, map_true.yaml, into out. */
static int write_site(const char *out, const rl_calib *cam, const rl_mount *mount, const mark *site, int n)
{
    rl_family fam = {6};
    rl_outfile o;
    char path[1024], err[512];
    int i;
    snprintf(path, sizeof path, "%s/camera.yaml", out);
    if (rl_calibfile_save(path, cam, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    snprintf(path, sizeof path, "%s/robot.yaml", out);
    if (rl_robotfile_save(path, mount, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    snprintf(path, sizeof path, "%s/map_true.yaml", out);
    if (rl_outfile_open(&o, path, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    rl_mapfile_put_header(o.f, &fam, 0.21, HEIGHT);
    for (i = 0; i < n; i++) {
        rl_map_landmark lm = {site[i].id, site[i].x, site[i].y, 0, 0, 0};
        rl_mapfile_put_landmark(o.f, &lm);
    }
    if (rl_outfile_commit(&o, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    return 0;
}

/* Frame k's robot pose (x, y, yaw, roll, pitch): back and forth over every
 * row, weaving, rocking. */
static void drive_pose(const synth_opts *o, int k, double *q)
{
    double row_len = (o->cols - 1) * PITCH, L = o->rows * row_len + (o->rows - 1) * PITCH;
    double p = L * k / (o->frames > 1 ? o->frames - 1 : 1);
    int r = (int)(p / (row_len + PITCH));
    double along = p - r * (row_len + PITCH), w = 0.4 * sin(k * 0.05);
    if (r >= o->rows)
        r = o->rows - 1, along = row_len;
    if (along < row_len) {
        q[0] = 0.5 * PITCH + (r % 2 ? row_len - along : along);
        q[1] = (r + 0.5) * PITCH;
        q[2] = (r % 2 ? M_PI : 0) + w;
    } else {
        q[0] = 0.5 * PITCH + (r % 2 ? 0 : row_len);
        q[1] = (r + 0.5) * PITCH + (along - row_len);
        q[2] = M_PI / 2 + w;
    }
    q[3] = o->rock * nrand();
    q[4] = o->rock * nrand();
}

/* What the recognizer measures of the landmark at m seen by the camera at
 * C turned by Rc: the centre and mean radius of its edge as the lens
 * draws it. */
static void landmark_in_image(const rl_calib *cam, const double *Rc, const double *C, const mark *m, double *u,
                              double *v, double *rad)
{
    double su = 0, sv = 0, pu[32], pv[32];
    int a;
    for (a = 0; a < 32; a++) {
        double X = m->x + 0.105 * cos(a * M_PI / 16), Y = m->y + 0.105 * sin(a * M_PI / 16);
        double dx = X - C[0], dy = Y - C[1], dz = HEIGHT - C[2];
        double fw = Rc[0] * dx + Rc[3] * dy + Rc[6] * dz, lf = Rc[1] * dx + Rc[4] * dy + Rc[7] * dz,
               up = Rc[2] * dx + Rc[5] * dy + Rc[8] * dz;
        rl_calib_project(cam, lf / up, -fw / up, &pu[a], &pv[a]);
        su += pu[a];
        sv += pv[a];
    }
    *u = su / 32;
    *v = sv / 32;
    for (a = 0, *rad = 0; a < 32; a++)
        *rad += hypot(pu[a] - *u, pv[a] - *v) / 32;
}

/* Frame k as a detect JSON line: the landmarks in view, with noise; the
 * border cuts those that reach it. */
static void write_frame(FILE *f, const synth_opts *o, const rl_calib *cam, const rl_pose_model *md,
                        const mark *site, int n, int k)
{
    double q[5], Rc[9], C[3];
    int i, first = 1;
    drive_pose(o, k, q);
    rl_pose_fit_camera(md, q, Rc, C);
    fprintf(f, "{\"image\": \"synth_%05d\", \"width\": %d, \"height\": %d, \"landmarks\": [", k, cam->width,
            cam->height);
    for (i = 0; i < n; i++) {
        double xn, yn, u, v, rad;
        if (fabs(site[i].x - C[0]) > 2.5 || fabs(site[i].y - C[1]) > 2.5 ||
            !rl_pose_fit_predict(md, Rc, C, site[i].x, site[i].y, HEIGHT, &xn, &yn) || fabs(xn) > 1 || fabs(yn) > 1)
            continue;
        landmark_in_image(cam, Rc, C, &site[i], &u, &v, &rad);
        if (u < -rad * 0.5 || v < -rad * 0.5 || u > cam->width - 1 + rad * 0.5 || v > cam->height - 1 + rad * 0.5)
            continue;
        fprintf(f, "%s{\"id\": %d, \"u\": %.2f, \"v\": %.2f, \"radius\": %.2f, \"complete\": %s}", first ? "" : ", ",
                site[i].id, u + o->noise * nrand(), v + o->noise * nrand(), rad + o->noise * nrand(),
                u - rad >= 0 && v - rad >= 0 && u + rad <= cam->width - 1 && v + rad <= cam->height - 1 ? "true"
                                                                                                      : "false");
        first = 0;
    }
    fprintf(f, "]}\n");
}

/* The drive's frames, detect.jsonl, into out. */
static int write_drive(const synth_opts *o, const rl_calib *cam, const rl_mount *mount, const mark *site, int n)
{
    rl_pose_model md;
    rl_outfile of;
    char path[1024], err[512];
    int k;
    snprintf(path, sizeof path, "%s/detect.jsonl", o->out);
    if (rl_outfile_open(&of, path, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    rl_pose_fit_model(&md, mount, HEIGHT, 0.105);
    for (k = 0; k < o->frames; k++)
        write_frame(of.f, o, cam, &md, site, n, k);
    if (rl_outfile_commit(&of, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    return 0;
}

int main(int argc, char **argv)
{
    static synth_opts o;
    static mark site[20000];
    static rl_site cam_site;
    rl_site_files files;
    rl_mount mount;
    char err[768];
    int n, r;

    rl_cli_start("ringloc-survey-synth");
    if ((r = synth_args(argc, argv, &o)) >= 0)
        return r;
    if (o.cmp)
        return optind < argc ? compare(o.cmp, argv[optind]) : (fprintf(stderr, "--compare TRUTH SURVEY\n"), 2);
    if (!o.out || !o.camera || o.cols * o.rows > 20000) {
        fprintf(stderr, "ringloc-survey-synth: --camera FILE, --out DIR, and at most 20000 landmarks (see --help)\n");
        return 2;
    }
    rl_site_files_init(&files);
    files.calibration = o.camera;
    if (rl_site_load(&cam_site, &files, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    mkdir(o.out, 0777);
    n = make_site(&o, site);
    rl_mount_defaults(&mount, 0.88);
    mount.x = 0.1;
    mount.rocking = o.rock; /* the truth, as the renderer writes it */
    if ((r = write_site(o.out, &cam_site.calib, &mount, site, n)) != 0)
        return r;
    return write_drive(&o, &cam_site.calib, &mount, site, n);
}
