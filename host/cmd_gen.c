/* ringloc gen: print-ready landmarks. */
#include <getopt.h>
#include <stdio.h>
#include <string.h>
#include "rl_cli.h"
#include "rl_cmd.h"
#include "rl_print.h"
#include "rl_site.h"

static const char *gen_help =
    "usage: ringloc gen [--family ring5] (--id ID[,ID...] | --map MAP.yaml)\n"
    "                   [--diameter 0.21] [--paper a4] [--margin 5] [--pdf FILE] [--svg FILE]\n"
    "                   [--png FILE --px N]\n\n"
    "Print-ready landmarks per docs/landmark-spec.md: one landmark per page at\n"
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

/* What the command line asks for. */
typedef struct {
    const char *family, *ids_arg, *map_path; /* --family, --id, --map */
    const char *paper_name;                  /* NULL: the first the landmark fits */
    const char *pdf, *svg, *png;             /* what to write (NULL: not that) */
    double diameter;                         /* --diameter (default 0.21; a map's) */
    int have_diameter;                       /* --diameter given */
    double margin;                           /* --margin, mm */
    int px;                                  /* --px (default 400) */
} gen_opts;

static void gen_opts_defaults(gen_opts *o)
{
    memset(o, 0, sizeof *o);
    o->diameter = 0.21;
    o->margin = RL_PRINT_MARGIN_MM;
    o->px = 400;
}

/* The landmarks to draw: their family, ids and (from a map) places. */
typedef struct {
    rl_family fam;
    int ids[RL_MAX_MAP_LANDMARKS];
    int n;
    const rl_map_landmark *lm; /* NULL: no map */
} gen_set;

/* The command line into o: -1 to go on, or the exit code (0 after --help). */
static int gen_args(const char *C, int argc, char **argv, gen_opts *o)
{
    static const struct option opts[] = {
        {"family", required_argument, 0, 'f'}, {"id", required_argument, 0, 'i'},
        {"map", required_argument, 0, 'm'},    {"diameter", required_argument, 0, 'd'},
        {"paper", required_argument, 0, 'p'},  {"pdf", required_argument, 0, 'P'},
        {"svg", required_argument, 0, 'S'},    {"png", required_argument, 0, 'N'},
        {"px", required_argument, 0, 'x'},     {"margin", required_argument, 0, 'M'},
        {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    int c, ok;
    gen_opts_defaults(o);
    optind = 1;
    while ((c = rl_cli_getopt(C, argc, argv, opts)) != -1) {
        ok = 1;
        switch (c) {
        case 'f': o->family = optarg; break;
        case 'i': o->ids_arg = optarg; break;
        case 'm': o->map_path = optarg; break;
        case 'd': ok = o->have_diameter = rl_cli_double(C, "--diameter", optarg, 0.001, 5.0, &o->diameter); break;
        case 'p': o->paper_name = optarg; break;
        case 'M': ok = rl_cli_double(C, "--margin", optarg, 0, 50, &o->margin); break;
        case 'P': o->pdf = optarg; break;
        case 'S': o->svg = optarg; break;
        case 'N': o->png = optarg; break;
        case 'x': ok = rl_cli_int(C, "--px", optarg, 16, 8000, &o->px); break;
        case 'h': fputs(gen_help, stdout); return 0;
        default: return RL_EXIT_USAGE; /* rl_cli_getopt said why */
        }
        if (!ok)
            return RL_EXIT_USAGE;
    }
    if (optind < argc)
        return rl_cli_fail(C, RL_EXIT_USAGE, "unexpected argument '%s'", argv[optind]);
    if ((o->ids_arg == NULL) == (o->map_path == NULL))
        return rl_cli_fail(C, RL_EXIT_USAGE, "give either --id or --map (see --help)");
    if (!o->pdf && !o->svg && !o->png)
        return rl_cli_fail(C, RL_EXIT_USAGE, "nothing to write: give --pdf, --svg or --png");
    return -1;
}

/* --map: every landmark of the map, its family and (unless --diameter)
 * its diameter. */
static int set_from_map(const char *C, gen_opts *o, gen_set *g)
{
    static rl_site site;
    rl_site_files files;
    char err[768];
    int i;
    rl_site_files_init(&files);
    files.map = o->map_path;
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    g->fam = site.map.family;
    if (o->family != NULL && strcmp(o->family, "") != 0) {
        rl_family f2;
        if (rl_family_parse(o->family, &f2) != RL_OK || f2.bits != g->fam.bits)
            return rl_cli_fail(C, RL_EXIT_USAGE, "--family %s disagrees with %s (ring%d)", o->family,
                               o->map_path, g->fam.bits);
    }
    if (!o->have_diameter)
        o->diameter = site.map.diameter;
    g->n = site.map.count;
    for (i = 0; i < g->n; i++)
        g->ids[i] = site.map.lm[i].id;
    g->lm = site.map.lm;
    return 0;
}

/* --id LIST: ids of --family (default ring5). */
static int set_from_ids(const char *C, const gen_opts *o, gen_set *g)
{
    int i;
    if (rl_family_parse(o->family ? o->family : "ring5", &g->fam) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--family: '%s' is not a family (ring2 .. ring%d)", o->family,
                           RL_MAX_BITS);
    if (o->ids_arg[0] == '\0')
        return rl_cli_fail(C, RL_EXIT_USAGE, "--id: no ids given");
    if (!rl_cli_ints(C, "--id", o->ids_arg, "a list of ids", g->ids, RL_MAX_MAP_LANDMARKS, &g->n))
        return RL_EXIT_USAGE;
    for (i = 0; i < g->n; i++)
        if (!rl_family_valid(&g->fam, g->ids[i]))
            return rl_cli_fail(C, RL_EXIT_USAGE, "--id: %d is not in ring%d (valid ids 1 .. %d)", g->ids[i],
                               g->fam.bits, rl_family_count(&g->fam));
    g->lm = NULL;
    return 0;
}

/* The paper for --pdf and --svg: --paper, or the first the landmark fits
 * within the margins; 0, or the exit code when it does not fit. */
static int gen_paper(const char *C, const gen_opts *o, const rl_paper **paper)
{
    double d = o->diameter, m = o->margin;
    const rl_paper *p = o->paper_name ? rl_paper_find(o->paper_name) : NULL, *fits = rl_paper_fitting(d, m);
    *paper = p;
    if (!o->pdf && !o->svg)
        return 0;
    if (p == NULL && fits == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--diameter: %.3f m fits no paper (%s) within %g mm "
                           "margins", d, rl_paper_names(), m);
    if (p == NULL)
        *paper = p = fits;
    if (d < RL_PRINT_MIN_DIAMETER)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--diameter: %.3f m is below the smallest printable, "
                           "%.3f m", d, RL_PRINT_MIN_DIAMETER);
    if (d > rl_print_max_diameter(p, m) + 1e-9)
        return rl_cli_fail(C, RL_EXIT_USAGE,
                           "--diameter: %.3f m does not fit %s paper within %g mm margins: the "
                           "largest that does is %.3f m%s%s", d, p->name, m, rl_print_max_diameter(p, m),
                           fits ? "; or --paper " : "", fits ? fits->name : "");
    if (1.25 * d > p->w_mm / 1000.0)
        fprintf(stderr, "ringloc gen: note: the white quiet zone (1.25 x diameter = %.0f mm) is wider "
                        "than %s paper; hang it on a light ceiling or leave white around it\n",
                1250.0 * d, p->name);
    return 0;
}

/* The PDF, the SVGs and the PNGs asked for. */
static int gen_write(const char *C, const gen_opts *o, const gen_set *g, const rl_paper *paper)
{
    char err[512], name[1024];
    int i;
    if (o->pdf && rl_print_pdf(o->pdf, paper, &g->fam, g->ids, g->lm, g->n, o->diameter, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    for (i = 0; o->svg && i < g->n; i++) {
        per_id_name(name, sizeof name, o->svg, g->ids[i], g->n > 1);
        if (rl_print_svg(name, paper, &g->fam, g->ids[i], g->lm ? &g->lm[i] : NULL, o->diameter, err,
                         sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    for (i = 0; o->png && i < g->n; i++) {
        per_id_name(name, sizeof name, o->png, g->ids[i], g->n > 1);
        if (rl_print_png(name, &g->fam, g->ids[i], o->px, err, sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    return 0;
}

int rl_cmd_gen(int argc, char **argv)
{
    const char *C = "gen";
    static gen_opts o;
    static gen_set g;
    const rl_paper *paper;
    int r;

    if ((r = gen_args(C, argc, argv, &o)) >= 0)
        return r;
    if (o.paper_name && rl_paper_find(o.paper_name) == NULL)
        return rl_cli_fail(C, RL_EXIT_USAGE, "--paper: unknown paper '%s' (%s)", o.paper_name,
                           rl_paper_names());
    if ((r = o.map_path ? set_from_map(C, &o, &g) : set_from_ids(C, &o, &g)) != 0 ||
        (r = gen_paper(C, &o, &paper)) != 0 || (r = gen_write(C, &o, &g, paper)) != 0)
        return r;
    fprintf(stderr, "ringloc gen: %d landmark%s of ring%d, %.0f mm%s%s%s%s%s%s%s%s\n", g.n,
            g.n == 1 ? "" : "s", g.fam.bits, o.diameter * 1000, o.pdf || o.svg ? " on " : "",
            o.pdf || o.svg ? paper->name : "", o.pdf ? " -> " : "", o.pdf ? o.pdf : "",
            o.svg ? " -> " : "", o.svg ? o.svg : "", o.png ? " -> " : "", o.png ? o.png : "");
    return 0;
}
