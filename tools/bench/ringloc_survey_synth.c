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
#include "rl_cli.h"
#include "rl_calibfile.h"
#include "rl_mapfile.h"
#include "rl_outfile.h"
#include "rl_pose_fit.h"
#include "rl_robotfile.h"

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

int main(int argc, char **argv)
{
    static const struct option opts[] = {
        {"out", required_argument, 0, 'o'}, {"cols", required_argument, 0, 'c'},
        {"rows", required_argument, 0, 'r'}, {"frames", required_argument, 0, 'n'},
        {"seed", required_argument, 0, 's'}, {"compare", required_argument, 0, 'C'},
        {"noise", required_argument, 0, 'N'}, {"rock", required_argument, 0, 'K'},
        {"camera", required_argument, 0, 'a'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    const char *out = NULL, *cmp = NULL, *cam_path = NULL;
    int cols = 50, rows = 40, frames = 20000, c, i, j, k;
    unsigned long seed = 1;
    double noise = 0.1, rock = 0.01;
    static mark site[20000];
    int n = 0;
    rl_calib cam;
    rl_mount mount;
    rl_outfile o;
    rl_family fam = {6};
    rl_pose_model md;
    char path[1024], err[512];
    FILE *f;
    double row_len, L;

    rl_cli_start("ringloc-survey-synth");
    while ((c = getopt_long(argc, argv, "h", opts, NULL)) != -1) {
        switch (c) {
        case 'o': out = optarg; break;
        case 'c': cols = atoi(optarg); break;
        case 'r': rows = atoi(optarg); break;
        case 'n': frames = atoi(optarg); break;
        case 's': seed = strtoul(optarg, NULL, 10); break;
        case 'C': cmp = optarg; break;
        case 'N': noise = atof(optarg); break;
        case 'K': rock = atof(optarg); break;
        case 'a': cam_path = optarg; break;
        case 'h':
            puts("usage: ringloc-survey-synth --camera CAM.yaml --out DIR [--cols 50] [--rows 40] [--frames 20000]\n"
                 "                            [--seed 1] [--noise 0.1] [--rock 0.01]\n"
                 "       ringloc-survey-synth --compare TRUTH.yaml SURVEY.yaml");
            return 0;
        default: return 2;
        }
    }
    if (cmp)
        return optind < argc ? compare(cmp, argv[optind]) : (fprintf(stderr, "--compare TRUTH SURVEY\n"), 2);
    if (!out || !cam_path || cols < 2 || rows < 2 || cols * rows > 20000 || frames < 1) {
        fprintf(stderr, "ringloc-survey-synth: --camera FILE, --out DIR, and at most 20000 landmarks (see --help)\n");
        return 2;
    }
    if (rl_calibfile_load(cam_path, &cam, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-survey-synth: %s\n", err), 1;
    mkdir(out, 0777);
    rng ^= seed * 0x2545F4914F6CDD1Dull;
    for (j = 0; j < rows; j++)
        for (i = 0; i < cols; i++) {
            double r = 0.15 * sqrt(urand()), a = 2 * M_PI * urand();
            mark *m = &site[n++];
            m->x = (i + 0.5) * PITCH + r * cos(a);
            m->y = (j + 0.5) * PITCH + r * sin(a);
            m->id = (int)((unsigned)(i * 7 + j * 23) % 60u) + 1;
        }
    site[(rows / 2) * cols + 1].id = 61;        /* the origin, near the middle of the left side */
    site[(rows / 2) * cols + cols - 2].id = 62; /* the axis, across the site */
    rl_mount_defaults(&mount, 0.88);
    mount.x = 0.1;
    snprintf(path, sizeof path, "%s/camera.yaml", out);
    if (rl_calibfile_save(path, &cam, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-survey-synth: %s\n", err), 1;
    snprintf(path, sizeof path, "%s/robot.yaml", out);
    if (rl_robotfile_save(path, &mount, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-survey-synth: %s\n", err), 1;
    snprintf(path, sizeof path, "%s/map_true.yaml", out);
    if (rl_outfile_open(&o, path, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-survey-synth: %s\n", err), 1;
    f = o.f;
    rl_mapfile_put_header(f, &fam, 0.21, HEIGHT);
    for (i = 0; i < n; i++) {
        rl_map_landmark lm = {site[i].id, site[i].x, site[i].y, 0, 0};
        rl_mapfile_put_landmark(f, &lm);
    }
    if (rl_outfile_commit(&o, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-survey-synth: %s\n", err), 1;
    snprintf(path, sizeof path, "%s/detect.jsonl", out);
    if (rl_outfile_open(&o, path, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-survey-synth: %s\n", err), 1;
    f = o.f;
    rl_pose_fit_model(&md, &mount, HEIGHT, 0.105);
    row_len = (cols - 1) * PITCH;
    L = rows * row_len + (rows - 1) * PITCH;
    for (k = 0; k < frames; k++) {
        double p = L * k / (frames > 1 ? frames - 1 : 1), q[5], Rc[9], C[3];
        int r = (int)(p / (row_len + PITCH)), first = 1;
        double along = p - r * (row_len + PITCH), w = 0.4 * sin(k * 0.05);
        if (r >= rows)
            r = rows - 1, along = row_len;
        if (along < row_len) {
            q[0] = 0.5 * PITCH + (r % 2 ? row_len - along : along);
            q[1] = (r + 0.5) * PITCH;
            q[2] = (r % 2 ? M_PI : 0) + w;
        } else {
            q[0] = 0.5 * PITCH + (r % 2 ? 0 : row_len);
            q[1] = (r + 0.5) * PITCH + (along - row_len);
            q[2] = M_PI / 2 + w;
        }
        q[3] = rock * nrand();
        q[4] = rock * nrand();
        rl_pose_fit_camera(&md, q, Rc, C);
        fprintf(f, "{\"image\": \"synth_%05d\", \"width\": %d, \"height\": %d, \"landmarks\": [", k, cam.width,
                cam.height);
        for (i = 0; i < n; i++) {
            double xn, yn, u, v, rad;
            if (fabs(site[i].x - C[0]) > 2.5 || fabs(site[i].y - C[1]) > 2.5 ||
                !rl_pose_fit_predict(&md, Rc, C, site[i].x, site[i].y, &xn, &yn) || fabs(xn) > 1 || fabs(yn) > 1)
                continue;
            /* what the recognizer measures: the centre and mean radius of
             * the landmark's edge as the lens draws it */
            {
                double su = 0, sv = 0, pu[32], pv[32];
                int a;
                for (a = 0; a < 32; a++) {
                    double X = site[i].x + 0.105 * cos(a * M_PI / 16), Y = site[i].y + 0.105 * sin(a * M_PI / 16);
                    double dx = X - C[0], dy = Y - C[1], dz = HEIGHT - C[2];
                    double fw = Rc[0] * dx + Rc[3] * dy + Rc[6] * dz, lf = Rc[1] * dx + Rc[4] * dy + Rc[7] * dz,
                           up = Rc[2] * dx + Rc[5] * dy + Rc[8] * dz;
                    rl_calib_project(&cam, lf / up, -fw / up, &pu[a], &pv[a]);
                    su += pu[a];
                    sv += pv[a];
                }
                u = su / 32;
                v = sv / 32;
                for (a = 0, rad = 0; a < 32; a++)
                    rad += hypot(pu[a] - u, pv[a] - v) / 32;
            }
            if (u < -rad * 0.5 || v < -rad * 0.5 || u > cam.width - 1 + rad * 0.5 || v > cam.height - 1 + rad * 0.5)
                continue;
            fprintf(f, "%s{\"id\": %d, \"u\": %.2f, \"v\": %.2f, \"radius\": %.2f, \"complete\": %s}", first ? "" : ", ",
                    site[i].id, u + noise * nrand(), v + noise * nrand(), rad + noise * nrand(),
                    u - rad >= 0 && v - rad >= 0 && u + rad <= cam.width - 1 && v + rad <= cam.height - 1 ? "true"
                                                                                                      : "false");
            first = 0;
        }
        fprintf(f, "]}\n");
    }
    if (rl_outfile_commit(&o, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-survey-synth: %s\n", err), 1;
    return 0;
}
