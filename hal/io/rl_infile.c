#include "rl_infile.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *kind_of(mode_t m)
{
    return S_ISDIR(m) ? "a folder" : S_ISFIFO(m) ? "a FIFO" : S_ISSOCK(m) ? "a socket"
         : S_ISCHR(m) ? "a character device" : S_ISBLK(m) ? "a block device" : "an unknown kind of file";
}

int rl_infile_open(const char *path, const char *what, rl_err *e, char *err, size_t errlen)
{
    struct stat st;
    int fd, flags;
    do /* O_NONBLOCK: a FIFO without a writer opens at once instead of waiting */
        fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    while (fd < 0 && errno == EINTR);
    if (fd < 0 || fstat(fd, &st) != 0) {
        int en = errno;
        if (fd >= 0)
            close(fd);
        *e = en == ENOENT ? RL_ENOTFOUND : RL_EIO;
        snprintf(err, errlen, "%s: %s", path, strerror(en));
        return -1;
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        *e = RL_EFORMAT;
        snprintf(err, errlen, "%s: %s, not %s", path, kind_of(st.st_mode), what);
        return -1;
    }
    if ((flags = fcntl(fd, F_GETFL)) >= 0)
        (void)fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    *e = RL_OK;
    return fd;
}

FILE *rl_infile_fopen(const char *path, const char *what, rl_err *e, char *err, size_t errlen)
{
    int fd = rl_infile_open(path, what, e, err, errlen);
    FILE *f;
    if (fd < 0)
        return NULL;
    if ((f = fdopen(fd, "rb")) == NULL) {
        *e = RL_ENOMEM;
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        close(fd);
    }
    return f;
}
