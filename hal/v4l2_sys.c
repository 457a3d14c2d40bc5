#include "rl_v4l2_sys.h"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

static int real_open(void *ctx, const char *path, int flags)
{
    (void)ctx;
    return open(path, flags);
}

static int real_close(void *ctx, int fd)
{
    (void)ctx;
    return close(fd);
}

static int real_ioctl(void *ctx, int fd, unsigned long req, void *arg)
{
    (void)ctx;
    return ioctl(fd, req, arg);
}

static void *real_mmap(void *ctx, size_t len, int fd, off_t offset)
{
    (void)ctx;
    return mmap(NULL, len, PROT_READ | PROT_WRITE, MAP_SHARED, fd, offset);
}

static int real_munmap(void *ctx, void *addr, size_t len)
{
    (void)ctx;
    return munmap(addr, len);
}

static int real_poll(void *ctx, struct pollfd *p, int timeout_ms)
{
    (void)ctx;
    return poll(p, 1, timeout_ms);
}

const rl_v4l2_sys *rl_v4l2_sys_real(void)
{
    static const rl_v4l2_sys sys = {real_open, real_close, real_ioctl, real_mmap, real_munmap,
                                    real_poll, NULL};
    return &sys;
}
