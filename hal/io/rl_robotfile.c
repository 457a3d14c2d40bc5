#include "rl_robotfile.h"

#include <stdio.h>
#include <string.h>
#include "rl_outfile.h"
#include "rl_yaml.h"

static const char *const top_keys[] = {"camera_mount", "rocking", NULL};
static const char *const mount_keys[] = {"x", "y", "z", "yaw", "roll", "pitch", NULL};

rl_err rl_robotfile_load(const char *path, rl_mount *m, char *err, size_t errlen)
{
    rl_yaml y;
    yaml_node_t *root, *cm;
    rl_err e;
    rl_mount_defaults(m, 0.0);
    if ((e = rl_yaml_load(&y, path, err, errlen)) != RL_OK)
        return e;
    root = rl_yaml_root(&y);
    cm = rl_yaml_get(&y, root, "camera_mount");
    if (cm == NULL || cm->type != YAML_MAPPING_NODE) {
        e = rl_yaml_fail(&y, cm ? cm : root, "camera_mount", RL_EFORMAT, err, errlen,
                         cm ? "expected {x, y, z, yaw, roll, pitch}" : "missing key");
        goto out;
    }
    if ((e = rl_yaml_only(&y, root, NULL, top_keys, err, errlen)) != RL_OK ||
        (e = rl_yaml_only(&y, cm, "camera_mount", mount_keys, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, cm, "x", "camera_mount.x", 0, -100, 100, &m->x, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, cm, "y", "camera_mount.y", 0, -100, 100, &m->y, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, cm, "z", "camera_mount.z", 1, 0, 20, &m->z, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, cm, "yaw", "camera_mount.yaw", 0, -7, 7, &m->yaw, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, cm, "roll", "camera_mount.roll", 0, -0.5, 0.5, &m->roll, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, cm, "pitch", "camera_mount.pitch", 0, -0.5, 0.5, &m->pitch, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, root, "rocking", "rocking", 0, 0, RL_POSE_ROCKING_MAX, &m->rocking, err,
                               errlen)) != RL_OK)
        goto out;
out:
    rl_yaml_free(&y);
    return e;
}

rl_err rl_robotfile_save(const char *path, const rl_mount *m, char *err, size_t errlen)
{
    rl_outfile o;
    FILE *f;
    rl_err e;
    if ((e = rl_outfile_open(&o, path, err, errlen)) != RL_OK)
        return e;
    f = o.f;
    fprintf(f, "# camera optical centre in the robot frame (REP-103), z above the floor\n");
    if (m->roll != 0 || m->pitch != 0)
        fprintf(f, "camera_mount: {x: %.4f, y: %.4f, z: %.4f, yaw: %.6f, roll: %.6f, pitch: %.6f}\n", m->x, m->y,
                m->z, m->yaw, m->roll, m->pitch);
    else
        fprintf(f, "camera_mount: {x: %.4f, y: %.4f, z: %.4f, yaw: %.6f}\n", m->x, m->y, m->z, m->yaw);
    /* only where it is not the default: a file an older ringloc reads too */
    if (m->rocking != RL_POSE_TILT_PRIOR)
        fprintf(f, "# how far the robot leans on its floor, rad (sd per axis; 0: never)\nrocking: %.6f\n",
                m->rocking);
    return rl_outfile_commit(&o, err, errlen);
}
