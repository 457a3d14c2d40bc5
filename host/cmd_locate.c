/* ringloc locate: the robot's pose from PNG images. */
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

static const char *locate_help =
    "usage: ringloc locate --camera CAM.yaml --map MAP.yaml --robot ROBOT.yaml\n"
    "                      [--offsets OFFSETS.yaml] [--annotate OUT.png] [--size WxH]\n"
    "                      [--local auto|always|never] [--min-score 0.8]\n"
    "                      [--interval 0.1 | --alone] [--track] [--readout MS] IMAGE...\n\n"
    "Recognize landmarks and compute the robot's pose (REP-103, map frame) for\n"
    "each image. Prints the detect JSON line with one more field:\n"
    "  \"pose\": {\"x\": 1.2034, \"y\": 0.5021, \"yaw\": 0.0312, \"landmarks_used\": 4,\n"
    "           \"residual\": 0.0021, \"sigma\": {\"x\": 0.0011, \"y\": 0.0009, \"yaw\": 0.0004},\n"
    "           \"tilt\": {\"roll\": 0.0012, \"pitch\": -0.0051, \"solved\": true}, \"dropped\": []}\n"
    "in metres and radians, or \"pose\": null with \"pose_error\" saying why.\n"
    "A map that repeats ids (a large site, 'ringloc plan --area') is searched for\n"
    "the place whose constellation the frame shows; one more field says how:\n"
    "  \"place\": {\"status\": \"found\", \"verified\": 9, \"runner_up\": 2, \"candidates\": 41}\n"
    "(status ambiguous: no place leads the others clearly; no pose). The images\n"
    "are taken as frames of one drive, in the order given: as 'ringloc run'\n"
    "does, each frame's place is looked for near the last pose first (status\n"
    "\"tracked\"), where two landmarks are enough (a place that leaves most of\n"
    "the frame unverified is checked against the whole map first); a recorded\n"
    "drive replays as it ran.\n\n"
    "  --camera FILE    ROS camera_info or OpenCV calibration YAML\n"
    "  --map FILE       landmark map YAML (family, diameter, ceiling_height, landmarks)\n"
    "  --robot FILE     robot YAML: camera_mount {x, y, z, yaw, roll, pitch}\n"
    "  --size WxH       the image size, for a calibration that does not give it\n"
    "  --offsets FILE   pixel-to-offset polynomial from 'ringloc calibrate-offsets',\n"
    "                   used instead of the pinhole model\n"
    "  --annotate FILE  write the image with what was recognized drawn on it\n"
    "  --local POLICY   local pass: always (default), auto (the paper's: when fewer\n"
    "                   than 2 were identified) or never\n"
    "  --min-score S    Pearson correlation an id needs in the global pass (default 0.8)\n"
    "  --gamma G|auto   the camera's tone curve (default auto), as for detect\n"
    "  --interval S     seconds between the frames of the drive (default 0.1, as\n"
    "                   recorded at 10 frames a second; 'every' of a recording\n"
    "                   multiplies it): how far the robot can have moved\n"
    "  --alone          each image alone, no previous pose (images of different\n"
    "                   places or drives)\n"
    "  --track          once placed, read an image of the drive only in windows\n"
    "                   round where the map's landmarks must be (\"track\":\n"
    "                   \"windows\"; \"unjudged\": the landmarks kept as known from\n"
    "                   the frame before), every 10th in full (\"full\"), and\n"
    "                   whenever a window misses or the pose jumps\n"
    "                   (docs/tracking.md); by default (or --no-track) every\n"
    "                   image is read in full\n"
    "  --readout MS     the camera's rolling shutter: its rows read top to bottom in\n"
    "                   MS milliseconds (0, the default: a global shutter); each\n"
    "                   landmark is moved to the middle row's instant by the motion\n"
    "                   of the last two poses (their times from --interval: give\n"
    "                   the drive's own), and the pose is the middle row's\n"
    "                   (docs/results.md, \"A rolling shutter\"); not with --alone\n";


typedef struct {
    const char *annotate;     /* --annotate, or NULL */
    int several;              /* more than one image */
    const rl_site *site;
    long failures;
} locate_sink;

static const char *pose_error(const rl_run_report *rep)
{
    if (rep->pose_err == RL_ETOOFEW)
        return rep->pose->n_dropped ? "too few consistent landmarks (some disagree with the map)"
                                    : "fewer than 2 landmarks identified";
    if (rep->pose_err == RL_EAMBIGUOUS)
        return "ambiguous: the landmarks fit more than one place of the map";
    return rl_strerror(rep->pose_err);
}

/* The map entries whose reads kept their ids unjudged (known from the
 * frame before): their ids and places. */
static void print_unjudged(const rl_track *t, const rl_map *map)
{
    int k;
    printf(", \"unjudged\": [");
    for (k = 0; k < t->n_unjudged; k++) {
        const rl_map_landmark *m = &map->lm[t->unjudged[k]];
        printf("%s{\"id\": %d, \"x\": %.4f, \"y\": %.4f}", k ? ", " : "", m->id, m->x, m->y);
    }
    printf("]");
}

/* The detect line's fields, then place and pose. */
static void print_pose(const rl_run_report *rep, const rl_site *site)
{
    const rl_pose *pose = rep->pose;
    const rl_place_found *found = rep->place;
    int k;
    rl_report_json_open(stdout, rep->frame->name, rep->res, &site->recog.cfg.family, rep->recog_us);
    if (site->place.pl != NULL)
        printf(", \"place\": {\"status\": \"%s\", \"verified\": %d, \"runner_up\": %d, \"candidates\": %d}",
               rl_place_status_name(found->status), found->verified, found->runner_up, found->candidates);
    printf(", \"track\": \"%s\"", rep->windows ? "windows" : "full");
    if (rep->windows) /* the reads kept as known, unjudged by the zone twins' check (rl_track.h) */
        print_unjudged(rep->track, &site->map);
    if (rep->pose_err != RL_OK) {
        printf(", \"pose\": null, \"pose_error\": \"%s\"}\n", pose_error(rep));
        return;
    }
    printf(", \"pose\": {\"x\": %.4f, \"y\": %.4f, \"yaw\": %.4f, \"landmarks_used\": %d, "
           "\"residual\": %.4f, \"sigma\": {\"x\": %.4f, \"y\": %.4f, \"yaw\": %.5f}, "
           "\"tilt\": {\"roll\": %.5f, \"pitch\": %.5f, \"solved\": %s}, \"dropped\": [",
           pose->x, pose->y, pose->yaw, pose->used, pose->residual, pose->sigma_x, pose->sigma_y,
           pose->sigma_yaw, pose->roll, pose->pitch, pose->tilt_solved ? "true" : "false");
    for (k = 0; k < pose->n_dropped; k++)
        printf("%s%d", k ? ", " : "", pose->dropped[k]);
    printf("]}}\n");
}

static void annotate_pose(locate_sink *l, const rl_run_report *rep)
{
    const char *image = rep->frame->name;
    char caption[256], name[1024], err[512];
    if (rep->pose_err == RL_OK)
        snprintf(caption, sizeof caption, "%s  x %.3f  y %.3f  yaw %.1f deg  (%d landmarks)", image,
                 rep->pose->x, rep->pose->y, rep->pose->yaw * 180.0 / 3.14159265358979, rep->pose->used);
    else
        snprintf(caption, sizeof caption, "%s  no pose", image);
    rl_cli_annotate_name(name, sizeof name, l->annotate, image, l->several);
    if (rl_annotate_png(name, &rep->frame->img, rep->res, &l->site->recog.cfg.family, caption, err,
                        sizeof err) != RL_OK) {
        rl_cli_fail("locate", RL_EXIT_FAIL, "%s", err);
        l->failures++;
    }
}

static rl_err locate_put(void *ctx, const rl_run_report *rep)
{
    locate_sink *l = (locate_sink *)ctx;
    print_pose(rep, l->site);
    fflush(stdout);
    if (l->annotate)
        annotate_pose(l, rep);
    return RL_OK;
}

int rl_cmd_locate(int argc, char **argv)
{
    static const struct option opts[] = {
        {"camera", required_argument, 0, 'c'}, {"map", required_argument, 0, 'm'},
        {"robot", required_argument, 0, 'r'}, {"offsets", required_argument, 0, 'o'},
        {"annotate", required_argument, 0, 'a'}, {"local", required_argument, 0, 'L'},
        {"min-score", required_argument, 0, 's'}, {"gamma", required_argument, 0, 'Y'},
        {"size", required_argument, 0, 'z'},
        {"interval", required_argument, 0, 'i'}, {"alone", no_argument, 0, 'A'},
        {"no-track", no_argument, 0, 'T'}, {"track", no_argument, 0, 'K'},
        {"readout", required_argument, 0, 'R'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    const char *C = "locate", *family = NULL;
    static rl_site site;
    rl_site_files files;
    rl_recog_config cfg;
    rl_pngrun pr;
    locate_sink l;
    long failed;
    int c, track = 0;
    char err[768];

    memset(&l, 0, sizeof l);
    rl_site_files_init(&files);
    files.size_from = "--size";
    rl_recog_defaults(&cfg);
    rl_pngrun_defaults(&pr, C);
    pr.run.frame_interval = 0.1;
    rl_track_defaults(&pr.run.track); /* used with --track */
    optind = 1;
    while ((c = rl_cli_getopt_recog(C, argc, argv, opts, &cfg, &family)) != -1) {
        switch (c) {
        case 'c': files.calibration = optarg; break;
        case 'm': files.map = optarg; break;
        case 'r': files.robot = optarg; break;
        case 'o': files.offsets = optarg; break;
        case 'a': l.annotate = optarg; break;
        case 'z':
            if (!rl_cli_size(C, "--size", optarg, RL_MAX_IMAGE_DIM, &files.width, &files.height))
                return RL_EXIT_USAGE;
            break;
        case 'i':
            if (!rl_cli_double(C, "--interval", optarg, 0.001, 3600, &pr.run.frame_interval))
                return RL_EXIT_USAGE;
            break;
        case 'A': pr.run.alone = 1; break;
        case 'R':
            if (!rl_cli_double(C, "--readout", optarg, 0, 200, &pr.run.readout))
                return RL_EXIT_USAGE;
            pr.run.readout /= 1000.0;
            break;
        case 'T': track = 0; break;
        case 'K': track = 1; break;
        case 'h': fputs(locate_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (!track)
        pr.run.track.full_every = 0; /* every image in full */
    if (pr.run.alone && pr.run.readout > 0)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--readout moves each frame by the motion of the ones before it: "
                                             "not with --alone");
    if (!files.calibration || !files.map || !files.robot)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--camera, --map and --robot are required (see --help)");
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "no images given (see --help)");
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK || rl_site_prepare(&site, &cfg, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    l.site = &site;
    l.several = argc - optind > 1;
    pr.put = locate_put;
    pr.ctx = &l;
    failed = rl_pngrun_files(&pr, &site, argv + optind, argc - optind);
    rl_site_free(&site);
    return failed + l.failures ? RL_EXIT_FAIL : 0;
}
