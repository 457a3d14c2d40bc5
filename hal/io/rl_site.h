/* rl_site: a site's files loaded and checked in one place, and what
 * recognition and localization build from them.
 *
 * A site is the camera's calibration, the landmark map, the robot's camera
 * mount and, optionally, the paper's offset maps. Each command, the
 * firmware, the tools and the tests name the files they need (the others
 * NULL); rl_site_load reads them and checks what they say together, with
 * one set of error lines: a map without landmarks, a camera not below the
 * ceiling, an image size the calibration is not for. rl_site_prepare then
 * makes the recognizer for the map's ids (at the calibration's size when
 * there is one: every frame of a drive has it) and, for a map that repeats
 * ids, the place index. The site is large (the map): keep it static.
 *
 *   static rl_site site;
 *   rl_site_files files;
 *   rl_recog_config rc;
 *   char err[768];
 *   rl_site_files_init(&files);
 *   files.calibration = "camera.yaml";
 *   files.map = "map.yaml";
 *   files.robot = "robot.yaml";
 *   rl_recog_defaults(&rc);
 *   if (rl_site_load(&site, &files, err, sizeof err) == RL_OK &&
 *       rl_site_prepare(&site, &rc, err, sizeof err) == RL_OK)
 *       use(site.map.count, site.recog.rec, site.place.pl);
 *   rl_site_free(&site);
 */
#ifndef RL_SITE_H
#define RL_SITE_H

#include <stddef.h>
#include "rl_calib.h"
#include "rl_heap_place.h"
#include "rl_heap_recog.h"
#include "rl_map.h"
#include "rl_pose.h"

typedef struct {
    const char *calibration; /* ROS camera_info or OpenCV YAML; NULL: none */
    const char *map;         /* landmark map; NULL: none */
    const char *robot;       /* camera_mount; NULL: none */
    const char *offsets;     /* the paper's offset maps; NULL or "": the pinhole model */
    /* the image size: a calibration that gives none takes it, one that
     * gives another is refused (0 x 0: the calibration's) */
    int width, height;
    const char *size_from;   /* where that size was given, for the error line ("--size") */
} rl_site_files;

typedef struct {
    rl_site_files files;
    int has_calib, has_map, has_mount, has_offsets;
    rl_calib calib;
    rl_map map;
    rl_mount mount;
    rl_offsets offsets;
    rl_heap_recog recog;     /* after rl_site_prepare */
    rl_heap_place place;     /* after rl_site_prepare: .pl NULL when ids are unique */
} rl_site;

/* No files, no size. */
void rl_site_files_init(rl_site_files *f);

/* The files of a site's folder, as the renderer and a recording write
 * them: DIR/camera.yaml, DIR/map.yaml, DIR/robot.yaml (paths kept in
 * held, which must outlive f). */
typedef struct {
    char calibration[1100], map[1100], robot[1100];
} rl_site_folder;
void rl_site_files_folder(rl_site_files *f, rl_site_folder *held, const char *dir);

/* Read and check the files named in f (pointers kept: they must outlive
 * the site). RL_ENOTFOUND, RL_EFORMAT, RL_ERANGE or RL_EINVAL with one
 * line in err naming the file. */
RL_CHECK rl_err rl_site_load(rl_site *s, const rl_site_files *f, char *err, size_t errlen);

/* The recognizer for rc, restricted to the map's ids (when there is a
 * map), made for the calibration's size (when there is one); the place
 * index when the map repeats ids. One line in err on failure. */
RL_CHECK rl_err rl_site_prepare(rl_site *s, const rl_recog_config *rc, char *err, size_t errlen);

/* The offset maps, or NULL for the pinhole model. */
const rl_offsets *rl_site_offsets(const rl_site *s);

/* The pose of a frame's landmarks: rl_heap_place_solve with the site's
 * calibration, map, mount and offsets. */
RL_CHECK rl_err rl_site_solve(const rl_site *s, const rl_detection *lm, int n, const rl_place_prior *prior,
                              rl_pose *pose, rl_place_found *found);

/* Free what rl_site_prepare made (the site can be loaded again). */
void rl_site_free(rl_site *s);

#endif
