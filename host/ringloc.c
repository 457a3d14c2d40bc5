/* ringloc: the host command line. One binary, one subcommand per job;
 * every subcommand feeds files through the same core as the firmware. */
#include <stdio.h>
#include <string.h>
#include "rl_cli.h"
#include "rl_cmd.h"

#ifndef RL_HAVE_SURVEY
static int no_survey(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return rl_cli_fail("survey", RL_EXIT_USAGE, "not in this build (a firmware-only build: the survey runs on a "
                       "desktop, `make host`)");
}
#define rl_cmd_survey no_survey
#endif

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} command;

static const command commands[] = {
    {"run", rl_cmd_run, "the firmware: camera -> pose frames on the serial line"},
    {"monitor", rl_cmd_monitor, "decode pose and status frames (controller side)"},
    {"fuse", rl_cmd_fuse, "odometry and pose frames fused (rl_fuse), the pose at a rate as JSON lines"},
    {"gen", rl_cmd_gen, "print-ready landmarks (PDF, SVG, PNG) for ids or a whole map"},
    {"plan", rl_cmd_plan, "choose family, diameter and grid pitch for a site; write a map"},
    {"site-check", rl_cmd_sitecheck, "false landmarks and recognition rates on photos of your ceiling"},
    {"detect", rl_cmd_detect, "recognize landmarks in PNG images (JSON lines)"},
    {"locate", rl_cmd_locate, "the robot's pose from PNG images (JSON lines)"},
    {"calibrate-offsets", rl_cmd_calibrate_offsets, "fit the paper's pixel-to-offset maps from a known pose"},
    {"calibrate-mount", rl_cmd_calibrate_mount, "the camera's fixed tilt on the robot, from recorded frames"},
    {"survey", rl_cmd_survey, "build the map from recorded frames (no tape measure)"},
};

static void usage(FILE *out)
{
    size_t i;
    fprintf(out, "usage: ringloc COMMAND [OPTIONS]\n\n"
                 "Self-localization from ring-coded ceiling landmarks.\n\ncommands:\n");
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(out, "  %-18s %s\n", commands[i].name, commands[i].summary);
    fprintf(out, "\n'ringloc COMMAND --help' describes a command's options.\n");
}

int main(int argc, char **argv)
{
    size_t i;
    rl_cli_start("ringloc");
    if (argc < 2) {
        usage(stderr);
        return RL_EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return rl_cli_finish(NULL, 0);
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("ringloc %s\n", RL_VERSION);
        return rl_cli_finish(NULL, 0);
    }
    /* every command's results reach the exit status, standard output's too */
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (strcmp(argv[1], commands[i].name) == 0)
            return rl_cli_finish(commands[i].name, commands[i].run(argc - 1, argv + 1));
    fprintf(stderr, "ringloc: unknown command '%s' (try 'ringloc --help')\n", argv[1]);
    return RL_EXIT_USAGE;
}
