/* ringloc calibrate-mount: the camera's fixed tilt on the robot, from
 * recorded frames with three or more landmarks. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_pngrun.h"
#include "rl_robotfile.h"
#include "rl_site.h"

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

/* The tilt each usable frame gives, summed. */
typedef struct {
    const char *cmd;
    int frames, total, used;
    double sr, sp, srr, spp;
} tilt_sums;

static rl_err tilt_put(void *ctx, const rl_run_report *rep)
{
    tilt_sums *t = (tilt_sums *)ctx;
    const rl_pose *pose = rep->pose;
    if (rep->pose_err == RL_OK && pose->fit_valid) {
        t->sr += pose->fit_roll;
        t->sp += pose->fit_pitch;
        t->srr += pose->fit_roll * pose->fit_roll;
        t->spp += pose->fit_pitch * pose->fit_pitch;
        t->used++;
    }
    if (isatty(2) && ++t->frames % 10 == 0)
        fprintf(stderr, "ringloc %s: %d of %d frames\r", t->cmd, t->frames, t->total);
    return RL_OK;
}

typedef struct {
    rl_site_files files;
    const char *out;
} mount_args;

/* The options; 0 to go on, else the exit code (--help: 0 with *done). */
static int parse_args(const char *C, int argc, char **argv, mount_args *a, int *done)
{
    static const struct option opts[] = {
        {"camera", required_argument, 0, 'c'}, {"map", required_argument, 0, 'm'},
        {"robot", required_argument, 0, 'r'}, {"out", required_argument, 0, 'o'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    int c;
    *done = 0;
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        switch (c) {
        case 'c': a->files.calibration = optarg; break;
        case 'm': a->files.map = optarg; break;
        case 'r': a->files.robot = optarg; break;
        case 'o': a->out = optarg; break;
        case 'h': fputs(mount_help, stdout); *done = 1; return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (!a->files.calibration || !a->files.map || !a->files.robot || !a->out)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--camera, --map, --robot and --out are required (see --help)");
    if (optind >= argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "no frames given (see --help)");
    return 0;
}

/* The mean tilt into mount, written to out with its JSON line. */
static int write_tilt(const char *C, const tilt_sums *t, rl_mount mount, const char *map_path, const char *out)
{
    char err[512];
    if (t->used < 3)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%d of %d frames show three or more landmarks of %s; at least 3 "
                           "such frames are needed", t->used, t->total, map_path);
    mount.roll = t->sr / t->used;
    mount.pitch = t->sp / t->used;
    if (!(fabs(mount.roll) < 0.5 && fabs(mount.pitch) < 0.5))
        return rl_cli_fail(C, RL_EXIT_FAIL, "the tilt found (roll %.3f, pitch %.3f rad) is beyond 0.5 rad: "
                           "check the camera calibration and the map", mount.roll, mount.pitch);
    if (rl_robotfile_save(out, &mount, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    printf("{\"roll\": %.5f, \"pitch\": %.5f, \"sigma_roll\": %.5f, \"sigma_pitch\": %.5f, \"frames_used\": %d, "
           "\"frames\": %d}\n", mount.roll, mount.pitch,
           sqrt(fmax(0.0, t->srr / t->used - mount.roll * mount.roll) / t->used),
           sqrt(fmax(0.0, t->spp / t->used - mount.pitch * mount.pitch) / t->used), t->used, t->total);
    return 0;
}

int rl_cmd_calibrate_mount(int argc, char **argv)
{
    const char *C = "calibrate-mount";
    static rl_site site;
    mount_args a;
    tilt_sums t;
    rl_mount mount;
    rl_recog_config cfg;
    rl_pngrun pr;
    char err[768];
    int code, done;

    memset(&a, 0, sizeof a);
    memset(&t, 0, sizeof t);
    rl_site_files_init(&a.files);
    if ((code = parse_args(C, argc, argv, &a, &done)) != 0 || done)
        return code;
    rl_recog_defaults(&cfg);
    if (rl_site_load(&site, &a.files, err, sizeof err) != RL_OK || rl_site_prepare(&site, &cfg, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    /* the tilt is measured from a mount taken as vertical */
    mount = site.mount;
    site.mount.roll = site.mount.pitch = 0;
    t.cmd = C;
    t.total = argc - optind;
    rl_pngrun_defaults(&pr, C);
    pr.run.alone = 1;
    pr.put = tilt_put;
    pr.ctx = &t;
    pr.bad_suffix = "; left out";
    (void)rl_pngrun_files(&pr, &site, argv + optind, argc - optind);
    rl_site_free(&site);
    return write_tilt(C, &t, mount, a.files.map, a.out);
}
