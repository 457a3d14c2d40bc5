#include "fixture_eval.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rl_yaml.h"

int truth_load_frame(const char *dir, const char *set, int k, truth *t)
{
    char yaml[1200];
    FILE *f;
    snprintf(yaml, sizeof yaml, "%s/%s_%03d.yaml", dir, set, k);
    if ((f = fopen(yaml, "r")) == NULL)
        return 0;
    fclose(f);
    return truth_load(yaml, t) == 0 ? 1 : -1;
}

int fixture_sets_args(int argc, char **argv, const char *prog, fixture_sets *fs)
{
    if (argc < 3) {
        fprintf(stderr, "usage: %s DIR SET...\n", prog);
        return 0;
    }
    fs->dir = argv[1];
    fs->sets = (const char *const *)(argv + 2);
    fs->n = argc - 2;
    return 1;
}

int fixture_sets_next(const fixture_sets *fs, int *s, int *k, truth *t)
{
    for (; *s < fs->n; ++*s, *k = 0) {
        int got = truth_load_frame(fs->dir, fs->sets[*s], *k, t);
        if (got != 0) {
            ++*k;
            return got;
        }
    }
    return 0;
}

int truth_load(const char *yaml, truth *t)
{
    rl_yaml y;
    yaml_node_t *root, *seq, *rob;
    char err[512];
    const char *img = NULL;
    int i, n;
    memset(t, 0, sizeof *t);
    if (rl_yaml_load(&y, yaml, err, sizeof err) != RL_OK) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    root = rl_yaml_root(&y);
    if (rl_yaml_string(&y, root, "image", NULL, 1, &img, err, sizeof err) != RL_OK ||
        rl_yaml_int(&y, root, "width", NULL, 1, &t->width, err, sizeof err) != RL_OK ||
        rl_yaml_int(&y, root, "height", NULL, 1, &t->height, err, sizeof err) != RL_OK)
        goto bad;
    snprintf(t->image, sizeof t->image, "%s", img);
    rob = rl_yaml_get(&y, root, "robot");
    if (rl_yaml_double(&y, rob, "x", NULL, 1, &t->robot_x, err, sizeof err) != RL_OK ||
        rl_yaml_double(&y, rob, "y", NULL, 1, &t->robot_y, err, sizeof err) != RL_OK ||
        rl_yaml_double(&y, rob, "yaw", NULL, 1, &t->robot_yaw, err, sizeof err) != RL_OK)
        goto bad;
    seq = rl_yaml_get(&y, root, "landmarks");
    n = rl_yaml_len(seq);
    for (i = 0; i < n && i < EVAL_MAX_TRUTH; i++) {
        yaml_node_t *it = rl_yaml_item(&y, seq, i);
        truth_landmark *l = &t->lm[i];
        if (rl_yaml_int(&y, it, "id", NULL, 1, &l->id, err, sizeof err) != RL_OK ||
            rl_yaml_double(&y, it, "x", NULL, 1, &l->x, err, sizeof err) != RL_OK ||
            rl_yaml_double(&y, it, "y", NULL, 1, &l->y, err, sizeof err) != RL_OK ||
            rl_yaml_double(&y, it, "u", NULL, 1, &l->u, err, sizeof err) != RL_OK ||
            rl_yaml_double(&y, it, "v", NULL, 1, &l->v, err, sizeof err) != RL_OK ||
            rl_yaml_double(&y, it, "radius", NULL, 1, &l->radius, err, sizeof err) != RL_OK ||
            rl_yaml_double(&y, it, "visible", NULL, 1, &l->visible, err, sizeof err) != RL_OK ||
            rl_yaml_double(&y, it, "light_gap_radii", NULL, 1, &l->light_gap_radii, err, sizeof err) != RL_OK)
            goto bad;
        t->n++;
    }
    rl_yaml_free(&y);
    return 0;
bad:
    fprintf(stderr, "%s\n", err);
    rl_yaml_free(&y);
    return -1;
}

double eval_per_id(const eval_counts *c, FILE *out, int *worst)
{
    double low = 1.0;
    int id;
    *worst = 0;
    fprintf(out, "  per id:");
    for (id = 1; id < RL_MAX_IDS; id++) {
        double rate;
        if (c->id_complete[id] == 0)
            continue;
        rate = (double)c->id_ident[id] / c->id_complete[id];
        fprintf(out, " %d %d/%d", id, c->id_ident[id], c->id_complete[id]);
        if (rate < low) {
            low = rate;
            *worst = id;
        }
    }
    fprintf(out, "\n");
    return low;
}

static const truth_landmark *nearest(const truth *t, double u, double v, double *dist)
{
    const truth_landmark *best = NULL;
    int i;
    *dist = 1e9;
    for (i = 0; i < t->n; i++) {
        double d = hypot(t->lm[i].u - u, t->lm[i].v - v);
        if (d < *dist) {
            *dist = d;
            best = &t->lm[i];
        }
    }
    return best;
}

void eval_frame(const truth *t, const rl_result *res, eval_counts *c, int verbose)
{
    int i, j;
    /* every report: right id, wrong id, or nothing there */
    for (j = 0; j < res->n_landmarks; j++) {
        const rl_detection *d = &res->landmarks[j];
        double dist;
        const truth_landmark *l = nearest(t, d->u, d->v, &dist);
        c->identified++;
        c->local_found += d->pass == RL_PASS_LOCAL;
        if (l == NULL || dist > 0.5 * l->radius) {
            c->invented++;
            if (verbose)
                fprintf(stderr, "  %s: id %d at (%.1f, %.1f) is not a landmark\n", t->image, d->id, d->u, d->v);
        } else if (l->id != d->id) {
            c->wrong_id++;
            if (verbose)
                fprintf(stderr, "  %s: id %d at (%.1f, %.1f) is really %d\n", t->image, d->id, d->u, d->v, l->id);
        }
    }
    /* every true landmark: found? identified? */
    for (i = 0; i < t->n; i++) {
        const truth_landmark *l = &t->lm[i];
        int found = 0, ident = 0;
        for (j = 0; j < res->n_landmarks; j++) {
            const rl_detection *d = &res->landmarks[j];
            if (hypot(d->u - l->u, d->v - l->v) < 0.5 * l->radius) {
                found = 1;
                ident = d->id == l->id;
                if (ident && l->visible >= 1.0) {
                    c->centre_err_sum += hypot(d->u - l->u, d->v - l->v);
                    c->centre_n++;
                }
            }
        }
        for (j = 0; j < res->n_unidentified && !found; j++) {
            const rl_detection *d = &res->unidentified[j];
            found = hypot(d->u - l->u, d->v - l->v) < 0.5 * l->radius;
        }
        if (l->visible >= 1.0) {
            for (j = 0; j < t->n; j++)
                if (j != i && t->lm[j].id == l->id && t->lm[j].visible > 0) {
                    c->twin++;
                    c->twin_ident += ident;
                    break;
                }
            if (l->id > 0 && l->id < RL_MAX_IDS) {
                c->id_complete[l->id]++;
                c->id_ident[l->id] += ident;
            }
            c->complete++;
            c->complete_found += found;
            c->complete_ident += ident;
            if (l->light_gap_radii <= 1.0) {
                c->glare++;
                c->glare_ident += ident;
            }
            if (verbose && !ident)
                fprintf(stderr, "  %s: landmark %d at (%.1f, %.1f) %s\n", t->image, l->id, l->u, l->v,
                        found ? "found, not identified" : "missed");
        } else if (l->visible >= 0.5) {
            c->border++;
            c->border_ident += ident;
            if (verbose && !ident)
                fprintf(stderr, "  %s: cut landmark %d at (%.1f, %.1f), %.0f%% visible, %s\n", t->image, l->id,
                        l->u, l->v, 100 * l->visible, found ? "found, not identified" : "missed");
        }
    }
}
