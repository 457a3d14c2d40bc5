#include "rl_templates.h"

#include <math.h>
#include <string.h>

typedef struct {
    double sigma;  /* Gaussian, units of R */
    double motion; /* length of a straight motion, units of R */
} blur_level;

/* Focus first; a robot's motion of 3 to 9 px at the paper's 25 px radius
 * (1 m/s under a 10-30 ms exposure) with a little defocus; the softest
 * last. */
static const blur_level blur_levels[RL_BLUR_LEVELS] = {
    {0.0, 0.0}, {0.03, 0.0}, {0.06, 0.0}, {0.03, 0.12}, {0.03, 0.24}, {0.03, 0.36}, {0.10, 0.0}};

/* A moving template is sampled from the Gaussian one on this grid of
 * radii, 0 .. MOTION_GRID_MAX. */
#define MOTION_GRID 512
#define MOTION_GRID_MAX 1.6
/* Directions and instants averaged over for a moving template. */
#define MOTION_ANGLES 8
#define MOTION_STEPS 8

/* Columns per bin, padded to whole blocks. */
static int padded_columns(int n)
{
    return (n * RL_BLUR_LEVELS + RL_MATCH_BLOCK - 1) / RL_MATCH_BLOCK * RL_MATCH_BLOCK;
}

size_t rl_templates_bytes(int n)
{
    return (size_t)n * sizeof(int) + sizeof(float) * RL_PROFILE_BINS * (size_t)padded_columns(n) +
           2 * RL_WS_ALIGN;
}

static size_t table_index(const rl_templates *tt, int i, int blur, int k)
{
    return (size_t)k * (size_t)tt->stride + (size_t)i * RL_BLUR_LEVELS + (size_t)blur;
}

float rl_templates_bin(const rl_templates *tt, int i, int blur, int k)
{
    return tt->table[table_index(tt, i, blur, k)];
}

int rl_templates_moving(int blur)
{
    return blur >= 0 && blur < RL_BLUR_LEVELS && blur_levels[blur].motion > 0;
}

int rl_templates_find(const rl_templates *tt, int id)
{
    return id >= 0 && id < (1 << RL_MAX_BITS) ? tt->at[id] : -1;
}

double rl_templates_value_at(const rl_family *fam, int id, double rho, double sigma)
{
    /* Darkness is a sum of steps at the zone edges: going inwards across
     * edge r[i] the darkness changes from the zone outside to the zone
     * inside. Blurring turns each step into a Gaussian CDF. */
    double r[RL_MAX_BITS + 2], d = 0.0;
    int i, n = fam->bits, outside = 0;
    rl_family_radii(fam, r);
    for (i = 0; i <= n; i++) {
        int inside = i == 0 ? 1 : rl_family_bit(fam, id, i);
        if (inside != outside) {
            double step = sigma > 0 ? 0.5 * (1.0 + erf((r[i] - rho) / (sigma * sqrt(2.0))))
                                    : (rho < r[i] ? 1.0 : 0.0);
            d += (inside - outside) * step;
        }
        outside = inside;
    }
    return d;
}

/* Darkness at radius rho from the Gaussian template sampled in g
 * (MOTION_GRID values over 0 .. MOTION_GRID_MAX), linear in between. */
static double grid_at(const double *g, double rho)
{
    double x = rho / MOTION_GRID_MAX * (MOTION_GRID - 1);
    int i = (int)x;
    if (i >= MOTION_GRID - 1)
        return g[MOTION_GRID - 1];
    return g[i] + (x - i) * (g[i + 1] - g[i]);
}

/* Darkness at radius rho of the Gaussian template g moved by `motion`
 * along x during the exposure, averaged over the directions of a circle
 * (a quarter of it: the pattern is symmetric about both axes). */
static double moving_at(const double *g, double rho, double motion)
{
    double acc = 0;
    int a, t;
    for (a = 0; a < MOTION_ANGLES; a++) {
        double th = (a + 0.5) * (M_PI / 2) / MOTION_ANGLES, x = rho * cos(th), y = rho * sin(th);
        for (t = 0; t < MOTION_STEPS; t++) {
            double dx = x + ((t + 0.5) / MOTION_STEPS - 0.5) * motion;
            acc += grid_at(g, sqrt(dx * dx + y * y));
        }
    }
    return acc / (MOTION_ANGLES * MOTION_STEPS);
}

/* Mean darkness over bin k's annulus, weighted by radius (area), of id at
 * blur level lv; g holds its Gaussian template on the motion grid. */
static float bin_mean(const rl_family *fam, int id, const blur_level *lv, const double *g, int k)
{
    double acc = 0, w = 0;
    int s;
    for (s = 0; s < 8; s++) {
        double rho = (k + (s + 0.5) / 8) * RL_PROFILE_EXTENT / RL_PROFILE_BINS;
        acc += rho * (lv->motion > 0 ? moving_at(g, rho, lv->motion)
                                     : rl_templates_value_at(fam, id, rho, lv->sigma));
        w += rho;
    }
    return (float)(acc / w);
}

/* The columns of one id at every blur level. */
static void id_columns(rl_templates *tt, int i)
{
    double g[MOTION_GRID];
    int b, k, j;
    for (b = 0; b < RL_BLUR_LEVELS; b++) {
        const blur_level *lv = &blur_levels[b];
        if (lv->motion > 0)
            for (j = 0; j < MOTION_GRID; j++)
                g[j] = rl_templates_value_at(&tt->fam, tt->ids[i], j * MOTION_GRID_MAX / (MOTION_GRID - 1),
                                             lv->sigma);
        for (k = 0; k < RL_PROFILE_BINS; k++)
            tt->table[table_index(tt, i, b, k)] = bin_mean(&tt->fam, tt->ids[i], lv, g, k);
    }
}

rl_err rl_templates_init(rl_templates *tt, rl_ws *ws, const rl_family *fam, const int *ids,
                         int n_ids)
{
    int i, n = ids ? n_ids : rl_family_count(fam);
    rl_err e;
    if (n <= 0)
        return RL_EINVAL;
    tt->fam = *fam;
    tt->n = n;
    if ((e = rl_ws_alloc(ws, (size_t)n * sizeof(int), RL_WS_ALIGN, (void **)&tt->ids)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)padded_columns(n) * RL_PROFILE_BINS * sizeof(float),
                         RL_WS_ALIGN, (void **)&tt->table)) != RL_OK)
        return e;
    tt->stride = padded_columns(n);
    if (rl_ws_is_sizing(ws))
        return RL_OK;
    memset(tt->table, 0, (size_t)tt->stride * RL_PROFILE_BINS * sizeof(float)); /* the pads */
    for (i = 0; i < (1 << RL_MAX_BITS); i++)
        tt->at[i] = -1;
    for (i = 0; i < n; i++) {
        tt->ids[i] = ids ? ids[i] : i + 1;
        if (!rl_family_valid(fam, tt->ids[i]) || tt->ids[i] >= (1 << RL_MAX_BITS))
            return RL_ERANGE;
        if (tt->at[tt->ids[i]] < 0) /* a repeated id: its first place */
            tt->at[tt->ids[i]] = (int16_t)i;
        id_columns(tt, i);
    }
    return RL_OK;
}
