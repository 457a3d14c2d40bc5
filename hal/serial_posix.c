#include "rl_serial.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

static speed_t speed_of(int baud)
{
    switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    }
    return 0;
}

int rl_serial_baud_ok(int baud)
{
    return speed_of(baud) != 0;
}

/* 1 for a path in /dev, where only devices belong. */
static int in_dev(const char *path)
{
    return strncmp(path, "/dev/", 5) == 0;
}

/* Raw 8N1 at baud on an open character device; a device that is no
 * terminal (/dev/null) is written as it is. */
static rl_err set_line(rl_serial *s, int baud, char *err, size_t errlen)
{
    struct termios t;
    if (tcgetattr(s->fd, &t) != 0)
        return RL_OK;
    t.c_iflag &= ~(tcflag_t)(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL | IXON);
    t.c_oflag &= ~(tcflag_t)OPOST;
    t.c_lflag &= ~(tcflag_t)(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
    t.c_cflag &= ~(tcflag_t)(CSIZE | PARENB | CSTOPB);
    t.c_cflag |= CS8 | CLOCAL | CREAD;
    t.c_cc[VMIN] = 0;
    t.c_cc[VTIME] = 0;
    cfsetispeed(&t, speed_of(baud));
    cfsetospeed(&t, speed_of(baud));
    if (tcsetattr(s->fd, TCSANOW, &t) != 0) {
        snprintf(err, errlen, "%s: cannot set 8N1 at %d baud: %s", s->path, baud, strerror(errno));
        return RL_EIO;
    }
    s->is_tty = 1;
    return RL_OK;
}

/* The device at dev (path itself, or where its links lead), opened
 * without following a link planted in between, and checked on the open
 * descriptor: only a character device is kept. */
static rl_err open_device(rl_serial *s, const char *dev, int baud, char *err, size_t errlen)
{
    struct stat st;
    rl_err e;
    s->fd = open(dev, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC | O_NOFOLLOW);
    if (s->fd < 0) {
        snprintf(err, errlen, "%s: %s", s->path, strerror(errno));
        return errno == ENOENT ? RL_ENOTFOUND : RL_ENODEV;
    }
    s->own = 1;
    if (fstat(s->fd, &st) != 0 || !S_ISCHR(st.st_mode)) {
        snprintf(err, errlen, "%s: not a serial device (a character device or a pty); not written to", s->path);
        rl_serial_close(s);
        return RL_ENODEV;
    }
    if ((e = set_line(s, baud, err, errlen)) != RL_OK)
        rl_serial_close(s);
    return e;
}

/* Frames recorded into a plain file: one this run creates (first open),
 * or the one it created, appended to on a reopen. */
static rl_err open_record(rl_serial *s, const char *path, int create, char *err, size_t errlen)
{
    s->fd = open(path, O_WRONLY | O_APPEND | O_CLOEXEC | O_NOFOLLOW | (create ? O_CREAT | O_EXCL : 0), 0644);
    if (s->fd < 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return RL_ENOTFOUND;
    }
    s->own = 1;
    return RL_OK;
}

rl_err rl_serial_open(rl_serial *s, const char *path, int baud, unsigned flags, char *err,
                      size_t errlen)
{
    struct stat st;
    char real[4096];
    memset(s, 0, sizeof *s);
    s->fd = -1;
    snprintf(s->path, sizeof s->path, "%s", path);
    if (!rl_serial_baud_ok(baud)) {
        snprintf(err, errlen, "%s: %d is not a supported baud rate (9600 .. 921600)", path, baud);
        return RL_EINVAL;
    }
    if (strcmp(path, "-") == 0) {
        s->fd = STDOUT_FILENO;
        return RL_OK;
    }
    /* Nothing there. In /dev it is a device that is not there (yet, or any
     * more): never a file made in its place. Nor, after the first open, a
     * file that vanished: the caller retries. */
    if (lstat(path, &st) != 0) {
        if (in_dev(path) || !(flags & RL_SERIAL_MAY_CREATE)) {
            snprintf(err, errlen, "%s: no such device", path);
            return RL_ENOTFOUND;
        }
        return open_record(s, path, 1, err, errlen);
    }
    /* A link (/dev/serial0, a pty monitor's) is followed to a device only;
     * a dangling one is a device that went (a restarted monitor's). */
    if (S_ISLNK(st.st_mode)) {
        if (realpath(path, real) == NULL || stat(real, &st) != 0) {
            snprintf(err, errlen, "%s: no such device", path);
            return RL_ENOTFOUND;
        }
        if (!S_ISCHR(st.st_mode)) {
            snprintf(err, errlen, "%s: a link to %s, not to a serial device (a character device or a pty); "
                     "not followed", path, real);
            return RL_ENODEV;
        }
        return open_device(s, real, baud, err, errlen);
    }
    if (S_ISCHR(st.st_mode))
        return open_device(s, path, baud, err, errlen);
    if (S_ISREG(st.st_mode) && !in_dev(path) && !(flags & RL_SERIAL_MAY_CREATE))
        return open_record(s, path, 0, err, errlen); /* the file this run made, reopened */
    if (S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "%s: an existing file, not a serial device (a character device or a pty); "
                 "not written into (name a new file to record the frames)", path);
        return RL_ENODEV;
    }
    /* a FIFO too: opening one would wait for a reader */
    snprintf(err, errlen, "%s: neither a serial device nor a file", path);
    return RL_ENODEV;
}

rl_err rl_serial_write(rl_serial *s, const uint8_t *p, size_t n, int timeout_ms)
{
    size_t done = 0;
    s->errnum = 0;
    if (s->fd < 0)
        return RL_ENODEV;
    while (done < n) {
        ssize_t w = write(s->fd, p + done, n - done);
        if (w > 0) {
            done += (size_t)w;
            continue;
        }
        if (w < 0 && errno == EINTR)
            continue;
        if (w < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            struct pollfd q;
            q.fd = s->fd;
            q.events = POLLOUT;
            q.revents = 0;
            if (poll(&q, 1, timeout_ms) <= 0)
                return RL_ETIMEOUT;
            if (q.revents & (POLLERR | POLLHUP | POLLNVAL))
                return RL_ENODEV;
            continue;
        }
        s->errnum = w < 0 ? errno : EIO;
        if (w < 0 && errno == EPIPE && !s->own) {
            s->broken = 1; /* standard output's reader went: it never comes back */
            return RL_EIO;
        }
        return w < 0 && (errno == EIO || errno == ENXIO || errno == ENODEV || errno == EBADF ||
                         errno == EPIPE)
                   ? RL_ENODEV
                   : RL_EIO;
    }
    return RL_OK;
}

void rl_serial_close(rl_serial *s)
{
    if (s->fd >= 0 && s->own)
        close(s->fd);
    s->fd = -1;
}
