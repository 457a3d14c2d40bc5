/* ringloc locate: the robot's pose from PNG images. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_annotate.h"
#include "rl_calibfile.h"
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_heap_place.h"
#include "rl_mapfile.h"
#include "rl_offsetsfile.h"
#include "rl_png.h"
#include "rl_report.h"
#include "rl_robotfile.h"

static const char *locate_help =
    "usage: ringloc locate --camera CAM.yaml --map MAP.yaml --robot ROBOT.yaml\n"
    "                      [--offsets OFFSETS.yaml] [--annotate OUT.png] [--size WxH]\n"
    "                      [--local auto|always|never] [--min-score 0.8]\n"
    "                      [--interval 0.1 | --alone] IMAGE...\n\n"
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
    "\"tracked\"), where two landmarks are enough; a recorded drive replays as it\n"
    "ran.\n\n"
    "  --camera FILE    ROS camera_info or OpenCV calibration YAML\n"
    "  --map FILE       landmark map YAML (family, diameter, ceiling_height, landmarks)\n"
    "  --robot FILE     robot YAML: camera_mount {x, y, z, yaw, roll, pitch}\n"
    "  --size WxH       the image size, for a calibration that does not give it\n"
    "  --offsets FILE   pixel-to-offset polynomial from 'ringloc calibrate-offsets',\n"
    "                   used instead of the pinhole model\n"
    "  --annotate FILE  write the image with what was recognized drawn on it\n"
    "  --local POLICY   local pass: always (default), auto (the paper's: when fewer\n"
    "                   than 2 were identified) or never\n"
    "  --gamma G|auto   the camera's tone curve (default auto), as for detect\n"
    "  --interval S     seconds between the frames of the drive (default 0.1, as\n"
    "                   recorded at 10 frames a second; 'every' of a recording\n"
    "                   multiplies it): how far the robot can have moved\n"
    "  --alone          each image alone, no previous pose (images of different\n"
    "                   places or drives)\n";


int rl_cmd_locate(int argc, char **argv)
{
    static const struct option opts[] = {
        {"camera", required_argument, 0, 'c'}, {"map", required_argument, 0, 'm'},
        {"robot", required_argument, 0, 'r'}, {"offsets", required_argument, 0, 'o'},
        {"annotate", required_argument, 0, 'a'}, {"local", required_argument, 0, 'L'},
        {"min-score", required_argument, 0, 's'}, {"gamma", required_argument, 0, 'Y'},
        {"size", required_argument, 0, 'z'},
        {"interval", required_argument, 0, 'i'}, {"alone", no_argument, 0, 'A'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    int size_w = 0, size_h = 0;
    const char *C = "locate", *cam_path = NULL, *map_path = NULL, *robot_path = NULL,
               *off_path = NULL, *annotate = NULL, *family = NULL;
    rl_recog_config cfg;
    rl_heap_recog hr;
    static rl_result res;
    static rl_map map;
    rl_calib cam;
    rl_mount mount;
    rl_offsets offsets;
    int c, i, failures = 0, ids[RL_MAX_IDS], alone = 0;
    double interval = 0.1;
    rl_place_prior prior;
    rl_heap_place hp;
    rl_place_found found;
    rl_err e0;
    char err[512], name[1024];

    rl_recog_defaults(&cfg);
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        int r = rl_cli_recog_option(C, c, optarg, &cfg, &family);
        if (r < 0)
            return RL_EXIT_USAGE;
        if (r > 0)
            continue;
        switch (c) {
        case 'c': cam_path = optarg; break;
        case 'm': map_path = optarg; break;
        case 'r': robot_path = optarg; break;
        case 'o': off_path = optarg; break;
        case 'a': annotate = optarg; break;
        case 'z':
            if (!rl_cli_size(C, "--size", optarg, RL_MAX_IMAGE_DIM, &size_w, &size_h))
                return RL_EXIT_USAGE;
            break;
        case 'i':
            if (!rl_cli_double(C, "--interval", optarg, 0.001, 3600, &interval))
                return RL_EXIT_USAGE;
            break;
        case 'A': alone = 1; break;
        case 'h': fputs(locate_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (!cam_path || !map_path || !robot_path)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--camera, --map and --robot are required (see --help)");
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "no images given (see --help)");
    if (rl_calibfile_load_sized(cam_path, size_w, size_h, &cam, err, sizeof err) != RL_OK ||
        rl_mapfile_load(map_path, &map, err, sizeof err) != RL_OK ||
        rl_robotfile_load(robot_path, &mount, err, sizeof err) != RL_OK ||
        (off_path && rl_offsetsfile_load(off_path, &offsets, err, sizeof err) != RL_OK))
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (map.count == 0)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: the map has no landmarks", map_path);
    if (!(map.ceiling_height > mount.z))
        return rl_cli_fail(C, RL_EXIT_FAIL,
                           "%s: camera_mount.z %.3f m is not below the ceiling (%s: ceiling_height %.3f m)",
                           robot_path, mount.z, map_path, map.ceiling_height);
    if ((e0 = rl_heap_place_init(&hp, &map, NULL)) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: the place index: %s", map_path, rl_strerror(e0));
    rl_recog_use_map(&cfg, &map, ids);
    rl_heap_recog_init(&hr, &cfg);
    memset(&prior, 0, sizeof prior);
    for (i = optind; i < argc; i++, prior.age += interval) {
        rl_image img;
        double us = 0;
        rl_pose pose;
        rl_err e;
        int k;
        if (rl_png_read_gray(argv[i], &img, err, sizeof err) != RL_OK) {
            rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
            failures++;
            continue;
        }
        if (img.width != cam.width || img.height != cam.height) {
            rl_cli_fail(C, RL_EXIT_FAIL, "%s: image is %dx%d but %s (image_width, image_height) is for %dx%d",
                        argv[i], img.width, img.height, cam_path, cam.width, cam.height);
            failures++;
            rl_png_free(&img);
            continue;
        }
        if ((e = rl_report_run(&hr, &img, &res, &us)) != RL_OK) {
            rl_cli_fail(C, RL_EXIT_FAIL, "%s: recognition failed: %s", argv[i], rl_strerror(e));
            failures++;
            rl_png_free(&img);
            continue;
        }
        e = rl_heap_place_solve(&hp, &cam, &map, &mount, res.landmarks, res.n_landmarks, off_path ? &offsets : NULL,
                                alone ? NULL : &prior, &pose, &found);
        if (e == RL_OK) { /* the next frame's prior */
            prior.valid = 1;
            prior.x = pose.x;
            prior.y = pose.y;
            prior.yaw = pose.yaw;
            prior.age = 0;
        }
        rl_report_json_open(stdout, argv[i], &res, &cfg.family, us);
        if (hp.pl != NULL)
            printf(", \"place\": {\"status\": \"%s\", \"verified\": %d, \"runner_up\": %d, \"candidates\": %d}",
                   rl_place_status_name(found.status), found.verified, found.runner_up, found.candidates);
        if (e == RL_OK) {
            printf(", \"pose\": {\"x\": %.4f, \"y\": %.4f, \"yaw\": %.4f, \"landmarks_used\": %d, "
                   "\"residual\": %.4f, \"sigma\": {\"x\": %.4f, \"y\": %.4f, \"yaw\": %.5f}, "
                   "\"tilt\": {\"roll\": %.5f, \"pitch\": %.5f, \"solved\": %s}, \"dropped\": [",
                   pose.x, pose.y, pose.yaw, pose.used, pose.residual, pose.sigma_x, pose.sigma_y,
                   pose.sigma_yaw, pose.roll, pose.pitch, pose.tilt_solved ? "true" : "false");
            for (k = 0; k < pose.n_dropped; k++)
                printf("%s%d", k ? ", " : "", pose.dropped[k]);
            printf("]}}\n");
        } else {
            printf(", \"pose\": null, \"pose_error\": \"%s\"}\n",
                   e == RL_ETOOFEW ? (pose.n_dropped ? "too few consistent landmarks (some disagree with the map)"
                                                     : "fewer than 2 landmarks identified")
                   : e == RL_EAMBIGUOUS ? "ambiguous: the landmarks fit more than one place of the map"
                                        : rl_strerror(e));
        }
        fflush(stdout);
        if (annotate) {
            char caption[256];
            if (e == RL_OK)
                snprintf(caption, sizeof caption, "%s  x %.3f  y %.3f  yaw %.1f deg  (%d landmarks)",
                         argv[i], pose.x, pose.y, pose.yaw * 180.0 / 3.14159265358979, pose.used);
            else
                snprintf(caption, sizeof caption, "%s  no pose", argv[i]);
            rl_cli_annotate_name(name, sizeof name, annotate, argv[i], argc - optind > 1);
            if (rl_annotate_png(name, &img, &res, &cfg.family, caption, err, sizeof err) != RL_OK) {
                rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
                failures++;
            }
        }
        rl_png_free(&img);
    }
    rl_heap_recog_free(&hr);
    rl_heap_place_free(&hp);
    return failures ? RL_EXIT_FAIL : 0;
}
