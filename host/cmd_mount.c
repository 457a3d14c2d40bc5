/* ringloc calibrate-mount: the camera's fixed tilt on the robot, from
 * recorded frames with three or more landmarks. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "rl_calibfile.h"
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_heap_place.h"
#include "rl_mapfile.h"
#include "rl_png.h"
#include "rl_report.h"
#include "rl_robotfile.h"

static const char *mount_help =
    "usage: ringloc calibrate-mount --camera CAM.yaml --map MAP.yaml --robot ROBOT.yaml\n"
    "                               --out ROBOT2.yaml FRAME...\n\n"
    "A camera bracket is rarely exactly vertical. From frames the robot's camera\n"
    "recorded on its floor (a drive, or the robot turning in place) with three or\n"
    "more landmarks in view, solve the camera's attitude in each and take the\n"
    "mount's fixed tilt as their mean (the robot's own rocking averages out).\n"
    "Writes ROBOT.yaml with camera_mount roll (about the robot's x) and pitch\n"
    "(about its y) in radians; 'locate' and 'run' then correct every ray by it,\n"
    "which matters most when only two landmarks are seen. Prints one JSON line:\n"
    "  {\"roll\": 0.0251, \"pitch\": -0.0249, \"sigma_roll\": 0.0002,\n"
    "   \"sigma_pitch\": 0.0002, \"frames_used\": 36, \"frames\": 40}\n"
    "(sigma: the standard error of the mean over the frames).\n";

int rl_cmd_mount(int argc, char **argv)
{
    static const struct option opts[] = {
        {"camera", required_argument, 0, 'c'}, {"map", required_argument, 0, 'm'},
        {"robot", required_argument, 0, 'r'}, {"out", required_argument, 0, 'o'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    const char *C = "calibrate-mount", *cam_path = NULL, *map_path = NULL, *robot_path = NULL, *out = NULL;
    static rl_map map;
    static rl_result res;
    rl_calib cam;
    rl_mount mount, level;
    rl_recog_config cfg;
    rl_heap_recog hr;
    int c, i, used = 0, frames = 0, ids[RL_MAX_IDS];
    rl_heap_place hp;
    rl_place_found found;
    double sr = 0, sp = 0, srr = 0, spp = 0;
    char err[512];

    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        switch (c) {
        case 'c': cam_path = optarg; break;
        case 'm': map_path = optarg; break;
        case 'r': robot_path = optarg; break;
        case 'o': out = optarg; break;
        case 'h': fputs(mount_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (!cam_path || !map_path || !robot_path || !out)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--camera, --map, --robot and --out are required (see --help)");
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "no frames given (see --help)");
    if (rl_calibfile_load(cam_path, &cam, err, sizeof err) != RL_OK ||
        rl_mapfile_load(map_path, &map, err, sizeof err) != RL_OK ||
        rl_robotfile_load(robot_path, &mount, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    /* the tilt is measured from a mount taken as vertical */
    level = mount;
    level.roll = level.pitch = 0;
    if (rl_heap_place_init(&hp, &map, NULL) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s: the place index: out of memory", map_path);
    rl_recog_defaults(&cfg);
    rl_recog_use_map(&cfg, &map, ids);
    rl_heap_recog_init(&hr, &cfg);
    for (i = optind; i < argc; i++) {
        rl_image img;
        rl_pose pose;
        double us;
        frames++;
        if (rl_png_read_gray(argv[i], &img, err, sizeof err) != RL_OK) {
            fprintf(stderr, "ringloc %s: %s; left out\n", C, err);
            continue;
        }
        if (img.width != cam.width || img.height != cam.height) {
            fprintf(stderr, "ringloc %s: %s: %dx%d, the calibration is for %dx%d; left out\n", C, argv[i],
                    img.width, img.height, cam.width, cam.height);
        } else if (rl_report_run(&hr, &img, &res, &us) == RL_OK &&
                   rl_heap_place_solve(&hp, &cam, &map, &level, res.landmarks, res.n_landmarks, NULL, NULL, &pose,
                                       &found) == RL_OK &&
                   pose.fit_valid) {
            sr += pose.fit_roll;
            sp += pose.fit_pitch;
            srr += pose.fit_roll * pose.fit_roll;
            spp += pose.fit_pitch * pose.fit_pitch;
            used++;
        }
        rl_png_free(&img);
        if (isatty(2) && frames % 10 == 0)
            fprintf(stderr, "ringloc %s: %d of %d frames\r", C, frames, argc - optind);
    }
    rl_heap_recog_free(&hr);
    rl_heap_place_free(&hp);
    if (used < 3)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%d of %d frames show three or more landmarks of %s; at least 3 "
                           "such frames are needed", used, frames, map_path);
    mount.roll = sr / used;
    mount.pitch = sp / used;
    if (!(fabs(mount.roll) < 0.5 && fabs(mount.pitch) < 0.5))
        return rl_cli_fail(C, RL_EXIT_FAIL, "the tilt found (roll %.3f, pitch %.3f rad) is beyond 0.5 rad: "
                           "check the camera calibration and the map", mount.roll, mount.pitch);
    if (rl_robotfile_save(out, &mount, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    printf("{\"roll\": %.5f, \"pitch\": %.5f, \"sigma_roll\": %.5f, \"sigma_pitch\": %.5f, \"frames_used\": %d, "
           "\"frames\": %d}\n", mount.roll, mount.pitch,
           sqrt(fmax(0.0, srr / used - mount.roll * mount.roll) / used),
           sqrt(fmax(0.0, spp / used - mount.pitch * mount.pitch) / used), used, frames);
    return 0;
}
