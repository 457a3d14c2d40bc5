/* render_set: each set's scenes (render_set.h). */
#include "render_set.h"

#include <math.h>
#include <string.h>
#include "render_random.h"

static const char *set_names[RENDER_SET_COUNT] = {"clean", "cluttered", "glare", "border", "clutter_only",
                                                  "dim", "blur", "motion", "illum", "degraded", "lens", "path",
                                                  "moving", "heldout", "repeats"};

int render_set_by_name(const char *name)
{
    int i;
    for (i = 0; i < RENDER_SET_COUNT; i++)
        if (i != RENDER_SET_PATH && strcmp(name, set_names[i]) == 0)
            return i;
    return -1;
}

void render_set_add_landmark(render_scene *s, double x, double y, int id, double drop)
{
    int n = s->n;
    double R = s->diameter / 2, rot = render_random_uniform(-0.15, 0.15) + (render_random_next() & 1 ? M_PI / 2 : 0);
    double a = R, b = R * 1.414;
    if (s->sheet_w > 0) { /* a paper size, the landmark in its middle */
        a = 0.5 * s->sheet_w;
        b = 0.5 * s->sheet_h;
    }
    /* printed on a sheet, rotated as taped */
    render_scene_add(s, RENDER_OBJ_PAPER, x, y, rot, a, b, 0);
    render_scene_add(s, RENDER_OBJ_LANDMARK, x, y, s->twin ? rot : 0, R, R, id);
    for (; n < s->n; n++) /* the sheet hangs with it */
        s->obj[n].drop = drop;
}

/* How far the landmarks with this id hang below the ceiling (--lower). */
static double lowered(const render_scene *s, int id)
{
    return id >= 0 && id < RL_MAX_IDS ? s->lower[id] : 0.0;
}

static void add_clutter(render_scene *s, double x, double y, int ring_like)
{
    int k = ring_like ? (int)(render_random_next() % 3) : (int)(render_random_next() % 7);
    double rot = render_random_uniform(0, M_PI);
    static const render_obj_kind kinds[] = {RENDER_OBJ_SPEAKER, RENDER_OBJ_DOWNLIGHT, RENDER_OBJ_SMOKE, RENDER_OBJ_SPRINKLER,
                                     RENDER_OBJ_VENT, RENDER_OBJ_BOX, RENDER_OBJ_EXIT};
    switch (kinds[k]) {
    case RENDER_OBJ_SPEAKER: render_scene_add(s, RENDER_OBJ_SPEAKER, x, y, 0, render_random_uniform(0.08, 0.14), 0, 0); break;
    case RENDER_OBJ_DOWNLIGHT: render_scene_add(s, RENDER_OBJ_DOWNLIGHT, x, y, 0, render_random_uniform(0.07, 0.10), 0, 0); break;
    case RENDER_OBJ_SMOKE: render_scene_add(s, RENDER_OBJ_SMOKE, x, y, 0, render_random_uniform(0.05, 0.07), 0, 0); break;
    case RENDER_OBJ_SPRINKLER: render_scene_add(s, RENDER_OBJ_SPRINKLER, x, y, 0, render_random_uniform(0.02, 0.035), 0, 0); break;
    case RENDER_OBJ_VENT: render_scene_add(s, RENDER_OBJ_VENT, x, y, rot, render_random_uniform(0.12, 0.2), 0, 0); break;
    case RENDER_OBJ_BOX: render_scene_add(s, RENDER_OBJ_BOX, x, y, rot, render_random_uniform(0.05, 0.12), render_random_uniform(0.05, 0.12), 0); break;
    default: render_scene_add(s, RENDER_OBJ_EXIT, x, y, rot, 0.15, 0.08, 0); break;
    }
}

/* The site: a grid of landmarks every tile (the paper's 0.61 m), ids from
 * a fixed layout, some tiles holding lights instead. */
#define SITE_COLS 6
#define SITE_ROWS 5

static int site_id(int i, int j)
{
    /* ids 1..30 spread so that neighbours differ in several bits */
    return (int)((((unsigned)(j * SITE_COLS + i)) * 7u) % 30u) + 1;
}

/* Where the site's landmarks hang (render_set_site_layout). */
static double site_xy[SITE_ROWS * SITE_COLS][2];

void render_set_site_layout(double tile, int irregular, int move_id, double mdx, double mdy)
{
    uint64_t st = 0x2545F4914F6CDD1Dull;
    double cx = SITE_COLS * tile / 2, cy = SITE_ROWS * tile / 2, th = irregular ? 0.087 : 0;
    int i, j;
    for (j = 0; j < SITE_ROWS; j++)
        for (i = 0; i < SITE_COLS; i++) {
            double x = (i + 0.5) * tile, y = (j + 0.5) * tile, *p = site_xy[j * SITE_COLS + i];
            if (irregular) {
                double r, a;
                st ^= st << 13, st ^= st >> 7, st ^= st << 17;
                r = 0.15 * sqrt((double)(st >> 11) / 9007199254740992.0);
                st ^= st << 13, st ^= st >> 7, st ^= st << 17;
                a = 2 * M_PI * (double)(st >> 11) / 9007199254740992.0;
                x += r * cos(a);
                y += r * sin(a);
            }
            p[0] = cx + cos(th) * (x - cx) - sin(th) * (y - cy);
            p[1] = cy + sin(th) * (x - cx) + cos(th) * (y - cy);
            if (site_id(i, j) == move_id) {
                p[0] += mdx;
                p[1] += mdy;
            }
        }
}

static void site_scene(render_scene *s, render_set kind)
{
    int i, j;
    s->tile_px = s->tile_py = 0;
    for (j = -1; j <= SITE_ROWS; j++)
        for (i = -1; i <= SITE_COLS; i++) {
            double x = (i + 0.5) * s->tile, y = (j + 0.5) * s->tile;
            int inside = i >= 0 && j >= 0 && i < SITE_COLS && j < SITE_ROWS;
            if (inside)
                render_set_add_landmark(s, site_xy[j * SITE_COLS + i][0], site_xy[j * SITE_COLS + i][1], site_id(i, j),
                                        lowered(s, site_id(i, j)));
            else if ((i + j) % 3 == 0)
                render_scene_add(s, RENDER_OBJ_LIGHT, x, y, 0, 0.29, 0.29, 0);
            else if ((i * 7 + j) % 5 == 0 && kind == RENDER_SET_PATH)
                add_clutter(s, x + 0.1, y - 0.05, 0);
        }
}

void render_set_site_map(const render_scene *s, rl_map *map)
{
    int a, b;
    map->family = s->fam;
    map->diameter = s->diameter;
    map->ceiling_height = s->ceiling_height;
    map->count = 0;
    for (b = 0; b < SITE_ROWS; b++)
        for (a = 0; a < SITE_COLS; a++) {
            rl_map_landmark *lm = &map->lm[map->count++];
            lm->id = site_id(a, b);
            lm->x = site_xy[b * SITE_COLS + a][0];
            lm->y = site_xy[b * SITE_COLS + a][1];
            lm->sigma_x = lm->sigma_y = 0;
            lm->z = lowered(s, lm->id) > 0 ? s->ceiling_height - lowered(s, lm->id) : 0.0;
        }
}

/* --site-map: the map's landmarks the camera can see, and ceiling things
 * (sprinklers, smoke detectors, vents, ...) in some of the gaps between
 * them, placed by the gap's grid cell (the same in every frame). */
static const rl_map *site_map; /* NULL: the fixed site */
static double site_spacing; /* the map's landmark spacing */

static void map_scene(render_scene *s)
{
    double view = 0.5 * sqrt((double)s->cam.width * s->cam.width + (double)s->cam.height * s->cam.height) /
                  s->cam.fx * s->distance * 1.05, p = site_spacing;
    int i, j, ci = (int)floor(s->cx / p), cj = (int)floor(s->cy / p), r = (int)ceil(view / p) + 1;
    s->tile_px = s->tile_py = 0;
    for (i = 0; i < site_map->count; i++) {
        const rl_map_landmark *lm = &site_map->lm[i];
        if (hypot(lm->x - s->cx, lm->y - s->cy) < view + s->diameter)
            render_set_add_landmark(s, lm->x, lm->y, lm->id, lm->z > 0 ? s->ceiling_height - lm->z : 0.0);
    }
    for (j = cj - r; j <= cj + r; j++)
        for (i = ci - r; i <= ci + r; i++) {
            double h = render_random_hash(i, j), x = (i + 0.5) * p, y = (j + 0.5) * p;
            uint64_t keep = render_random_state();
            if (h > 0.25 || hypot(x - s->cx, y - s->cy) > view + p)
                continue;
            /* the kind and size from the cell too */
            render_random_seed((uint64_t)(h * 1e9) * 0x9E3779B97F4A7C15ull + 1);
            add_clutter(s, x, y, h < 0.08);
            render_random_seed(keep);
        }
}

void render_set_use_map(const rl_map *map)
{
    int i;
    site_map = map;
    /* the spacing: landmark 0's nearest neighbour (a planned grid is even) */
    site_spacing = HUGE_VAL;
    for (i = 1; i < map->count; i++)
        site_spacing = fmin(site_spacing, hypot(map->lm[i].x - map->lm[0].x, map->lm[i].y - map->lm[0].y));
}

static void random_scene(render_scene *s, render_set kind)
{
    int i, j, pool[RL_MAX_IDS], npool = rl_family_count(&s->fam);
    double view, reach;
    s->tile_px = render_random_uniform(0, s->tile);
    s->tile_py = render_random_uniform(0, s->tile);
    for (i = 0; i < npool; i++)
        pool[i] = i + 1;
    /* the view's half-diagonal on the ceiling: landmarks only where they
     * can be seen (ids stay unique in a frame), other things a bit beyond */
    view = 0.5 * sqrt((double)s->cam.width * s->cam.width + (double)s->cam.height * s->cam.height) /
           s->cam.fx * s->distance * 1.05;
    if (kind == RENDER_SET_LENS) {
        /* a wide-angle lens sees further than its focal length says */
        double xn, yn;
        rl_calib_unproject(&s->cam, 0, 0, &xn, &yn);
        view = hypot(xn, yn) * s->distance * 1.05;
    }
    reach = view + s->tile;
    for (j = -8; j <= 8; j++)
        for (i = -8; i <= 8; i++) {
            double x = s->tile_px + (floor(s->cx / s->tile) + i + 0.5) * s->tile;
            double y = s->tile_py + (floor(s->cy / s->tile) + j + 0.5) * s->tile;
            double p = render_random_uniform(0, 1), d = hypot(x - s->cx, y - s->cy);
            if (d > reach)
                continue;
            if (kind == RENDER_SET_CLUTTER_ONLY) {
                if (p < 0.12)
                    render_scene_add(s, RENDER_OBJ_LIGHT, x, y, 0, 0.29, 0.29, 0);
                else if (p < 0.75)
                    add_clutter(s, x + render_random_uniform(-0.15, 0.15), y + render_random_uniform(-0.15, 0.15), p < 0.45);
                continue;
            }
            if (p < 0.55 && d < view + s->diameter && npool > 0) {
                int pick = (int)(render_random_next() % (unsigned)npool), id = pool[pick];
                if (kind != RENDER_SET_REPEATS)
                    pool[pick] = pool[--npool];
                else if (npool > 4)
                    npool = 4; /* four ids: a frame holds each two or three times */
                render_set_add_landmark(s, x + render_random_uniform(-0.04, 0.04), y + render_random_uniform(-0.04, 0.04), id,
                                        lowered(s, id));
                if ((kind == RENDER_SET_GLARE && render_random_uniform(0, 1) < 0.6) ||
                    ((kind == RENDER_SET_MOVING || kind == RENDER_SET_HELDOUT) && render_random_uniform(0, 1) < 0.25)) {
                    /* a light 2 to 6 cm from the landmark's edge, on one side */
                    render_object *lm = &s->obj[s->n - 1];
                    double gap = render_random_uniform(0.02, 0.06), hw = 0.29, side = (double)(render_random_next() % 4);
                    double off = lm->a + gap + hw;
                    double lx = lm->x + (side == 0 ? off : side == 1 ? -off : render_random_uniform(-0.1, 0.1));
                    double ly = lm->y + (side == 2 ? off : side == 3 ? -off : render_random_uniform(-0.1, 0.1));
                    render_scene_add(s, RENDER_OBJ_LIGHT, lx, ly, 0, hw, hw, 0);
                }
            } else if (p < 0.65 && kind != RENDER_SET_CLEAN) {
                render_scene_add(s, RENDER_OBJ_LIGHT, x, y, 0, 0.29, 0.29, 0);
            } else if (p < 0.85 && (kind == RENDER_SET_CLUTTERED || kind == RENDER_SET_BORDER || kind == RENDER_SET_DIM ||
                                    kind == RENDER_SET_ILLUM || kind == RENDER_SET_DEGRADED || kind == RENDER_SET_LENS ||
                                    kind == RENDER_SET_MOVING || kind == RENDER_SET_HELDOUT)) {
                add_clutter(s, x + render_random_uniform(-0.12, 0.12), y + render_random_uniform(-0.12, 0.12), p < 0.72);
            }
        }
    /* lights go last: they cover the paper they overlap */
    {
        int a, b = 0;
        render_object tmp[RENDER_MAX_OBJ];
        for (a = 0; a < s->n; a++)
            if (s->obj[a].kind != RENDER_OBJ_LIGHT)
                tmp[b++] = s->obj[a];
        for (a = 0; a < s->n; a++)
            if (s->obj[a].kind == RENDER_OBJ_LIGHT)
                tmp[b++] = s->obj[a];
        memcpy(s->obj, tmp, sizeof(render_object) * (size_t)s->n);
    }
}

void render_set_fill(render_scene *s, render_set kind)
{
    if (site_map != NULL)
        map_scene(s);
    else if (kind == RENDER_SET_PATH)
        site_scene(s, kind);
    else
        random_scene(s, kind);
}
