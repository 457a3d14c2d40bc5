/* The libcamera backend's module (ringloc-libcamera.so, built from
 * cam_libcamera.cpp where libcamera is found): its two entry points, which
 * rl_cam_open_libcamera and rl_cam_probe_libcamera (cam_libcamera_load.c)
 * load on first use. Nothing else of the module is visible.
 *
 *   rl_cam c;
 *   rl_cam_config cc;
 *   char err[256];
 *   rl_cam_defaults(&cc);
 *   cc.backend = "libcamera";
 *   if (rl_cam_libcamera_open(&c, &cc, err, sizeof err) == RL_OK) // in the module
 *       rl_cam_close(&c);
 */
#ifndef RL_CAM_LIBCAMERA_H
#define RL_CAM_LIBCAMERA_H

#include "rl_cam.h"
#include "rl_module.h"

/* The module as rl_module_symbol finds it; the layout its entry points take. */
#define RL_CAM_LIBCAMERA_ABI RL_MODULE_ABI(sizeof(rl_cam), sizeof(rl_cam_config))
#define RL_CAM_LIBCAMERA_MODULE                                                                           \
    {"ringloc-libcamera.so", "the libcamera camera backend (package ringloc, built where libcamera is)",     \
     RL_CAM_LIBCAMERA_ABI}

#ifdef __cplusplus
extern "C" {
#endif

/* As rl_cam_open_libcamera and rl_cam_probe_libcamera (rl_cam.h). */
typedef rl_err (*rl_cam_libcamera_probe_fn)(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx,
                                            char *err, size_t errlen);
RL_MODULE_EXPORT unsigned long rl_module_abi(void);
RL_MODULE_EXPORT rl_err rl_cam_libcamera_open(rl_cam *c, const rl_cam_config *cc, char *err,
                                              size_t errlen);
RL_MODULE_EXPORT rl_err rl_cam_libcamera_probe(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx,
                                               char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
