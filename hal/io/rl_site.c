/* rl_site: a site's files loaded and checked in one place (rl_site.h). */
#include "rl_site.h"

#include <stdio.h>
#include <string.h>
#include "rl_calibfile.h"
#include "rl_mapfile.h"
#include "rl_offsetsfile.h"
#include "rl_robotfile.h"

void rl_site_files_init(rl_site_files *f)
{
    memset(f, 0, sizeof *f);
}

void rl_site_files_folder(rl_site_files *f, rl_site_folder *held, const char *dir)
{
    snprintf(held->calibration, sizeof held->calibration, "%.1024s/camera.yaml", dir);
    snprintf(held->map, sizeof held->map, "%.1024s/map.yaml", dir);
    snprintf(held->robot, sizeof held->robot, "%.1024s/robot.yaml", dir);
    rl_site_files_init(f);
    f->calibration = held->calibration;
    f->map = held->map;
    f->robot = held->robot;
}

static int given(const char *path)
{
    return path != NULL && path[0] != '\0';
}

/* Each named file read; the first that fails says why. */
static rl_err load_files(rl_site *s, const rl_site_files *f, char *err, size_t errlen)
{
    rl_err e = RL_OK;
    if (given(f->calibration) &&
        (e = rl_calibfile_load_sized(f->calibration, f->width, f->height, &s->calib, err, errlen)) != RL_OK)
        return e;
    if (given(f->map) && (e = rl_mapfile_load(f->map, &s->map, err, errlen)) != RL_OK)
        return e;
    if (given(f->robot) && (e = rl_robotfile_load(f->robot, &s->mount, err, errlen)) != RL_OK)
        return e;
    if (given(f->offsets) && (e = rl_offsetsfile_load(f->offsets, &s->offsets, err, errlen)) != RL_OK)
        return e;
    s->has_calib = given(f->calibration);
    s->has_map = given(f->map);
    s->has_mount = given(f->robot);
    s->has_offsets = given(f->offsets);
    return RL_OK;
}

/* What the files say together. */
static rl_err check_site(const rl_site *s, char *err, size_t errlen)
{
    const rl_site_files *f = &s->files;
    int i;
    if (s->has_calib && f->width > 0 && (f->width != s->calib.width || f->height != s->calib.height)) {
        snprintf(err, errlen, "%s: image is %dx%d but %s (image_width, image_height) is for %dx%d",
                 f->size_from ? f->size_from : "size", f->width, f->height, f->calibration, s->calib.width,
                 s->calib.height);
        return RL_EINVAL;
    }
    if (s->has_map && s->map.count == 0) {
        snprintf(err, errlen, "%s: the map has no landmarks", f->map);
        return RL_EINVAL;
    }
    if (s->has_map && s->has_mount && !(s->map.ceiling_height > s->mount.z)) {
        snprintf(err, errlen, "%s: camera_mount.z %.3f m is not below the ceiling (%s: ceiling_height %.3f m)",
                 f->robot, s->mount.z, f->map, s->map.ceiling_height);
        return RL_EINVAL;
    }
    for (i = 0; s->has_map && s->has_mount && i < s->map.count; i++)
        if (s->map.lm[i].z > 0 && !(s->map.lm[i].z - s->mount.z >= RL_POSE_MIN_DEPTH)) {
            snprintf(err, errlen, "%s: landmarks[%d].z %.3f m is not %.2f m above the camera (%s: camera_mount.z "
                     "%.3f m)", f->map, i, s->map.lm[i].z, RL_POSE_MIN_DEPTH, f->robot, s->mount.z);
            return RL_EINVAL;
        }
    return RL_OK;
}

/* A path of f kept in the site: *path points at the copy. 0 when it is
 * too long. */
static int hold(rl_site *s, int i, const char **path)
{
    if (*path == NULL)
        return 1;
    if (strlen(*path) >= sizeof s->held[i])
        return 0;
    memcpy(s->held[i], *path, strlen(*path) + 1);
    *path = s->held[i];
    return 1;
}

rl_err rl_site_load(rl_site *s, const rl_site_files *f, char *err, size_t errlen)
{
    rl_err e;
    memset(s, 0, sizeof *s);
    s->files = *f;
    if (!hold(s, 0, &s->files.calibration) || !hold(s, 1, &s->files.map) || !hold(s, 2, &s->files.robot) ||
        !hold(s, 3, &s->files.offsets) || !hold(s, 4, &s->files.size_from)) {
        snprintf(err, errlen, "a site file's path is longer than %d characters", (int)sizeof s->held[0] - 1);
        return RL_ELIMIT;
    }
    f = &s->files;
    if ((e = load_files(s, f, err, errlen)) != RL_OK)
        return e;
    return check_site(s, err, errlen);
}

rl_err rl_site_prepare(rl_site *s, const rl_recog_config *rc, char *err, size_t errlen)
{
    rl_err e;
    if (s->has_map)
        rl_heap_recog_init_map(&s->recog, rc, &s->map);
    else
        rl_heap_recog_init(&s->recog, rc);
    if (s->has_calib && (e = rl_heap_recog_prepare(&s->recog, s->calib.width, s->calib.height)) != RL_OK) {
        snprintf(err, errlen, "cannot prepare recognition for %dx%d: %s", s->calib.width, s->calib.height,
                 rl_strerror(e));
        return e;
    }
    if (s->has_map && (e = rl_heap_place_init(&s->place, &s->map, NULL)) != RL_OK) {
        rl_heap_recog_free(&s->recog);
        snprintf(err, errlen, "%s: the place index: %s", s->files.map, rl_strerror(e));
        return e;
    }
    return RL_OK;
}

const rl_offsets *rl_site_offsets(const rl_site *s)
{
    return s->has_offsets ? &s->offsets : NULL;
}

rl_err rl_site_solve(const rl_site *s, const rl_detection *lm, int n, const rl_place_prior *prior, rl_pose *pose,
                     rl_place_found *found)
{
    return rl_heap_place_solve(&s->place, &s->calib, &s->map, &s->mount, lm, n, rl_site_offsets(s), prior, pose,
                               found);
}

void rl_site_free(rl_site *s)
{
    rl_heap_recog_free(&s->recog);
    rl_heap_place_free(&s->place);
}
