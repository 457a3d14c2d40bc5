#define _XOPEN_SOURCE 600
#include "rl_ptylink.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* LINK's target into buf ("" when LINK is no link or unreadable). */
static void link_target(const char *link, char *buf, size_t len)
{
    ssize_t n = readlink(link, buf, len - 1);
    buf[n > 0 ? n : 0] = '\0';
}

/* What stands at LINK, if it may not be replaced: a reason, else NULL
 * (nothing there, or it may go). */
static const char *occupied(const char *link, int force)
{
    struct stat st, to;
    char target[256];
    if (lstat(link, &st) != 0)
        return errno == ENOENT ? NULL : "cannot be checked";
    if (S_ISDIR(st.st_mode))
        return "is a folder";
    if (force)
        return NULL;
    if (!S_ISLNK(st.st_mode))
        return S_ISREG(st.st_mode) ? "exists and is a regular file" : "exists and is not a link";
    link_target(link, target, sizeof target);
    if (strncmp(target, "/dev/pts/", 9) != 0)
        return "exists and is a link to something else than a pseudo-terminal";
    if (stat(link, &to) == 0)
        return "points to a pseudo-terminal still in use";
    return NULL; /* a stale link of a pty monitor that went away */
}

rl_err rl_ptylink_open(rl_ptylink *p, const char *link, int force, int nonblock, char *err,
                       size_t errlen)
{
    const char *name, *why;
    memset(p, 0, sizeof *p);
    p->fd = -1;
    p->link = link;
    if ((why = occupied(link, force)) != NULL) {
        snprintf(err, errlen, "%s: %s; not replaced (remove it, or give --force)", link, why);
        return RL_EINVAL;
    }
    p->fd = posix_openpt(O_RDWR | O_NOCTTY | (nonblock ? O_NONBLOCK : 0));
    if (p->fd < 0 || grantpt(p->fd) != 0 || unlockpt(p->fd) != 0 || (name = ptsname(p->fd)) == NULL) {
        snprintf(err, errlen, "%s: cannot create a pseudo-terminal: %s", link, strerror(errno));
        rl_ptylink_close(p);
        return RL_EIO;
    }
    snprintf(p->name, sizeof p->name, "%s", name);
    /* what occupied() let go: a stale link, or anything but a folder with force */
    if ((unlink(link) != 0 && errno != ENOENT) || symlink(p->name, link) != 0) {
        snprintf(err, errlen, "%s: %s", link, strerror(errno));
        p->name[0] = '\0';
        rl_ptylink_close(p);
        return RL_EIO;
    }
    return RL_OK;
}

void rl_ptylink_close(rl_ptylink *p)
{
    char target[256];
    if (p->name[0] && p->link) {
        link_target(p->link, target, sizeof target);
        if (strcmp(target, p->name) == 0)
            unlink(p->link);
    }
    p->name[0] = '\0';
    if (p->fd >= 0)
        close(p->fd);
    p->fd = -1;
}
