/* ringloc gen: print-ready landmarks. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_mapfile.h"
#include "rl_print.h"

static const char *gen_help =
    "usage: ringloc gen [--family ring5] (--id ID[,ID...] | --map MAP.yaml)\n"
    "                   [--diameter 0.21] [--paper a4] [--margin 5] [--pdf FILE] [--svg FILE]\n"
    "                   [--png FILE --px N]\n\n"
    "Print-ready landmarks per shared/landmark-spec.md: one landmark per page at\n"
    "its exact printed diameter, crop marks, and the id in small type.\n\n"
    "  --family NAME   ring2 .. ring8 (default ring5; a map's family with --map)\n"
    "  --id LIST       landmark ids, comma-separated (1 .. 2^N-2)\n"
    "  --map FILE      every landmark of a map YAML (family and diameter from it)\n"
    "  --diameter M    printed outer diameter in metres (default 0.21)\n"
    "  --paper NAME    a4, letter, a3, tabloid (default: the first the landmark fits)\n"
    "  --margin MM     the printer's unprintable border: nothing is drawn nearer an\n"
    "                  edge (default 5)\n"
    "  --pdf FILE      all landmarks in one PDF, a page each\n"
    "  --svg FILE      SVG page (FILE-ID.svg per landmark when there are several)\n"
    "  --png FILE      PNG for tests, landmark --px pixels across (default 400)\n"
    "  --px N          PNG landmark diameter in pixels (16 .. 8000)\n";

/* "out.svg" + 25 -> "out-25.svg" */
static void per_id_name(char *buf, size_t len, const char *path, int id, int several)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    if (!several) {
        snprintf(buf, len, "%s", path);
        return;
    }
    if (dot == NULL || (slash != NULL && dot < slash))
        snprintf(buf, len, "%s-%d", path, id);
    else
        snprintf(buf, len, "%.*s-%d%s", (int)(dot - path), path, id, dot);
}

int rl_cmd_gen(int argc, char **argv)
{
    static const struct option opts[] = {
        {"family", required_argument, 0, 'f'}, {"id", required_argument, 0, 'i'},
        {"map", required_argument, 0, 'm'},    {"diameter", required_argument, 0, 'd'},
        {"paper", required_argument, 0, 'p'},  {"pdf", required_argument, 0, 'P'},
        {"svg", required_argument, 0, 'S'},    {"png", required_argument, 0, 'N'},
        {"px", required_argument, 0, 'x'},     {"margin", required_argument, 0, 'M'},
        {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    const char *C = "gen", *family = NULL, *ids_arg = NULL, *map_path = NULL;
    const char *paper_name = NULL, *pdf = NULL, *svg = NULL, *png = NULL;
    double diameter = 0.21, margin = RL_PRINT_MARGIN_MM;
    int have_diameter = 0, px = 400, c, i, n = 0;
    static int ids[RL_MAX_MAP_LANDMARKS];
    static rl_map map;
    rl_family fam;
    const rl_paper *paper;
    char err[512], name[1024];

    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        switch (c) {
        case 'f': family = optarg; break;
        case 'i': ids_arg = optarg; break;
        case 'm': map_path = optarg; break;
        case 'd':
            if (!rl_cli_double(C, "--diameter", optarg, 0.001, 5.0, &diameter))
                return RL_EXIT_USAGE;
            have_diameter = 1;
            break;
        case 'p': paper_name = optarg; break;
        case 'M':
            if (!rl_cli_double(C, "--margin", optarg, 0, 50, &margin))
                return RL_EXIT_USAGE;
            break;
        case 'P': pdf = optarg; break;
        case 'S': svg = optarg; break;
        case 'N': png = optarg; break;
        case 'x':
            if (!rl_cli_int(C, "--px", optarg, 16, 8000, &px))
                return RL_EXIT_USAGE;
            break;
        case 'h': fputs(gen_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
    }
    if (optind < argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "unexpected argument '%s'", argv[optind]);
    if ((ids_arg == NULL) == (map_path == NULL))
        return rl_cli_fail(C, RL_EXIT_USAGE, "give either --id or --map (see --help)");
    if (!pdf && !svg && !png)
        return rl_cli_fail(C, RL_EXIT_USAGE, "nothing to write: give --pdf, --svg or --png");
    paper = paper_name ? rl_paper_find(paper_name) : NULL;
    if (paper_name && paper == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--paper: unknown paper '%s' (%s)", paper_name,
                           rl_paper_names());

    if (map_path != NULL) {
        if (rl_mapfile_load(map_path, &map, err, sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
        fam = map.family;
        if (family != NULL && strcmp(family, "") != 0) {
            rl_family f2;
            if (rl_family_parse(family, &f2) != RL_OK || f2.bits != fam.bits)
                return rl_cli_fail(C, RL_EXIT_USAGE, "--family %s disagrees with %s (ring%d)",
                                   family, map_path, fam.bits);
        }
        if (!have_diameter)
            diameter = map.diameter;
        n = map.count;
        for (i = 0; i < n; i++)
            ids[i] = map.lm[i].id;
        if (n == 0)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s: the map has no landmarks", map_path);
    } else {
        const char *s = ids_arg;
        rl_err e = rl_family_parse(family ? family : "ring5", &fam);
        if (e != RL_OK)
            return rl_cli_fail(C, RL_EXIT_USAGE, "--family: '%s' is not a family (ring2 .. ring%d)",
                               family, RL_MAX_BITS);
        while (*s) {
            char *end;
            long v = strtol(s, &end, 10);
            if (end == s || (*end != ',' && *end != '\0') || (*end == ',' && end[1] == '\0'))
                return rl_cli_fail(C, RL_EXIT_USAGE, "--id: '%s' is not a list of ids", ids_arg);
            if (!rl_family_valid(&fam, (int)v) || v != (int)v)
                return rl_cli_fail(C, RL_EXIT_USAGE, "--id: %ld is not in ring%d (valid ids 1 .. %d)",
                                   v, fam.bits, rl_family_count(&fam));
            if (n == RL_MAX_MAP_LANDMARKS)
                return rl_cli_fail(C, RL_EXIT_USAGE, "--id: more than %d ids", RL_MAX_MAP_LANDMARKS);
            ids[n++] = (int)v;
            s = *end ? end + 1 : end;
        }
        if (n == 0)
            return rl_cli_fail(C, RL_EXIT_USAGE, "--id: no ids given");
    }
    if ((pdf || svg) && paper == NULL && (paper = rl_paper_fitting(diameter, margin)) == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--diameter: %.3f m fits no paper (%s) within %g mm "
                           "margins", diameter, rl_paper_names(), margin);
    if ((pdf || svg) && paper == NULL)
        paper = rl_paper_find("a4");
    if ((pdf || svg) && diameter < RL_PRINT_MIN_DIAMETER)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--diameter: %.3f m is below the smallest printable, "
                           "%.3f m", diameter, RL_PRINT_MIN_DIAMETER);
    if ((pdf || svg) && diameter > rl_print_max_diameter(paper, margin) + 1e-9)
        return rl_cli_fail(C, RL_EXIT_USAGE,
                           "--diameter: %.3f m does not fit %s paper within %g mm margins: the "
                           "largest that does is %.3f m%s%s", diameter, paper->name, margin,
                           rl_print_max_diameter(paper, margin),
                           rl_paper_fitting(diameter, margin) ? "; or --paper " : "",
                           rl_paper_fitting(diameter, margin) ? rl_paper_fitting(diameter, margin)->name : "");
    if ((pdf || svg) && 1.25 * diameter > paper->w_mm / 1000.0)
        fprintf(stderr, "ringloc gen: note: the white quiet zone (1.25 x diameter = %.0f mm) is wider "
                        "than %s paper; hang it on a light ceiling or leave white around it\n",
                1250.0 * diameter, paper->name);

    if (pdf && rl_print_pdf(pdf, paper, &fam, ids, map_path ? map.lm : NULL, n, diameter, err,
                            sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    for (i = 0; svg && i < n; i++) {
        per_id_name(name, sizeof name, svg, ids[i], n > 1);
        if (rl_print_svg(name, paper, &fam, ids[i], map_path ? &map.lm[i] : NULL, diameter, err,
                         sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    for (i = 0; png && i < n; i++) {
        per_id_name(name, sizeof name, png, ids[i], n > 1);
        if (rl_print_png(name, &fam, ids[i], px, err, sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    fprintf(stderr, "ringloc gen: %d landmark%s of ring%d, %.0f mm%s%s%s%s%s%s%s%s\n", n,
            n == 1 ? "" : "s", fam.bits, diameter * 1000, pdf || svg ? " on " : "",
            pdf || svg ? paper->name : "", pdf ? " -> " : "", pdf ? pdf : "",
            svg ? " -> " : "", svg ? svg : "", png ? " -> " : "", png ? png : "");
    return 0;
}
