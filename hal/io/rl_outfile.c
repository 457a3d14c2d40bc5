#include "rl_outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
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

/* An existing target must be a regular file of ours; *st gets what it
 * was (st_mode 0: none, the umask decides the new file's mode). */
static rl_err check_target(const char *path, struct stat *st, char *err, size_t errlen)
{
    if (lstat(path, st) != 0) {
        st->st_mode = 0;
        return errno == ENOENT ? RL_OK : refuse(err, errlen, RL_EIO, path, strerror(errno));
    }
    if (S_ISLNK(st->st_mode))
        return refuse(err, errlen, RL_EINVAL, path, "is a symbolic link; not written through it "
                      "(give the file it points to)");
    if (!S_ISREG(st->st_mode))
        return refuse(err, errlen, RL_EINVAL, path, "not a regular file; not replaced");
    if (st->st_uid != geteuid())
        return refuse(err, errlen, RL_EINVAL, path, "belongs to another user; not replaced");
    return RL_OK;
}

/* The new file takes the old one's group and mode. The group first: a
 * change of group clears the set-id bits, which the mode then restores. A
 * group the user may not give (not one of theirs) is left as the system
 * made it; the mode is kept whatever the group. */
static int keep_owner_mode(int fd, const struct stat *st)
{
    if (st->st_mode == 0)
        return 0;
    (void)!fchown(fd, st->st_uid, st->st_gid);
    return fchmod(fd, st->st_mode & 07777);
}

/* Temporaries alive now, removed if SIGINT, SIGTERM or SIGHUP ends the
 * program before they are committed. A slot is 0 free, 1 being filled,
 * 2 armed; the handler only reads armed slots (async-signal-safe:
 * unlink and raise). More files open at once than slots: those extra
 * temporaries are not removed by a signal. */
#define LIVE_SLOTS 8
static char live_tmp[LIVE_SLOTS][RL_OUTFILE_PATH];
static volatile sig_atomic_t live_state[LIVE_SLOTS];
static volatile sig_atomic_t handlers_set;

static void on_fatal_signal(int sig)
{
    int i, saved = errno;
    for (i = 0; i < LIVE_SLOTS; i++)
        if (live_state[i] == 2)
            unlink(live_tmp[i]);
    errno = saved;
    raise(sig); /* SA_RESETHAND: the default action, once this returns */
}

/* Only where the program kept the default action: a program with its own
 * handler (a stop flag) ends its writes itself. */
static void set_handlers(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    size_t i;
    if (handlers_set)
        return;
    handlers_set = 1;
    for (i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        struct sigaction old, sa;
        if (sigaction(sigs[i], NULL, &old) != 0 || old.sa_handler != SIG_DFL)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_fatal_signal;
        sa.sa_flags = SA_RESETHAND;
        sigemptyset(&sa.sa_mask);
        sigaction(sigs[i], &sa, NULL);
    }
}

/* Arm o's temporary: its slot number, or -1 when all are taken. */
static int live_add(const char *tmp)
{
    int i;
    set_handlers();
    for (i = 0; i < LIVE_SLOTS; i++)
        if (__sync_bool_compare_and_swap(&live_state[i], 0, 1)) {
            snprintf(live_tmp[i], sizeof live_tmp[i], "%s", tmp);
            __sync_synchronize();
            live_state[i] = 2;
            return i;
        }
    return -1;
}

static void live_drop(rl_outfile *o)
{
    if (o->slot >= 0 && o->slot < LIVE_SLOTS)
        live_state[o->slot] = 0;
    o->slot = -1;
}

/* The longest name the target's folder takes. */
static size_t name_max(const char *path, int dirlen)
{
    char dir[RL_OUTFILE_PATH];
    long m;
    snprintf(dir, sizeof dir, "%.*s", dirlen, dirlen ? path : ".");
    m = pathconf(dir, _PC_NAME_MAX);
    return m > 16 ? (size_t)m : NAME_MAX;
}

/* ".NAME.tmpPID_N" in the target's folder, created exclusively (a name
 * someone else made, or a link, is passed over, never opened). A NAME too
 * long for the folder's limit with the additions is shortened in the
 * temporary's name (the rename gives the whole one). */
static int make_temp(rl_outfile *o)
{
    const char *slash = strrchr(o->path, '/');
    int dirlen = slash ? (int)(slash - o->path + 1) : 0;
    const char *base = o->path + dirlen;
    size_t limit = name_max(o->path, dirlen);
    unsigned n;
    for (n = 0; n < 100; n++) {
        char tail[48];
        size_t keep = strlen(base);
        int fd, len;
        snprintf(tail, sizeof tail, ".tmp%ld_%u", (long)getpid(), n);
        if (keep + 1 + strlen(tail) > limit)
            keep = limit - 1 - strlen(tail);
        len = snprintf(o->tmp, sizeof o->tmp, "%.*s.%.*s%s", dirlen, o->path, (int)keep, base, tail);
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
    struct stat st;
    int fd;
    rl_err e;
    memset(o, 0, sizeof *o);
    o->slot = -1;
    if (path == NULL || path[0] == '\0')
        return refuse(err, errlen, RL_EINVAL, "(no name)", "no file to write");
    if (strlen(path) >= sizeof o->path - 40)
        return refuse(err, errlen, RL_EINVAL, path, "path too long");
    snprintf(o->path, sizeof o->path, "%s", path);
    if ((e = check_target(path, &st, err, errlen)) != RL_OK)
        return e;
    if ((fd = make_temp(o)) < 0) {
        o->tmp[0] = '\0';
        return refuse(err, errlen, RL_EIO, path, strerror(errno));
    }
    o->slot = live_add(o->tmp);
    if (keep_owner_mode(fd, &st) != 0 || (o->f = fdopen(fd, "wb")) == NULL) {
        int en = errno;
        close(fd);
        unlink(o->tmp);
        o->tmp[0] = '\0';
        live_drop(o);
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
    live_drop(o); /* after the rename: a signal before it still removes the temporary */
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
    live_drop(o);
}
