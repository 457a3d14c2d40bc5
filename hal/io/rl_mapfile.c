#include "rl_mapfile.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rl_outfile.h"
#include "rl_yaml.h"

static const char *const top_keys[] = {"family", "diameter", "ceiling_height", "landmarks", NULL};
static const char *const landmark_keys[] = {"id", "x", "y", "z", "sigma_x", "sigma_y", NULL};

/* A landmark's surveyed sigma_x and sigma_y: both or neither, each above 0
 * (a survey never writes 0: it would weigh the landmark infinitely). */
static rl_err read_sigmas(rl_yaml *y, yaml_node_t *item, int i, rl_map_landmark *lm, char *err, size_t errlen)
{
    static const char *const names[2] = {"sigma_x", "sigma_y"};
    double *v[2];
    char label[64];
    int k;
    rl_err e;
    v[0] = &lm->sigma_x;
    v[1] = &lm->sigma_y;
    for (k = 0; k < 2; k++) {
        yaml_node_t *n = rl_yaml_get(y, item, names[k]);
        snprintf(label, sizeof label, "landmarks[%d].%s", i, names[k]);
        if ((e = rl_yaml_double_in(y, item, names[k], label, 0, 0.0, 10.0, v[k], err, errlen)) != RL_OK)
            return e;
        if (n != NULL && !(*v[k] > 0))
            return rl_yaml_fail(y, n, label, RL_ERANGE, err, errlen, "%g: a sigma must be above 0", *v[k]);
        if ((n == NULL) != (rl_yaml_get(y, item, names[1 - k]) == NULL)) {
            snprintf(label, sizeof label, "landmarks[%d]", i);
            int has = n != NULL ? k : 1 - k;
            return rl_yaml_fail(y, item, label, RL_EFORMAT, err, errlen, "%s without %s (give both or neither)",
                                names[has], names[1 - has]);
        }
    }
    return RL_OK;
}

/* family, diameter and ceiling_height; *fam the family as written. */
static rl_err read_header(rl_yaml *y, yaml_node_t *root, rl_map *map, const char **fam, char *err, size_t errlen)
{
    rl_err e;
    if ((e = rl_yaml_only(y, root, NULL, top_keys, err, errlen)) != RL_OK ||
        (e = rl_yaml_string(y, root, "family", NULL, 1, fam, err, errlen)) != RL_OK)
        return e;
    if ((e = rl_family_parse(*fam, &map->family)) != RL_OK)
        return rl_yaml_fail(y, rl_yaml_get(y, root, "family"), "family", e, err, errlen,
                            "'%s' is not a family (ring2 .. ring%d)", *fam, RL_MAX_BITS);
    if ((e = rl_yaml_double(y, root, "diameter", NULL, 1, &map->diameter, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(y, root, "ceiling_height", NULL, 1, 0.0, 100.0, &map->ceiling_height, err,
                               errlen)) != RL_OK)
        return e;
    if (!(map->diameter > 0.0) || map->diameter > 5.0)
        return rl_yaml_fail(y, rl_yaml_get(y, root, "diameter"), "diameter", RL_ERANGE, err, errlen,
                            "%g m is not a printable diameter (0 .. 5 m)", map->diameter);
    if (!(map->ceiling_height > 0.0))
        return rl_yaml_fail(y, rl_yaml_get(y, root, "ceiling_height"), "ceiling_height", RL_ERANGE, err, errlen,
                            "must be positive");
    return RL_OK;
}

/* landmarks[i]: {id, x, y[, z][, sigma_x, sigma_y]} */
static rl_err read_landmark(rl_yaml *y, yaml_node_t *item, int i, rl_map_landmark *lm, char *err, size_t errlen)
{
    char label[64];
    rl_err e;
    snprintf(label, sizeof label, "landmarks[%d]", i);
    if (item == NULL || item->type != YAML_MAPPING_NODE)
        return rl_yaml_fail(y, item, label, RL_EFORMAT, err, errlen, "expected {id, x, y}");
    if ((e = rl_yaml_only(y, item, label, landmark_keys, err, errlen)) != RL_OK)
        return e;
    snprintf(label, sizeof label, "landmarks[%d].id", i);
    if ((e = rl_yaml_int(y, item, "id", label, 1, &lm->id, err, errlen)) != RL_OK)
        return e;
    snprintf(label, sizeof label, "landmarks[%d].x", i);
    if ((e = rl_yaml_double_in(y, item, "x", label, 1, -RL_MAP_MAX_COORD, RL_MAP_MAX_COORD, &lm->x, err,
                               errlen)) != RL_OK)
        return e;
    snprintf(label, sizeof label, "landmarks[%d].y", i);
    if ((e = rl_yaml_double_in(y, item, "y", label, 1, -RL_MAP_MAX_COORD, RL_MAP_MAX_COORD, &lm->y, err,
                               errlen)) != RL_OK)
        return e;
    /* its own height: a landmark on a beam or a lower panel */
    snprintf(label, sizeof label, "landmarks[%d].z", i);
    lm->z = 0.0;
    if ((e = rl_yaml_double_in(y, item, "z", label, 0, 0.001, RL_MAP_MAX_HEIGHT, &lm->z, err, errlen)) != RL_OK)
        return e;
    return read_sigmas(y, item, i, lm, err, errlen);
}

/* The landmarks list, each read into map (map->count: those read). */
static rl_err read_landmarks(rl_yaml *y, yaml_node_t *root, yaml_node_t *seq, rl_map *map, char *err,
                             size_t errlen)
{
    int i, n = rl_yaml_len(seq);
    rl_err e;
    if (n < 0)
        return rl_yaml_fail(y, seq ? seq : root, "landmarks", RL_EFORMAT, err, errlen,
                            seq ? "expected a list of {id, x, y}" : "missing key");
    if (n > RL_MAX_MAP_LANDMARKS)
        return rl_yaml_fail(y, seq, "landmarks", RL_ELIMIT, err, errlen,
                            "%d landmarks, more than the %d this build holds (RL_MAX_MAP_LANDMARKS)", n,
                            RL_MAX_MAP_LANDMARKS);
    for (i = 0; i < n; i++) {
        if ((e = read_landmark(y, rl_yaml_item(y, seq, i), i, &map->lm[i], err, errlen)) != RL_OK)
            return e;
        map->count = i + 1;
    }
    return RL_OK;
}

/* rl_map_check's verdict on the whole map, naming the landmark at fault. */
static rl_err check_map(rl_yaml *y, yaml_node_t *root, yaml_node_t *seq, const rl_map *map, const char *fam,
                        char *err, size_t errlen)
{
    char label[64];
    int bad;
    rl_err e = rl_map_check(map, &bad);
    if (e != RL_OK && bad >= 0) {
        yaml_node_t *item = rl_yaml_item(y, seq, bad);
        snprintf(label, sizeof label, "landmarks[%d].id", bad);
        if (e == RL_ERANGE) {
            rl_yaml_fail(y, item, label, e, err, errlen, "id %d is not in %s (1 .. %d)", map->lm[bad].id, fam,
                         rl_family_count(&map->family));
        } else {
            int o = rl_map_overlapped(map, bad);
            snprintf(label, sizeof label, "landmarks[%d]", bad);
            rl_yaml_fail(y, item, label, e, err, errlen,
                         "id %d at (%g, %g) overlaps landmarks[%d] (id %d at (%g, %g)): centres "
                         "closer than the diameter %g m",
                         map->lm[bad].id, map->lm[bad].x, map->lm[bad].y, o, o >= 0 ? map->lm[o].id : 0,
                         o >= 0 ? map->lm[o].x : 0, o >= 0 ? map->lm[o].y : 0, map->diameter);
        }
    } else if (e != RL_OK) {
        rl_yaml_fail(y, root, "map", e, err, errlen, "%s", rl_strerror(e));
    }
    return e;
}

rl_err rl_mapfile_load(const char *path, rl_map *map, char *err, size_t errlen)
{
    rl_yaml y;
    yaml_node_t *root, *seq;
    const char *fam = NULL;
    rl_err e;

    memset(map, 0, sizeof *map);
    if ((e = rl_yaml_load(&y, path, err, errlen)) != RL_OK)
        return e;
    root = rl_yaml_root(&y);
    seq = rl_yaml_get(&y, root, "landmarks");
    if (root->type != YAML_MAPPING_NODE)
        e = rl_yaml_fail(&y, root, "map", RL_EFORMAT, err, errlen,
                         "expected a mapping with family, diameter, ceiling_height, landmarks");
    else if ((e = read_header(&y, root, map, &fam, err, errlen)) == RL_OK &&
             (e = read_landmarks(&y, root, seq, map, err, errlen)) == RL_OK)
        e = check_map(&y, root, seq, map, fam, err, errlen);
    rl_yaml_free(&y);
    return e;
}

void rl_mapfile_put_header(FILE *f, const rl_family *fam, double diameter, double ceiling_height)
{
    fprintf(f, "family: ring%d          # docs/landmark-spec.md\n", fam->bits);
    fprintf(f, "diameter: %.4f        # printed outer diameter, metres\n", diameter);
    fprintf(f, "ceiling_height: %.5f  # ceiling above the floor, metres\n", ceiling_height);
    fprintf(f, "landmarks:\n");
}

void rl_mapfile_put_landmark(FILE *f, const rl_map_landmark *lm)
{
    int surveyed = lm->sigma_x > 0 || lm->sigma_y > 0;
    if (surveyed)
        fprintf(f, "  - {id: %d, x: %.5f, y: %.5f", lm->id, lm->x, lm->y);
    else
        fprintf(f, "  - {id: %d, x: %.4f, y: %.4f", lm->id, lm->x, lm->y);
    if (lm->z > 0) /* its own height (0: the map's ceiling_height) */
        fprintf(f, ", z: %.4f", lm->z);
    /* a sigma is written at least at the file's resolution (0.01 mm): 0
     * (the survey's axis landmark across its axis) would claim a landmark
     * known exactly, which the loader refuses */
    if (surveyed)
        fprintf(f, ", sigma_x: %.5f, sigma_y: %.5f", fmax(lm->sigma_x, 1e-5), fmax(lm->sigma_y, 1e-5));
    fprintf(f, "}\n");
}

rl_err rl_mapfile_save(const char *path, const rl_map *map, char *err, size_t errlen)
{
    rl_outfile o;
    FILE *f;
    rl_err e;
    int i;
    if ((e = rl_outfile_open(&o, path, err, errlen)) != RL_OK)
        return e;
    f = o.f;
    rl_mapfile_put_header(f, &map->family, map->diameter, map->ceiling_height);
    for (i = 0; i < map->count; i++)
        rl_mapfile_put_landmark(f, &map->lm[i]);
    return rl_outfile_commit(&o, err, errlen);
}
