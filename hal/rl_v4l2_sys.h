/* rl_v4l2_sys: the system calls of the V4L2 camera, as a seam. The real
 * ones by default; a test passes a fake device (formats, controls,
 * damaged and short buffers, a device that goes away) through
 * rl_cam_config.v4l2_sys and runs the real backend against it.
 *
 *   int fake_ioctl(void *ctx, int fd, unsigned long req, void *arg); // the test's
 *   rl_v4l2_sys sys = *rl_v4l2_sys_real();
 *   sys.ioctl = fake_ioctl;  // everything else stays the real call
 *   use(&sys);               // rl_cam_config.v4l2_sys = &sys
 */
#ifndef RL_V4L2_SYS_H
#define RL_V4L2_SYS_H

#include <poll.h>
#include <stddef.h>
#include <sys/types.h>

typedef struct rl_v4l2_sys {
    int (*open)(void *ctx, const char *path, int flags);
    int (*close)(void *ctx, int fd);
    int (*ioctl)(void *ctx, int fd, unsigned long req, void *arg); /* EINTR retried by the caller */
    void *(*mmap)(void *ctx, size_t len, int fd, off_t offset);   /* read/write, shared; MAP_FAILED */
    int (*munmap)(void *ctx, void *addr, size_t len);
    int (*poll)(void *ctx, struct pollfd *p, int timeout_ms);
    void *ctx;
} rl_v4l2_sys;

/* open(2), close(2), ioctl(2), mmap(2), munmap(2), poll(2). */
const rl_v4l2_sys *rl_v4l2_sys_real(void);

#endif
