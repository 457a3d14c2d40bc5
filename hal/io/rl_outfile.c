#include "rl_outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef O_CLOEXEC
#define O_CLOEXEC 0
#endif

static rl_err refuse(char *err, size_t errlen, rl_err e, const char *path, const char *why)
{
    snprintf(err, errlen, "%s: %s", path, why);
    return e;
}

/* An existing target must be a regular file of ours; its mode is kept
 * (*mode -1: none, the umask decides). */
static rl_err check_target(const char *path, int *mode, char *err, size_t errlen)
{
    struct stat st;
    *mode = -1;
    if (lstat(path, &st) != 0)
        return errno == ENOENT ? RL_OK : refuse(err, errlen, RL_EIO, path, strerror(errno));
    if (S_ISLNK(st.st_mode))
        return refuse(err, errlen, RL_EINVAL, path, "is a symbolic link; not written through it "
                      "(give the file it points to)");
    if (!S_ISREG(st.st_mode))
        return refuse(err, errlen, RL_EINVAL, path, "not a regular file; not replaced");
    if (st.st_uid != geteuid())
        return refuse(err, errlen, RL_EINVAL, path, "belongs to another user; not replaced");
    *mode = (int)(st.st_mode & 07777);
    return RL_OK;
}

/* ".NAME.tmpPID_N" in the target's folder, created exclusively (a name
 * someone else made, or a link, is passed over, never opened). */
static int make_temp(rl_outfile *o)
{
    const char *slash = strrchr(o->path, '/');
    int dirlen = slash ? (int)(slash - o->path + 1) : 0;
    const char *base = o->path + dirlen;
    unsigned n;
    for (n = 0; n < 100; n++) {
        int fd, len = snprintf(o->tmp, sizeof o->tmp, "%.*s.%s.tmp%ld_%u", dirlen, o->path, base,
                               (long)getpid(), n);
        if (len < 0 || (size_t)len >= sizeof o->tmp) {
            errno = ENAMETOOLONG;
            return -1;
        }
        fd = open(o->tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    return -1;
}

rl_err rl_outfile_open(rl_outfile *o, const char *path, char *err, size_t errlen)
{
    int fd, mode;
    rl_err e;
    memset(o, 0, sizeof *o);
    if (path == NULL || path[0] == '\0')
        return refuse(err, errlen, RL_EINVAL, "(no name)", "no file to write");
    if (strlen(path) >= sizeof o->path - 40)
        return refuse(err, errlen, RL_EINVAL, path, "path too long");
    snprintf(o->path, sizeof o->path, "%s", path);
    if ((e = check_target(path, &mode, err, errlen)) != RL_OK)
        return e;
    if ((fd = make_temp(o)) < 0) {
        o->tmp[0] = '\0';
        return refuse(err, errlen, RL_EIO, path, strerror(errno));
    }
    if ((mode >= 0 && fchmod(fd, (mode_t)mode) != 0) || (o->f = fdopen(fd, "wb")) == NULL) {
        int en = errno;
        close(fd);
        unlink(o->tmp);
        o->tmp[0] = '\0';
        return refuse(err, errlen, RL_EIO, path, strerror(en));
    }
    return RL_OK;
}

int rl_outfile_write(rl_outfile *o, const void *p, size_t n)
{
    if (o->errnum != 0 || o->f == NULL)
        return -1;
    if (n > 0 && fwrite(p, 1, n, o->f) != n) {
        rl_outfile_set_error(o, errno);
        return -1;
    }
    return 0;
}

void rl_outfile_set_error(rl_outfile *o, int errnum)
{
    if (o->errnum == 0)
        o->errnum = errnum != 0 ? errnum : EIO;
}

/* Make the rename durable: the folder's entry synced (where a folder can
 * be opened for it; a failure here leaves the new file in place). */
static void sync_folder(const char *path)
{
    char dir[RL_OUTFILE_PATH];
    const char *slash = strrchr(path, '/');
    int fd;
    if (slash == NULL)
        snprintf(dir, sizeof dir, ".");
    else
        snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
    if ((fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC)) >= 0) {
        (void)fsync(fd);
        close(fd);
    }
}

rl_err rl_outfile_commit(rl_outfile *o, char *err, size_t errlen)
{
    if (o->f == NULL)
        return refuse(err, errlen, RL_EIO, o->path, "not open");
    errno = 0;
    if (fflush(o->f) != 0 || ferror(o->f))
        rl_outfile_set_error(o, errno);
    if (o->errnum == 0 && fsync(fileno(o->f)) != 0 && errno != EINVAL)
        rl_outfile_set_error(o, errno); /* EINVAL: a file system without fsync */
    errno = 0;
    if (fclose(o->f) != 0)
        rl_outfile_set_error(o, errno);
    o->f = NULL;
    if (o->errnum == 0 && rename(o->tmp, o->path) != 0)
        rl_outfile_set_error(o, errno);
    if (o->errnum != 0) {
        rl_outfile_abort(o);
        return refuse(err, errlen, RL_EIO, o->path, strerror(o->errnum));
    }
    o->tmp[0] = '\0';
    sync_folder(o->path);
    return RL_OK;
}

void rl_outfile_abort(rl_outfile *o)
{
    if (o->f != NULL)
        fclose(o->f);
    o->f = NULL;
    if (o->tmp[0])
        unlink(o->tmp);
    o->tmp[0] = '\0';
}
