/* ringloc-render: fixtures that know the truth.
 *
 * Ray-casts an upward-looking camera (pinhole + plumb_bob, the core's own
 * rl_calib model) onto a ceiling plane: tiles and T-bars, light fixtures
 * that saturate and wash out their surroundings, clutter (smoke detectors,
 * downlights, sprinklers, vents, round speaker grilles, boxes, exit signs),
 * landmarks printed per docs/landmark-spec.md on paper, and camera
 * effects (vignetting, exposure, blur, motion blur, noise). Writes each
 * frame as PNG with a ground-truth YAML: the camera and robot pose and,
 * for every landmark, id, projected centre, radius, visible fraction and
 * gap to the nearest light. With --twin it renders the same scene with
 * AprilTag 36h11 tags of the same size at the same places.
 *
 * This file is the command line and the frame loop; the jobs are modules:
 * render_random (the random numbers), render_set (each set's scenes),
 * render_look (their looks), render_path and render_tour (the robot's
 * poses), render_stream (poses a simulator streams in), render_camera (its
 * pose and the frame), render_ceiling (what the
 * ceiling radiates), render_sensor (light to 8 bits), render_truth (the
 * YAML beside each frame).
 *
 * Host tool: allocates freely, uses libapriltag for the tags' bit patterns.
 */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "render_camera.h"
#include "render_ceiling.h"
#include "render_isp.h"
#include "render_look.h"
#include "render_path.h"
#include "render_random.h"
#include "render_set.h"
#include "render_stream.h"
#include "render_tour.h"
#include "render_truth.h"
#include "rl_calibfile.h"
#include "rl_cli.h"
#include "rl_mapfile.h"
#include "rl_png.h"
#include "rl_print.h"
#include "rl_robotfile.h"
#include "rl_site.h"

static const char *help =
    "usage: ringloc-render --out DIR (--set NAME --count N | --path KIND --frames N)\n"
    "                      [--seed S] [--size 640x480] [--camera CAM.yaml] [--twin]\n"
    "                      [--mount X,Y,YAW] [--write-map FILE] [--write-camera FILE]\n"
    "                      [--write-robot FILE] [--rock SIGMA] [--site grid|irregular]\n"
    "                      [--rolling MS[,SPEED[,TURN]] [--interval S]]\n"
    "                      [--move ID,DX,DY] [--lower ID,M]... [--look SET] [--sheet PAPER]\n"
    "                      [--isp STAGES]\n"
    "       ringloc-render --out DIR --path stream --site-map FILE [--newest] [...]\n\n"
    "Render ceiling fixtures with ground truth (NAME_NNN.png + NAME_NNN.yaml).\n"
    "  --set NAME      clean, cluttered, glare, border, clutter_only, dim, blur, motion,\n"
    "                  illum (vignetting, fall-off, a shadow, grey ink), degraded (blur\n"
    "                  1.1 px, 4 px motion, 0.35 exposure, 3 DN noise), lens (a wide-angle\n"
    "                  lens's barrel distortion, k1 -0.22: landmarks at the border as\n"
    "                  ellipses; replaces the camera's distortion), moving (a robot\n"
    "                  moving in dim light: blur, motion of any direction and a turn,\n"
    "                  photon and read noise, sheets of every paper on ceilings darker\n"
    "                  and lighter than paper), heldout (the same kind of frames by\n"
    "                  other optics, tone curve and raw depth, letter sheets: nothing\n"
    "                  is tuned on it), repeats (four ids, each two or three times a\n"
    "                  frame):\n"
    "                  random scenes around the paper's set-up (ring5, 0.21 m landmarks,\n"
    "                  1.87 m from camera to ceiling, 0.61 m tiles)\n"
    "  --path KIND     straight, rect, circle or survey (back and forth over the whole\n"
    "                  site, weaving): frames along a robot path under a fixed site of\n"
    "                  6x5 landmarks 0.61 m apart (the map of --write-map)\n"
    "  --site LAYOUT   grid (default) or irregular: each landmark up to 15 cm off the\n"
    "                  grid, the layout turned 5 degrees (a site taped up by hand)\n"
    "  --move ID,DX,DY the site's landmark ID moved by (DX, DY) m\n"
    "  --lower ID,M    landmarks of id ID hang M m below the ceiling (a beam, a lower\n"
    "                  panel; --write-map gives their z); repeat for more\n"
    "  --twin          also render each frame with AprilTag 36h11 tags of the same size\n"
    "                  at the same places (NAME_NNN_tag.png)\n"
    "  --camera FILE   calibration to render with (default: 640x480, 70 deg, mild\n"
    "                  barrel distortion; --size scales it)\n"
    "  --mount X,Y,YAW[,ROLL,PITCH]  camera offset in the robot frame, and its\n"
    "                  tilt (radians, roll about the robot's x, pitch about its y;\n"
    "                  default 0,0,0,0,0)\n"
    "  --rock SIGMA    the robot rocks: a random tilt per frame and axis (radians)\n"
    "  --rolling MS[,SPEED[,TURN]]  a rolling shutter: the rows read top to bottom in\n"
    "                  MS milliseconds while the robot drives forward at SPEED m/s and\n"
    "                  turns at TURN rad/s (left positive), or, with MS alone, moves\n"
    "                  along the --path as it does with frames --interval S seconds\n"
    "                  apart; the truth is the middle row's pose\n"
    "  --look SET      with --path: the frames look as that set's do (degraded, dim, ...)\n"
    "  --sheet PAPER   the landmarks' sheets: letter, a4, a3, tabloid or WxH in mm\n"
    "                  (default: as wide as the landmark, A4's proportions; the\n"
    "                  moving set draws letter, A4, A3 or that, heldout letter)\n"
    "  --isp STAGES    a camera's processing after its tone curve, on grey levels, in\n"
    "                  the order given (comma-separated): blur:S (Gaussian, px),\n"
    "                  scale:F (down by F and back up), sharpen:A (unsharp mask),\n"
    "                  jpeg:Q (quality), scurve:K (S-curve, 0..1), ae:STOPS (auto\n"
    "                  exposure, another each frame); e.g. scale:2,sharpen:0.8,jpeg:75\n"
    "                  (the truth is the frame's geometry: unchanged)\n"
    ;
/* the rest (a C99 string literal holds 4095 characters) */
static const char *help_sites =
    "  --site-map FILE a large site's map (ringloc plan --area; any size, ids repeated):\n"
    "                  frames under it with --path random (poses uniform over the\n"
    "                  landmarks' extent, any heading), --path tour (a drive over the\n"
    "                  site, 0.1 m a frame, carried elsewhere halfway), --path edge (a\n"
    "                  drive past the lower edge and along it) or --path corner (0.08 m\n"
    "                  a frame, round the lower right corner); its family,\n"
    "                  diameter and ceiling height\n"
    "  --path stream   follow a simulated robot: poses in on standard input, one line\n"
    "                  each, 'T_US X Y YAW' (the pose's time in microseconds; m, m, rad\n"
    "                  in the map's frame); each drawn at once to DIR/stream_NNNNNN.png\n"
    "                  (+ .yaml truth) and announced on standard output as 'T_US\n"
    "                  stream_NNNNNN.png' when written: the lines the firmware's sim\n"
    "                  camera reads (a pipe in DIR), each frame stamped with its pose's\n"
    "                  time. One frame per pose, in lockstep; a slow machine slows the\n"
    "                  stream, or with --newest draws only the latest pose waiting\n"
    "                  (the others skipped and counted on standard error at the end)\n";

/* What the command line asks for. */
typedef struct {
    const char *out;                /* --out DIR */
    const char *set, *path;         /* --set NAME or --path KIND */
    int count;                      /* --count, --frames (default 10) */
    unsigned long seed;             /* default 1 */
    int w, h;                       /* --size (default 640x480), without --camera */
    const char *camera;             /* --camera (NULL: render_camera_default) */
    int twin;                       /* --twin */
    render_mount mount;             /* --mount (default 0,0,0,0,0) */
    const char *map_out, *cam_out, *robot_out; /* --write-map, --write-camera, --write-robot */
    double rock;                    /* --rock (0: none) */
    const char *look;               /* --look SET (NULL: the drive's own) */
    int irregular;                  /* --site irregular */
    int move_id;                    /* --move ID,DX,DY (0: none) */
    double mdx, mdy;
    const char *site_map;           /* --site-map FILE */
    rl_paper sheet;                 /* --sheet (name NULL: the set's) */
    int newest;                     /* --newest: a stream's latest pose only */
    render_isp isp;                 /* --isp (n 0: none) */
    double readout, speed, turn;    /* --rolling MS[,SPEED[,TURN]] (readout in s; 0: global shutter) */
    int rolling_path;               /* --rolling MS alone: the motion the path has */
    double interval;                /* --interval S: the frames' spacing in time (--rolling MS) */
    double lower[RL_MAX_IDS];       /* --lower ID,M: the fixed site's id ID hangs M below the ceiling */
    int lowered;                    /* how many --lower */
} render_opts;

static void render_opts_defaults(render_opts *o)
{
    memset(o, 0, sizeof *o);
    o->count = 10;
    o->seed = 1;
    o->w = 640;
    o->h = 480;
}

/* --size WxH, each side 16 .. 4096 */
static int parse_size(const char *arg, render_opts *o)
{
    if (!rl_cli_size(NULL, "--size", arg, 4096, &o->w, &o->h))
        return 0;
    if (o->w < 16 || o->h < 16)
        return !rl_cli_fail(NULL, 2, "--size: '%s' is not a size like 640x480", arg);
    return 1;
}

/* --mount X,Y,YAW[,ROLL,PITCH] */
static int parse_mount(const char *arg, render_mount *m)
{
    double v[5] = {0, 0, 0, 0, 0};
    int n;
    if (!rl_cli_doubles(NULL, "--mount", arg, "X,Y,YAW[,ROLL,PITCH]", v, 5, &n))
        return 0;
    if (n != 3 && n != 5)
        return !rl_cli_fail(NULL, 2, "--mount: '%s' is not X,Y,YAW[,ROLL,PITCH]", arg);
    m->x = v[0];
    m->y = v[1];
    m->yaw = v[2];
    m->roll = v[3];
    m->pitch = v[4];
    return 1;
}

/* --move ID,DX,DY: an id 1..30, up to 1 m */
static int parse_move(const char *arg, render_opts *o)
{
    static const char *form = "ID,DX,DY (an id 1..30, up to 1 m)";
    double v[3];
    int n;
    if (!rl_cli_doubles(NULL, "--move", arg, form, v, 3, &n))
        return 0;
    if (n != 3 || v[0] != floor(v[0]) || v[0] < 1 || v[0] > 30 || !(fabs(v[1]) < 1 && fabs(v[2]) < 1))
        return !rl_cli_fail(NULL, 2, "--move: '%s' is not %s", arg, form);
    o->move_id = (int)v[0];
    o->mdx = v[1];
    o->mdy = v[2];
    return 1;
}

/* --rolling MS[,SPEED[,TURN]] */
static int parse_rolling(const char *arg, render_opts *o)
{
    static const char *form = "MS[,SPEED[,TURN]] (readout 0..100 ms, up to 5 m/s and 10 rad/s)";
    double v[3] = {0, 0, 0};
    int n;
    if (!rl_cli_doubles(NULL, "--rolling", arg, form, v, 3, &n))
        return 0;
    if (n < 1 || !(v[0] >= 0 && v[0] <= 100) || !(fabs(v[1]) <= 5) || !(fabs(v[2]) <= 10))
        return !rl_cli_fail(NULL, 2, "--rolling: '%s' is not %s", arg, form);
    o->readout = v[0] / 1000.0;
    o->speed = v[1];
    o->turn = v[2];
    o->rolling_path = n == 1;
    return 1;
}

/* --lower ID,M: an id 1..30, 0 < M <= 1.5 m (the camera 1.87 m below the
 * ceiling) */
static int parse_lower(const char *arg, render_opts *o)
{
    static const char *form = "ID,M (an id 1..30, hanging 0 .. 1.5 m below the ceiling)";
    double v[2];
    int n;
    if (!rl_cli_doubles(NULL, "--lower", arg, form, v, 2, &n))
        return 0;
    if (n != 2 || v[0] != floor(v[0]) || v[0] < 1 || v[0] > 30 || !(v[1] > 0 && v[1] <= 1.5))
        return !rl_cli_fail(NULL, 2, "--lower: '%s' is not %s", arg, form);
    o->lower[(int)v[0]] = v[1];
    o->lowered++;
    return 1;
}

/* One option into o: 1, or 0 with the error line printed. */
static int render_option(int c, const char *arg, render_opts *o)
{
    switch (c) {
    case 'o': o->out = arg; return 1;
    case 's': o->set = arg; return 1;
    case 'p': o->path = arg; return 1;
    case 'n': return rl_cli_int(NULL, "--count", arg, 0, 1000000, &o->count);
    case 'N': return rl_cli_int(NULL, "--frames", arg, 0, 1000000, &o->count);
    case 'S': return rl_cli_ulong(NULL, "--seed", arg, 0, 4294967295ul, &o->seed);
    case 'z': return parse_size(arg, o);
    case 'c': o->camera = arg; return 1;
    case 't': o->twin = 1; return 1;
    case 'm': return parse_mount(arg, &o->mount);
    case 'l': o->look = arg; return 1;
    case 'G':
        if (strcmp(arg, "grid") != 0 && strcmp(arg, "irregular") != 0)
            return !rl_cli_fail(NULL, 2, "--site: '%s' is not grid or irregular", arg);
        o->irregular = strcmp(arg, "irregular") == 0;
        return 1;
    case 'V': return parse_move(arg, o);
    case 'D': return parse_lower(arg, o);
    case 'L': return parse_rolling(arg, o);
    case 'T': return rl_cli_double(NULL, "--interval", arg, 0.001, 3600, &o->interval);
    case 'r': return rl_cli_double(NULL, "--rock", arg, 0, RL_POSE_ROCKING_MAX, &o->rock);
    case 'E': o->site_map = arg; return 1;
    case 'P':
        if (!rl_paper_parse(arg, &o->sheet))
            return !rl_cli_fail(NULL, 2, "--sheet: '%s' is not %s or WxH in mm", arg, rl_paper_names());
        return 1;
    case 'W': o->newest = 1; return 1;
    case 'I': {
        char err[256];
        if (render_isp_parse(arg, &o->isp, err, sizeof err) != 0)
            return !rl_cli_fail(NULL, 2, "%s", err);
        return 1;
    }
    case 'M': o->map_out = arg; return 1;
    case 'C': o->cam_out = arg; return 1;
    case 'R': o->robot_out = arg; return 1;
    default: return 0; /* rl_cli_getopt said why */
    }
}

/* The command line into o: -1 to go on, or the exit code (0 after --help). */
static int render_args(int argc, char **argv, render_opts *o)
{
    static const struct option opts[] = {
        {"out", required_argument, 0, 'o'}, {"set", required_argument, 0, 's'},
        {"count", required_argument, 0, 'n'}, {"path", required_argument, 0, 'p'},
        {"frames", required_argument, 0, 'N'}, {"seed", required_argument, 0, 'S'},
        {"size", required_argument, 0, 'z'}, {"camera", required_argument, 0, 'c'},
        {"twin", no_argument, 0, 't'}, {"mount", required_argument, 0, 'm'},
        {"write-map", required_argument, 0, 'M'}, {"write-camera", required_argument, 0, 'C'},
        {"write-robot", required_argument, 0, 'R'}, {"rock", required_argument, 0, 'r'},
        {"look", required_argument, 0, 'l'}, {"site", required_argument, 0, 'G'},
        {"move", required_argument, 0, 'V'}, {"site-map", required_argument, 0, 'E'},
        {"sheet", required_argument, 0, 'P'}, {"newest", no_argument, 0, 'W'},
        {"isp", required_argument, 0, 'I'}, {"rolling", required_argument, 0, 'L'},
        {"interval", required_argument, 0, 'T'}, {"lower", required_argument, 0, 'D'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    int c;
    render_opts_defaults(o);
    while ((c = rl_cli_getopt(NULL, argc, argv, opts)) != -1) {
        if (c == 'h') {
            fputs(help, stdout);
            fputs(help_sites, stdout);
            return 0;
        }
        if (!render_option(c, optarg, o))
            return 2;
    }
    return -1;
}

/* mkdir -p */
static int mkdir_p(const char *dir)
{
    char buf[1024];
    size_t i, n = strlen(dir);
    if (n >= sizeof buf)
        return -1;
    memcpy(buf, dir, n + 1);
    for (i = 1; i <= n; i++)
        if (buf[i] == '/' || buf[i] == '\0') {
            char c = buf[i];
            buf[i] = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return -1;
            buf[i] = c;
        }
    return 0;
}

/* The camera (--camera, or the default at --size) and the large site's
 * map (--site-map) through rl_site. 0, or the exit code. */
static int load_site(const render_opts *o, rl_site *site, rl_calib *cam)
{
    rl_site_files files;
    char err[768];
    rl_site_files_init(&files);
    files.calibration = o->camera;
    files.map = o->site_map;
    if (rl_site_load(site, &files, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    if (site->has_calib)
        *cam = site->calib;
    else
        render_camera_default(cam, o->w, o->h);
    return 0;
}

/* The scene every frame starts from: the paper's set-up (ring5, 0.21 m
 * landmarks, 1.87 m from camera to ceiling, 0.61 m tiles), or the large
 * site's family, diameter and ceiling. 0, or the exit code. */
static int scene_setup(const render_opts *o, const rl_site *site, const rl_calib *cam, render_scene *s)
{
    int i;
    memset(s, 0, sizeof *s);
    s->cam = *cam;
    s->fam.bits = 5;
    s->diameter = 0.21;
    s->distance = 1.87;
    s->ceiling_height = 2.75;
    s->cam_z = s->ceiling_height - s->distance;
    s->tile = 0.61;
    render_set_site_layout(s->tile, o->irregular, o->move_id, o->mdx, o->mdy);
    memcpy(s->lower, o->lower, sizeof s->lower);
    if (!site->has_map)
        return 0;
    if (o->lowered)
        return rl_cli_fail(NULL, 2, "--lower is for the fixed site: a --site-map gives each landmark's own z");
    if (site->map.count < 2)
        return rl_cli_fail(NULL, 1, "%s: a site needs two landmarks or more", o->site_map);
    s->fam = site->map.family;
    s->diameter = site->map.diameter;
    s->ceiling_height = site->map.ceiling_height;
    s->distance = s->ceiling_height - s->cam_z;
    if (!(s->distance > 0.3))
        return rl_cli_fail(NULL, 1, "%s: ceiling_height %.3f m is not above the camera (%.2f m)", o->site_map,
                           s->ceiling_height, s->cam_z);
    for (i = 0; i < site->map.count; i++)
        if (site->map.lm[i].z > 0 && !(site->map.lm[i].z - s->cam_z > 0.3 && site->map.lm[i].z <= s->ceiling_height))
            return rl_cli_fail(NULL, 1, "%s: landmarks[%d].z %.3f m (id %d) is not between 0.3 m above the camera "
                               "(%.2f m) and the ceiling (%.3f m): the renderer hangs landmarks below it only",
                               o->site_map, i, site->map.lm[i].z, site->map.lm[i].id, s->cam_z, s->ceiling_height);
    render_set_use_map(&site->map);
    return 0;
}

/* --write-camera, --write-robot, --write-map (the large site's map, or
 * the fixed site's). 0, or the exit code. */
static int write_site(const render_opts *o, const rl_site *site, const render_scene *s)
{
    static rl_map map;
    char err[768];
    if (o->cam_out && rl_calibfile_save(o->cam_out, &s->cam, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    if (o->robot_out) {
        rl_mount mnt;
        mnt.x = o->mount.x;
        mnt.y = o->mount.y;
        mnt.yaw = o->mount.yaw;
        mnt.roll = o->mount.roll;
        mnt.pitch = o->mount.pitch;
        mnt.z = s->cam_z;
        mnt.rocking = o->rock; /* the truth: --rock's sigma */
        if (rl_robotfile_save(o->robot_out, &mnt, err, sizeof err) != RL_OK)
            return rl_cli_fail(NULL, 1, "%s", err);
    }
    if (o->map_out == NULL)
        return 0;
    if (!site->has_map)
        render_set_site_map(s, &map);
    if (rl_mapfile_save(o->map_out, site->has_map ? &site->map : &map, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, 1, "%s", err);
    return 0;
}

/* The landmarks' extent: where a robot under a large site may be. */
static void map_area(const rl_map *map, render_area *area)
{
    int i;
    area->x0 = area->y0 = HUGE_VAL;
    area->x1 = area->y1 = -HUGE_VAL;
    for (i = 0; i < map->count; i++) {
        area->x0 = fmin(area->x0, map->lm[i].x);
        area->y0 = fmin(area->y0, map->lm[i].y);
        area->x1 = fmax(area->x1, map->lm[i].x);
        area->y1 = fmax(area->y1, map->lm[i].y);
    }
}

/* What the frames are.  With --set: random robot poses.  With --path: a
 * drive under the fixed site (render_path), or under a large site's map
 * (random poses, a tour or its edge, into *poses); the looks of a set
 * (--look) or the drive's own. */
typedef struct {
    render_set kind;      /* the set (RENDER_SET_PATH: a drive) */
    render_set look;      /* a drive's looks (RENDER_SET_PATH: its own) */
    render_pose *poses;   /* a large site's drive; NULL: none */
    int stream;           /* --path stream: the pose below, from standard input */
    double q[3];
} render_plan;

/* The frames o asks for into p: 0, or the exit code. */
static int plan_frames(const render_opts *o, const rl_site *site, render_plan *p)
{
    render_area area;
    double x, y, yaw;
    int i;
    p->kind = p->look = RENDER_SET_PATH;
    p->poses = NULL;
    p->stream = 0;
    if ((o->set == NULL) == (o->path == NULL))
        return rl_cli_fail(NULL, 2, "give --set NAME or --path KIND (see --help)");
    if (o->set) {
        if ((i = render_set_by_name(o->set)) < 0)
            return rl_cli_fail(NULL, 2, "--set: unknown set '%s'", o->set);
        p->kind = (render_set)i;
        return o->rolling_path ? rl_cli_fail(NULL, 2, "--rolling MS alone moves along a --path: with --set give "
                                                      "MS,SPEED[,TURN]")
                               : 0;
    }
    if (o->look != NULL) {
        /* a path drive with the looks of a set (not lens: that changes
         * the camera the calibration was written for) */
        if ((i = render_set_by_name(o->look)) < 0 || (render_set)i == RENDER_SET_LENS)
            return rl_cli_fail(NULL, 2, "--look: '%s' is not a set's look (lens excepted)", o->look);
        p->look = (render_set)i;
    }
    if (strcmp(o->path, "stream") == 0) {
        if (!site->has_map)
            return rl_cli_fail(NULL, 2, "--path stream: give the site's map (--site-map FILE)");
        p->stream = 1;
        return o->rolling_path ? rl_cli_fail(NULL, 2, "--rolling MS alone moves along a --path: with a stream give "
                                                      "MS,SPEED[,TURN]")
                               : 0;
    }
    if (!site->has_map) {
        if (render_path_pose(o->path, 0, 2, &x, &y, &yaw) != 0)
            return rl_cli_fail(NULL, 2, "--path: '%s' is not straight, rect, circle or survey", o->path);
        if (o->rolling_path && !(o->interval > 0))
            return rl_cli_fail(NULL, 2, "--rolling MS alone moves along the path: give --interval S");
        return 0;
    }
    if (o->rolling_path)
        return rl_cli_fail(NULL, 2, "--rolling MS alone needs a path of the fixed site (straight, rect, circle, "
                                    "survey): give MS,SPEED[,TURN]");
    if (strcmp(o->path, "random") != 0 && strcmp(o->path, "tour") != 0 && strcmp(o->path, "edge") != 0 &&
        strcmp(o->path, "corner") != 0)
        return rl_cli_fail(NULL, 2, "--path: with --site-map, random, tour, edge or corner ('%s')", o->path);
    map_area(&site->map, &area);
    if ((p->poses = malloc(sizeof *p->poses * (size_t)(o->count > 0 ? o->count : 1))) == NULL)
        return rl_cli_fail(NULL, 1, "out of memory");
    if (strcmp(o->path, "random") == 0)
        render_random_poses(&area, o->seed, o->count, p->poses);
    else if (strcmp(o->path, "edge") == 0)
        render_edge(&area, o->seed, o->count, 0.1, p->poses);
    else if (strcmp(o->path, "corner") == 0)
        render_corner(&area, o->seed, o->count, 0.08, p->poses);
    else
        render_tour(&area, o->seed, o->count, 0.1, p->poses);
    return 0;
}

/* Frame k's robot pose and name (NAME_NNN). */
static void frame_pose(const render_opts *o, const render_plan *p, int k, double *q, char *name, size_t len)
{
    if (p->stream) {
        memcpy(q, p->q, sizeof p->q);
    } else if (p->poses) {
        q[0] = p->poses[k].x;
        q[1] = p->poses[k].y;
        q[2] = p->poses[k].yaw;
    } else if (p->kind == RENDER_SET_PATH) {
        render_path_pose(o->path, k, o->count, &q[0], &q[1], &q[2]);
    } else {
        q[0] = render_random_uniform(2, 8);
        q[1] = render_random_uniform(2, 8);
        q[2] = render_random_uniform(-M_PI, M_PI);
    }
    if (p->stream)
        snprintf(name, len, "stream_%06d", k);
    else
        snprintf(name, len, "%s_%03d", p->kind == RENDER_SET_PATH ? o->path : o->set, k);
}

/* A rolling shutter along the path (--rolling MS --interval S): the
 * camera's travel and turn between the first row's instant and the last's,
 * from the path's poses half the readout before and after frame k. */
static void path_shutter(const render_opts *o, render_scene *s, int k)
{
    double h = 0.5 * o->readout / o->interval, a[3], b[3], ca[2], cb[2];
    int i;
    render_path_pose(o->path, k - h, o->count, &a[0], &a[1], &a[2]);
    render_path_pose(o->path, k + h, o->count, &b[0], &b[1], &b[2]);
    for (i = 0; i < 2; i++) {
        const double *p = i ? b : a;
        double *c = i ? cb : ca;
        c[0] = p[0] + cos(p[2]) * o->mount.x - sin(p[2]) * o->mount.y;
        c[1] = p[1] + sin(p[2]) * o->mount.x + cos(p[2]) * o->mount.y;
    }
    s->shutter_dx = cb[0] - ca[0];
    s->shutter_dy = cb[1] - ca[1];
    s->shutter_turn = atan2(sin(b[2] - a[2]), cos(b[2] - a[2]));
}

/* Frame k: its scene, drawn (and its twin), and its truth. 0, or the
 * exit code. */
static int render_frame(const render_opts *o, const render_plan *p, render_scene *s, int k, uint8_t *px)
{
    rl_image img = rl_image_view(s->cam.width, s->cam.height, s->cam.width, px);
    char name[1024], file[1200], err[1400];
    double q[3], rr, rp;
    int i, pass;
    /* every frame its own stream: it can be rendered alone */
    render_random_seed(0x9E3779B97F4A7C15ull ^ (o->seed * 1000003ull + (uint64_t)k * 7919ull + p->kind * 104729ull));
    for (i = 0; i < 4; i++)
        render_random_next();
    s->n = 0;
    s->twin = 0;
    render_look_apply(s, p->kind == RENDER_SET_PATH ? p->look : p->kind);
    if (o->sheet.name != NULL) {
        s->sheet_w = o->sheet.w_mm / 1000.0;
        s->sheet_h = o->sheet.h_mm / 1000.0;
    }
    frame_pose(o, p, k, q, name, sizeof name);
    /* the camera from the robot's pose, rocking about its footprint on the floor */
    rr = o->rock > 0 ? o->rock * render_random_normal() : 0;
    rp = o->rock > 0 ? o->rock * render_random_normal() : 0;
    render_camera_pose(s, &o->mount, q[0], q[1], q[2], rr, rp);
    if (o->rolling_path)
        path_shutter(o, s, k);
    else
        render_camera_shutter(s, &o->mount, q[2], o->readout, o->speed, o->turn);
    render_set_fill(s, p->kind);
    for (pass = 0; pass <= o->twin; pass++) {
        s->twin = pass;
        if (pass) /* a tag (10 cells, the ring's diameter 8) needs a larger sheet */
            for (i = 0; i < s->n; i++)
                if (s->obj[i].kind == RENDER_OBJ_PAPER)
                    s->obj[i].a *= 1.25, s->obj[i].b *= 1.25;
        if (render_camera_frame(s, px) != 0 ||
            render_isp_apply(&o->isp, px, s->cam.width, s->cam.height, k) != 0)
            return rl_cli_fail(NULL, 1, "out of memory, or JPEG failed (--isp)");
        snprintf(file, sizeof file, "%s/%s%s.png", o->out, name, pass ? "_tag" : "");
        if (rl_png_write_gray(file, &img, err, sizeof err) != RL_OK)
            return rl_cli_fail(NULL, 1, "%s", err);
    }
    s->twin = 0;
    snprintf(file, sizeof file, "%s.png", name);
    snprintf(err, sizeof err, "%s/%s.yaml", o->out, name);
    return render_truth_write(err, file, s, q[0], q[1], q[2]) != 0 ? 1 : 0; /* the line is printed */
}

/* --path stream: a frame per pose read, each announced when written.
 * 0, or the exit code. */
static int render_stream_frames(const render_opts *o, render_plan *p, render_scene *s, uint8_t *px)
{
    render_stream st;
    uint64_t t;
    int k, r = 0, got = 0;
    render_stream_open(&st, 0, "standard input", o->newest);
    for (k = 0; r == 0 && (got = render_stream_next(&st, &t, &p->q[0], &p->q[1], &p->q[2])) == 1; k++)
        if ((r = render_frame(o, p, s, k, px)) == 0 &&
            (printf("%llu stream_%06d.png\n", (unsigned long long)t, k) < 0 || fflush(stdout) != 0))
            r = rl_cli_fail(NULL, 1, "standard output: %s", strerror(errno));
    if (r == 0 && got < 0)
        r = 1;
    if (st.skipped > 0)
        fprintf(stderr, "ringloc-render: %d frames drawn, %ld poses skipped as stale (--newest)\n", k, st.skipped);
    return r;
}

/* Every frame into o->out. 0, or the exit code. */
static int render_frames(const render_opts *o, render_plan *p, render_scene *s)
{
    uint8_t *px;
    int k, r = 0;
    if (mkdir_p(o->out) != 0)
        return rl_cli_fail(NULL, 1, "%s: %s", o->out, strerror(errno));
    if (render_ceiling_tags_open() != 0 || (px = malloc((size_t)s->cam.width * s->cam.height)) == NULL)
        return rl_cli_fail(NULL, 1, "out of memory");
    if (p->stream)
        r = render_stream_frames(o, p, s, px);
    for (k = 0; !p->stream && k < o->count && r == 0; k++)
        r = render_frame(o, p, s, k, px);
    free(px);
    render_ceiling_tags_close();
    render_camera_free();
    return r;
}

int main(int argc, char **argv)
{
    static render_opts o;
    static rl_site site;
    static render_scene s;
    render_plan plan;
    rl_calib cam;
    int r;

    rl_cli_start("ringloc-render");
    if ((r = render_args(argc, argv, &o)) >= 0 || (r = load_site(&o, &site, &cam)) != 0)
        return r;
    if (o.out && mkdir_p(o.out) != 0)
        return rl_cli_fail(NULL, 1, "%s: %s", o.out, strerror(errno));
    if ((r = scene_setup(&o, &site, &cam, &s)) != 0 || (r = write_site(&o, &site, &s)) != 0)
        return r;
    if (!o.out) {
        if (o.map_out || o.cam_out || o.robot_out)
            return 0;
        return rl_cli_fail(NULL, 2, "--out DIR is required (see --help)");
    }
    if ((r = plan_frames(&o, &site, &plan)) != 0)
        return r;
    r = render_frames(&o, &plan, &s);
    free(plan.poses);
    return r;
}
