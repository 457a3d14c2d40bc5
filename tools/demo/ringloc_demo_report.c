/* ringloc-demo-report: what the demo's robot was told, against the truth.
 *
 *   ringloc-demo-report FRAMES.txt POSES.jsonl MAP.yaml PLOT.png
 *
 * FRAMES.txt lists the frames the camera played, in order (each with its
 * NAME.yaml truth beside it); POSES.jsonl is what `ringloc monitor`
 * decoded. One message was sent per frame, so seq n belongs to frame n.
 * Prints a line per frame and a summary, and draws the trajectory
 * (estimated against true, landmarks of the map) into PLOT.png. */
#include <cairo.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_cli.h"
#include "rl_print.h"
#include "rl_site.h"
#include "rl_yaml.h"

#define MAX_FRAMES 4096

typedef struct {
    char name[256];
    double tx, ty, tyaw;       /* truth */
    int have_pose, used, status;
    double x, y, yaw, latency;
} row;

static row rows[MAX_FRAMES];

/* The number after key in a JSON line, or NaN when there is none. */
static double field(const char *line, const char *key)
{
    const char *p = strstr(line, key);
    char *end;
    double v;
    if (p == NULL)
        return NAN;
    v = strtod(p + strlen(key), &end);
    return end == p + strlen(key) ? NAN : v;
}

static int load_truth(const char *dir, row *r)
{
    char path[2048], err[512];
    rl_yaml y;
    yaml_node_t *rob;
    snprintf(path, sizeof path, "%s/%s.yaml", dir, r->name);
    if (rl_yaml_load(&y, path, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-demo-report: %s\n", err);
        return -1;
    }
    rob = rl_yaml_get(&y, rl_yaml_root(&y), "robot");
    if (rl_yaml_double(&y, rob, "x", NULL, 1, &r->tx, err, sizeof err) != RL_OK ||
        rl_yaml_double(&y, rob, "y", NULL, 1, &r->ty, err, sizeof err) != RL_OK ||
        rl_yaml_double(&y, rob, "yaw", NULL, 1, &r->tyaw, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-demo-report: %s\n", err);
        rl_yaml_free(&y);
        return -1;
    }
    rl_yaml_free(&y);
    return 0;
}

static void plot(const char *path, const rl_map *map, int n)
{
    int W = 900, H = 760, i;
    char err[1200];
    double minx = 0, maxx = 0, miny = 0, maxy = 0, s, ox, oy;
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, W, H);
    cairo_t *cr = cairo_create(surf);
    for (i = 0; i < map->count; i++) {
        if (i == 0 || map->lm[i].x < minx) minx = map->lm[i].x;
        if (i == 0 || map->lm[i].x > maxx) maxx = map->lm[i].x;
        if (i == 0 || map->lm[i].y < miny) miny = map->lm[i].y;
        if (i == 0 || map->lm[i].y > maxy) maxy = map->lm[i].y;
    }
    minx -= 0.4; maxx += 0.4; miny -= 0.4; maxy += 0.4;
    s = fmin((W - 80) / (maxx - minx), (H - 120) / (maxy - miny));
    ox = 40 - minx * s;
    oy = H - 80 + miny * s; /* map y up, image y down */
#define PX(x) (ox + (x) * s)
#define PY(y) (oy - (y) * s)
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0.75, 0.75, 0.75);
    for (i = 0; i < map->count; i++) {
        char id[16];
        cairo_new_path(cr);
        cairo_arc(cr, PX(map->lm[i].x), PY(map->lm[i].y), map->diameter / 2 * s, 0, 2 * M_PI);
        cairo_fill(cr);
        snprintf(id, sizeof id, "%d", map->lm[i].id);
        cairo_move_to(cr, PX(map->lm[i].x) + 12, PY(map->lm[i].y) - 12);
        cairo_show_text(cr, id);
    }
    cairo_set_line_width(cr, 2.0);
    cairo_set_source_rgb(cr, 0.1, 0.4, 0.95); /* truth: blue line */
    for (i = 0; i < n; i++) {
        if (i == 0 || strncmp(rows[i].name, rows[i - 1].name, 4) != 0)
            cairo_move_to(cr, PX(rows[i].tx), PY(rows[i].ty));
        else
            cairo_line_to(cr, PX(rows[i].tx), PY(rows[i].ty));
    }
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.9, 0.15, 0.1); /* estimates: red crosses and headings */
    for (i = 0; i < n; i++) {
        if (!rows[i].have_pose)
            continue;
        cairo_move_to(cr, PX(rows[i].x) - 5, PY(rows[i].y) - 5);
        cairo_line_to(cr, PX(rows[i].x) + 5, PY(rows[i].y) + 5);
        cairo_move_to(cr, PX(rows[i].x) - 5, PY(rows[i].y) + 5);
        cairo_line_to(cr, PX(rows[i].x) + 5, PY(rows[i].y) - 5);
        cairo_move_to(cr, PX(rows[i].x), PY(rows[i].y));
        cairo_line_to(cr, PX(rows[i].x + 0.12 * cos(rows[i].yaw)), PY(rows[i].y + 0.12 * sin(rows[i].yaw)));
    }
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_font_size(cr, 16);
    cairo_move_to(cr, 40, 30);
    cairo_show_text(cr, "ringloc demo: poses sent to the robot (red) against the true path (blue)");
    cairo_set_font_size(cr, 12);
    cairo_move_to(cr, 40, H - 30);
    cairo_show_text(cr, "grey: ceiling landmarks of the map with their ids; x right, y up, metres");
    cairo_destroy(cr);
    if (rl_print_surface_png(surf, path, err, sizeof err) != RL_OK)
        fprintf(stderr, "ringloc-demo-report: %s\n", err);
}

/* The frames FRAMES.txt lists, each with its truth; their count, or -1
 * (the line printed). */
static int read_frames(const char *path)
{
    FILE *f;
    char line[1024], dir[1024];
    const char *slash = strrchr(path, '/');
    int n = 0;
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) : 1, slash ? path : ".");
    if ((f = fopen(path, "r")) == NULL) {
        fprintf(stderr, "ringloc-demo-report: %s: cannot open\n", path);
        return -1;
    }
    while (n < MAX_FRAMES && fgets(line, sizeof line, f)) {
        char *b = strrchr(line, '/');
        line[strcspn(line, "\r\n")] = '\0';
        if (!line[0])
            continue;
        snprintf(rows[n].name, sizeof rows[n].name, "%.200s", b ? b + 1 : line);
        rows[n].name[strcspn(rows[n].name, ".")] = '\0';
        if (b) { *b = '\0'; snprintf(dir, sizeof dir, "%s", line); }
        if (load_truth(dir, &rows[n]) != 0) {
            fclose(f);
            return -1;
        }
        n++;
    }
    fclose(f);
    return n;
}

/* What monitor decoded: seq n's pose or status into frame n. 0, or -1. */
static int read_poses(const char *path, int n)
{
    FILE *f;
    char line[1024];
    if ((f = fopen(path, "r")) == NULL) {
        fprintf(stderr, "ringloc-demo-report: %s: cannot open\n", path);
        return -1;
    }
    while (fgets(line, sizeof line, f)) {
        double s = field(line, "\"seq\": ");
        int seq = s >= 0 && s < n ? (int)s : -1;
        if (seq < 0)
            continue;
        if (strstr(line, "\"type\": \"pose\"")) {
            rows[seq].have_pose = 1;
            rows[seq].x = field(line, "\"x\": ");
            rows[seq].y = field(line, "\"y\": ");
            rows[seq].yaw = field(line, "\"yaw\": ");
            rows[seq].used = (int)field(line, "\"landmarks_used\": ");
            rows[seq].latency = field(line, "\"latency_ms\": ");
        } else {
            rows[seq].status = (int)field(line, "\"reason\": ");
        }
    }
    fclose(f);
    return 0;
}

/* A line per frame and the summary; the number of poses. */
static int print_report(int n)
{
    int i, poses = 0, statuses = 0, used = 0;
    double pos = 0, yaw = 0, worst = 0, lat = 0;
    printf("%-16s %4s %9s %9s %8s   %9s %9s %8s   %7s %7s\n", "frame", "lms", "x", "y", "yaw_deg",
           "true_x", "true_y", "true_deg", "err_mm", "err_deg");
    for (i = 0; i < n; i++) {
        row *r = &rows[i];
        if (r->have_pose) {
            double e = hypot(r->x - r->tx, r->y - r->ty), ey = fabs(remainder(r->yaw - r->tyaw, 2 * M_PI));
            printf("%-16s %4d %9.3f %9.3f %8.2f   %9.3f %9.3f %8.2f   %7.1f %7.3f\n", r->name, r->used,
                   r->x, r->y, r->yaw * 180 / M_PI, r->tx, r->ty, r->tyaw * 180 / M_PI, e * 1000,
                   ey * 180 / M_PI);
            poses++;
            used += r->used;
            pos += e;
            yaw += ey;
            lat += r->latency;
            if (e > worst)
                worst = e;
        } else {
            printf("%-16s  no pose (status reason %d)\n", r->name, r->status);
            statuses++;
        }
    }
    printf("\n%d frames: %d poses, %d without a pose; %.1f landmarks per pose\n", n, poses, statuses,
           poses ? (double)used / poses : 0.0);
    if (poses)
        printf("mean position error %.1f mm (worst %.1f mm), mean yaw error %.3f deg, mean latency %.1f ms\n",
               1000 * pos / poses, 1000 * worst, yaw / poses * 180 / M_PI, lat / poses);
    printf("(the paper's system: 20.2 mm and 0.5 deg)\n");
    return poses;
}

int main(int argc, char **argv)
{
    static rl_site site;
    rl_site_files files;
    char err[768];
    int n, poses;
    rl_cli_start("ringloc-demo-report");
    if (argc != 5) {
        fprintf(stderr, "usage: ringloc-demo-report FRAMES.txt POSES.jsonl MAP.yaml PLOT.png\n");
        return 2;
    }
    if ((n = read_frames(argv[1])) < 0)
        return 1;
    rl_site_files_init(&files);
    files.map = argv[3];
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-demo-report: %s\n", err);
        return 1;
    }
    if (read_poses(argv[2], n) != 0)
        return 1;
    poses = print_report(n);
    plot(argv[4], &site.map, n);
    return poses == n ? 0 : 1;
}
