/* ringloc survey: the map from a recorded drive (rl_survey). */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "rl_cli.h"
#include "rl_clock.h"
#include "rl_cmd.h"
#include "rl_mapfile.h"
#include "rl_outfile.h"
#include "rl_site.h"
#include "rl_survey.h"
#include "rl_survey_input.h"
#include "rl_survey_moved.h"
#include "rl_survey_plot.h"

static const char *survey_help =
    "usage: ringloc survey --camera CAM.yaml --robot ROBOT.yaml --origin ID --axis ID\n"
    "                      [--family ring5] [--diameter 0.21]\n"
    "                      [--ceiling-height H | --axis-distance D] [--map OLD.yaml]\n"
    "                      [--plot FILE.png] --out MAP.yaml FRAME...\n\n"
    "Build the landmark map from frames the robot recorded on a drive (ringloc run\n"
    "--record DIR), instead of measuring the ceiling by hand. Every frame is\n"
    "recognized, then every landmark's position, the ceiling's height and every\n"
    "frame's pose and tilt are estimated together by robust least squares over all\n"
    "observations (Ceres Solver), and the height of each landmark off the\n"
    "ceiling's plane (a beam, a lower panel). FRAME: PNG files, folders of them, or JSON-lines\n"
    "files of `ringloc detect` output (to redo a survey without recognizing again).\n"
    "The map frame: the origin landmark at (0, 0), the axis landmark on +x. The\n"
    "scale comes from the printed diameter (the landmarks' image radii), or from a\n"
    "measured ceiling height or origin-axis distance when given (more exact).\n"
    "Writes MAP.yaml for locate and run, each landmark with its standard deviations,\n"
    "and prints one JSON line:\n"
    "  {\"landmarks\": 30, \"frames\": 300, \"frames_used\": 296, \"observations\": 3712,\n"
    "   \"ceiling_height\": 2.7503, \"sigma_ceiling_height\": 0.0004, \"rms_px\": 0.11,\n"
    "   \"scale\": \"diameter\", \"least_certain\": {\"id\": 6, \"sigma\": 0.0009},\n"
    "   \"off_plane\": [{\"id\": 8, \"z\": 2.4503, \"sigma_z\": 0.0021}],\n"
    "   \"not_placed\": [], \"alone\": [],\n"
    "   \"left_out\": {\"few\": 3, \"lost\": 0, \"outlier\": 1, \"unreadable\": 0},\n"
    "   \"moved\": [{\"id\": 12, \"distance\": 0.0501, \"sigmas\": 61.2}], \"seconds\": 4.1,\n"
    "   \"cpu_seconds\": 4.0}\n"
    "off_plane: landmarks off the ceiling's plane (a beam, a lower panel: 3 cm and\n"
    "five of their sigmas or more), each with its own height z in MAP.yaml;\n"
    "not_placed: landmarks seen in fewer than two frames with another landmark;\n"
    "alone: ids seen only by themselves; few: frames with fewer than two landmarks;\n"
    "lost: frames that fit no place of the others; outlier: frames whose centres\n"
    "disagree with the rest. moved (with --map): landmarks more than three of their\n"
    "sigmas away from their place in OLD.yaml (after fitting the two maps together).\n\n"
    "  --camera FILE        the camera's calibration (ROS / OpenCV YAML)\n"
    "  --robot FILE         the camera's mounting on the robot (camera_mount)\n"
    "  --origin ID          the landmark put at (0, 0)\n"
    "  --axis ID            the landmark put on +x\n"
    "  --family NAME        landmark family (default ring5)\n"
    "  --diameter D         printed outer diameter, m (default 0.21)\n"
    "  --ceiling-height H   the ceiling above the floor, measured, m\n"
    "  --axis-distance D    origin to axis landmark, measured centre to centre, m\n"
    "  --map FILE           an older map: list the landmarks that moved since\n"
    "  --plot FILE          draw the landmarks, their uncertainty and the drive (PNG)\n"
    "  --gate M             a landmark of the same id this far from where a frame's\n"
    "                       pose puts it is the same one (default 0.3 m; sites that\n"
    "                       repeat ids)\n"
    "  --local POLICY, --min-score R, --gamma G|auto  recognition options, as for detect\n"
    "  --out FILE           the map to write\n";

typedef struct {
    const char *cam, *robot, *old, *plot, *out, *family;
    int origin, axis;
} survey_args;

static int parse(int argc, char **argv, survey_args *a, rl_survey_config *cfg, rl_recog_config *rc)
{
    static const struct option opts[] = {
        {"camera", required_argument, 0, 'c'}, {"robot", required_argument, 0, 'r'},
        {"origin", required_argument, 0, 'O'}, {"axis", required_argument, 0, 'A'},
        {"family", required_argument, 0, 'f'}, {"diameter", required_argument, 0, 'd'},
        {"ceiling-height", required_argument, 0, 'H'}, {"axis-distance", required_argument, 0, 'D'},
        {"map", required_argument, 0, 'm'}, {"plot", required_argument, 0, 'p'},
        {"gate", required_argument, 0, 'g'}, {"local", required_argument, 0, 'L'},
        {"min-score", required_argument, 0, 's'}, {"gamma", required_argument, 0, 'Y'},
        {"out", required_argument, 0, 'o'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    const char *C = "survey";
    int c;
    optind = 1;
    while ((c = rl_cli_getopt_recog(C, argc, argv, opts, rc, &a->family)) != -1) {
        switch (c) {
        case 'c': a->cam = optarg; break;
        case 'r': a->robot = optarg; break;
        case 'O': if (!rl_cli_int(C, "--origin", optarg, 1, 1 << 20, &a->origin)) return RL_EXIT_USAGE; break;
        case 'A': if (!rl_cli_int(C, "--axis", optarg, 1, 1 << 20, &a->axis)) return RL_EXIT_USAGE; break;
        case 'd': if (!rl_cli_double(C, "--diameter", optarg, 0.005, 5, &cfg->diameter)) return RL_EXIT_USAGE; break;
        case 'H':
            if (!rl_cli_double(C, "--ceiling-height", optarg, 0.1, 100, &cfg->ceiling_height))
                return RL_EXIT_USAGE;
            break;
        case 'D':
            if (!rl_cli_double(C, "--axis-distance", optarg, 0.01, 1e4, &cfg->axis_distance))
                return RL_EXIT_USAGE;
            break;
        case 'g': if (!rl_cli_double(C, "--gate", optarg, 0.01, 100, &cfg->gate)) return RL_EXIT_USAGE; break;
        case 'm': a->old = optarg; break;
        case 'p': a->plot = optarg; break;
        case 'o': a->out = optarg; break;
        case 'h': fputs(survey_help, stdout); return -1;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (!a->cam || !a->robot || !a->out || !a->origin || !a->axis)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--camera, --robot, --origin, --axis and --out are required (see --help)");
    if (a->origin == a->axis)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--origin and --axis are the same landmark (%d)", a->origin);
    if (cfg->ceiling_height > 0 && cfg->axis_distance > 0)
        return rl_cli_fail(C, RL_EXIT_USAGE, "give --ceiling-height or --axis-distance, not both");
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "no frames given (see --help)");
    if (a->family && rl_family_parse(a->family, &rc->family) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--family: '%s' is not a family (ring2 .. ring%d)", a->family,
                           RL_MAX_BITS);
    if (!rl_family_valid(&rc->family, a->origin) || !rl_family_valid(&rc->family, a->axis))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--%s: %d is not an id of ring%d (1 .. %d)",
                           rl_family_valid(&rc->family, a->origin) ? "axis" : "origin",
                           rl_family_valid(&rc->family, a->origin) ? a->axis : a->origin, rc->family.bits,
                           rl_family_count(&rc->family));
    return 0;
}

static rl_err write_map(const char *path, const rl_survey *sv, const rl_family *fam, char *err, size_t errlen)
{
    rl_outfile o;
    FILE *f;
    int i;
    rl_err e;
    if ((e = rl_outfile_open(&o, path, err, errlen)) != RL_OK)
        return e;
    f = o.f;
    fprintf(f, "# ringloc survey: %d frames used, RMS %.3f px; origin %d, axis %d\n", sv->frames_used,
            sv->rms_px, sv->cfg.origin_id, sv->cfg.axis_id);
    rl_mapfile_put_header(f, fam, sv->cfg.diameter, sv->height);
    for (i = 0; i < sv->n_lm; i++) {
        const rl_survey_landmark *l = &sv->lm[i];
        rl_map_landmark m;
        if (l->status != RL_SURVEY_PLACED)
            continue;
        m.id = l->id;
        m.x = l->x;
        m.y = l->y;
        m.sigma_x = sqrt(fmax(0, l->cov[0]));
        m.sigma_y = sqrt(fmax(0, l->cov[2]));
        m.z = l->z; /* off the ceiling's plane: its own height */
        rl_mapfile_put_landmark(f, &m);
    }
    return rl_outfile_commit(&o, err, errlen);
}

static void print_ids(const rl_survey *sv, int status)
{
    int i, n = 0;
    for (i = 0; i < sv->n_lm; i++)
        if (sv->lm[i].status == status)
            printf("%s%d", n++ ? ", " : "", sv->lm[i].id);
}

static void report(const rl_survey *sv, int frames, int unreadable, const rl_survey_move *mv, int n_mv,
                   double seconds)
{
    int i, placed = 0, n_off = 0, worst = -1, left[4] = {0, 0, 0, 0};
    double ws = -1;
    for (i = 0; i < sv->n_lm; i++) {
        const rl_survey_landmark *l = &sv->lm[i];
        double s = sqrt(fmax(0, l->cov[0] + l->cov[2]));
        if (l->status != RL_SURVEY_PLACED)
            continue;
        placed++;
        if (s > ws) {
            ws = s;
            worst = i;
        }
    }
    for (i = 0; i < sv->n_fr; i++)
        left[sv->fr[i].status]++;
    printf("{\"landmarks\": %d, \"frames\": %d, \"frames_used\": %d, \"observations\": %d, \"ceiling_height\": %.5f, "
           "\"sigma_ceiling_height\": %.5f, \"rms_px\": %.3f, \"scale\": \"%s\", ",
           placed, frames, sv->frames_used, sv->obs_used, sv->height, sv->sigma_height, sv->rms_px,
           sv->cfg.ceiling_height > 0 ? "ceiling-height" : sv->cfg.axis_distance > 0 ? "axis-distance" : "diameter");
    if (worst >= 0)
        printf("\"least_certain\": {\"id\": %d, \"sigma\": %.5f}, ", sv->lm[worst].id, ws);
    printf("\"off_plane\": [");
    for (i = 0; i < sv->n_lm; i++)
        if (sv->lm[i].status == RL_SURVEY_PLACED && sv->lm[i].z > 0)
            printf("%s{\"id\": %d, \"z\": %.4f, \"sigma_z\": %.4f}", n_off++ ? ", " : "", sv->lm[i].id, sv->lm[i].z,
                   sv->lm[i].sigma_z);
    printf("], \"not_placed\": [");
    print_ids(sv, RL_SURVEY_RARE);
    printf("], \"alone\": [");
    for (i = 0; i < sv->n_alone; i++)
        printf("%s%d", i ? ", " : "", sv->alone[i]);
    printf("], \"left_out\": {\"few\": %d, \"lost\": %d, \"outlier\": %d, \"unreadable\": %d}", left[RL_SURVEY_FEW],
           left[RL_SURVEY_LOST], left[RL_SURVEY_OUTLIER], unreadable);
    if (mv) {
        printf(", \"moved\": [");
        for (i = 0; i < n_mv; i++)
            printf("%s{\"id\": %d, \"distance\": %.4f, \"sigmas\": %.1f}", i ? ", " : "", mv[i].id, mv[i].distance,
                   mv[i].sigmas);
        printf("]");
    }
    printf(", \"seconds\": %.2f, \"cpu_seconds\": %.2f}\n", seconds, (double)clock() / CLOCKS_PER_SEC);
}

/* What the user should hear about on stderr: frames and landmarks left out. */
static void tell(const rl_survey *sv)
{
    static const char *why[] = {"", "fewer than two landmarks", "fit no place of the others",
                                "centres disagree with the rest"};
    int s, i;
    for (s = RL_SURVEY_LOST; s <= RL_SURVEY_OUTLIER; s++) {
        int n = 0;
        for (i = 0; i < sv->n_fr; i++)
            if (sv->fr[i].status == s && n++ < 5)
                fprintf(stderr, "ringloc survey: %s: left out (%s)\n", sv->fr[i].name, why[s]);
        if (n > 5)
            fprintf(stderr, "ringloc survey: ... and %d more frames left out (%s)\n", n - 5, why[s]);
    }
    for (i = 0; i < sv->n_lm; i++)
        if (sv->lm[i].status == RL_SURVEY_RARE)
            fprintf(stderr, "ringloc survey: landmark %d seen in %d frame(s) with others: not placed\n",
                    sv->lm[i].id, sv->lm[i].views);
    for (i = 0; i < sv->n_alone; i++)
        fprintf(stderr, "ringloc survey: landmark %d was only ever seen alone: not placed\n", sv->alone[i]);
    for (i = 0; i < sv->n_lm; i++)
        if (sv->lm[i].status == RL_SURVEY_PLACED && sv->lm[i].z > 0)
            fprintf(stderr, "ringloc survey: landmark %d is %.3f m %s the ceiling's plane (+-%.3f m): its own z in the map\n",
                    sv->lm[i].id, fabs(sv->lm[i].z - sv->height), sv->lm[i].z < sv->height ? "below" : "above",
                    sv->lm[i].sigma_z);
}

int rl_cmd_survey(int argc, char **argv)
{
    const char *C = "survey";
    survey_args a;
    rl_survey_config cfg;
    rl_recog_config rc;
    rl_survey sv;
    rl_survey_input in;
    static rl_site site, old_site;
    const rl_map *old = &old_site.map;
    rl_site_files files;
    static rl_survey_move mv[RL_MAX_MAP_LANDMARKS];
    double t0;
    char err[600];
    int i, r, n_mv = 0, code = 0;
    rl_err e;

    memset(&a, 0, sizeof a);
    rl_survey_defaults(&cfg);
    rl_recog_defaults(&rc);
    rc.band_radius = 1; /* the scale from the radii */
    if ((r = parse(argc, argv, &a, &cfg, &rc)) != 0)
        return r < 0 ? 0 : r;
    rl_site_files_init(&files);
    files.calibration = a.cam;
    files.robot = a.robot;
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    rl_site_files_init(&files);
    files.map = a.old;
    if (a.old && rl_site_load(&old_site, &files, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (a.old && old->family.bits != rc.family.bits)
        return rl_cli_fail(C, RL_EXIT_USAGE, "%s is a ring%d map, the survey is of ring%d", a.old, old->family.bits,
                           rc.family.bits);
    if (rl_site_prepare(&site, &rc, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    /* the solver found before the frames are read, not after */
    if (rl_survey_solver_check(err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    cfg.mount = site.mount;
    cfg.origin_id = a.origin;
    cfg.axis_id = a.axis;
    cfg.pixel_scale = sqrt(site.calib.fx * site.calib.fy);
    t0 = rl_clock_now_s();
    rl_survey_init(&sv, &cfg);
    rl_survey_input_init(&in, &site.calib, &rc.family, &sv, &site);
    in.progress = isatty(2);
    for (i = optind; i < argc; i++)
        if ((e = rl_survey_input_path(&in, argv[i])) != RL_OK) {
            code = rl_cli_fail(C, RL_EXIT_FAIL, "%s", in.err);
            goto out;
        }
    if (in.progress)
        fprintf(stderr, "ringloc survey: %d frames read, solving\n", in.frames);
    if (rl_survey_build(&sv) != RL_OK || rl_survey_adjust(&sv) != RL_OK) {
        code = rl_cli_fail(C, RL_EXIT_FAIL, "%s", sv.err);
        goto out;
    }
    if (a.old && (n_mv = rl_survey_moved(&sv, old, 3.0, mv, RL_MAX_MAP_LANDMARKS)) < 0) {
        code = rl_cli_fail(C, RL_EXIT_FAIL, "out of memory comparing with %s", a.old);
        goto out;
    }
    if (write_map(a.out, &sv, &rc.family, err, sizeof err) != RL_OK ||
        (a.plot && rl_survey_plot(a.plot, &sv, mv, n_mv, err, sizeof err) != RL_OK)) {
        code = rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
        goto out;
    }
    tell(&sv);
    report(&sv, in.frames + in.unreadable, in.unreadable, a.old ? mv : NULL, n_mv,
           rl_clock_now_s() - t0);
out:
    rl_survey_free(&sv);
    rl_site_free(&site);
    return code;
}
