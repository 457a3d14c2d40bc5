#include "rl_record.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "rl_png.h"

void rl_record_defaults(rl_record_config *c)
{
    c->dir = NULL;
    c->every = 10;
    c->max_mb = 1000;
}

/* Stop recording with a reason (the writer's own state; the loop reads it
 * through rl_record_news). */
static void stop_with(rl_record *r, const char *what, int errnum)
{
    snprintf(r->error, sizeof r->error, "%s: %s; recording stopped", what, strerror(errnum));
    r->write_failed = 1;
}

/* Append the frame's line to frames.txt, whole or not at all (a part
 * written is cut off again). */
static int list_frame(rl_record *r, const char *name, uint64_t t_us)
{
    char line[96];
    int n = snprintf(line, sizeof line, "%s %llu\n", name, (unsigned long long)(t_us / 1000u));
    ssize_t w = write(r->list_fd, line, (size_t)n);
    if (w == n) {
        r->list_bytes += n;
        return 0;
    }
    if (w >= 0)
        errno = ENOSPC; /* a short write: the disk filled in the middle */
    {
        int en = errno;
        (void)ftruncate(r->list_fd, r->list_bytes);
        errno = en;
    }
    return -1;
}

/* Write slot s (the lock not held: the loop does not touch a full slot).
 * The frame is written through rl_outfile (a temporary, renamed when
 * whole: a failed frame leaves nothing behind) and listed after. */
static void write_slot(rl_record *r, int s)
{
    char name[64], path[600], err[900];
    rl_image img = rl_image_view(r->width, r->height, r->width, r->buf[s]);
    struct stat st;
    snprintf(name, sizeof name, "frame_%07ld.png", r->index[s]);
    snprintf(path, sizeof path, "%s/%s", r->dir, name);
    if (rl_png_write_gray(path, &img, err, sizeof err) != RL_OK) {
        snprintf(r->error, sizeof r->error, "%s; recording stopped", err);
        r->write_failed = 1;
        return;
    }
    if (list_frame(r, name, r->t_us[s]) != 0) {
        int en = errno;
        unlink(path); /* listed or not there: the drive stays consistent */
        snprintf(path, sizeof path, "%s/frames.txt", r->dir);
        stop_with(r, path, en);
        return;
    }
    if (stat(path, &st) == 0)
        r->bytes += (uint64_t)st.st_size;
    r->saved++;
    if (r->bytes >= r->max_bytes) {
        snprintf(r->error, sizeof r->error, "%s: %.1f MB on disk, the recording's max_mb; recording stopped",
                 r->dir, r->bytes / 1e6);
        r->write_failed = 1;
    }
}

static void *writer(void *arg)
{
    rl_record *r = (rl_record *)arg;
    pthread_mutex_lock(&r->lock);
    for (;;) {
        int s, next = -1;
        for (s = 0; s < RL_RECORD_SLOTS; s++)
            if (r->full[s] && (next < 0 || r->index[s] < r->index[next]))
                next = s;
        if (next < 0) {
            if (r->quit)
                break;
            pthread_cond_wait(&r->wake, &r->lock);
            continue;
        }
        {
            int stopped = r->stopped;
            pthread_mutex_unlock(&r->lock);
            if (!stopped)
                write_slot(r, next);
            pthread_mutex_lock(&r->lock);
            r->stopped |= r->write_failed;
            r->full[next] = 0;
        }
    }
    pthread_mutex_unlock(&r->lock);
    return NULL;
}

/* The folder (made if missing) must be a folder of the running user's, not
 * a link; the drive gets a new subfolder drive_NNN in it (mkdir is
 * exclusive: an earlier drive is never written into) with an empty
 * frames.txt made exclusively too. */
static rl_err make_drive_folder(rl_record *r, const char *dir, char *err, size_t errlen)
{
    struct stat st;
    int fd, n;
    if (mkdir(dir, 0755) != 0 && errno != EEXIST) {
        snprintf(err, errlen, "%s: cannot make the recording folder: %s", dir, strerror(errno));
        return RL_EIO;
    }
    if ((fd = open(dir, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC)) < 0 || fstat(fd, &st) != 0) {
        snprintf(err, errlen, "%s: not a folder (%s)", dir, strerror(errno == ELOOP ? ENOTDIR : errno));
        if (fd >= 0)
            close(fd);
        return RL_EIO;
    }
    if (st.st_uid != geteuid()) {
        close(fd);
        snprintf(err, errlen, "%s: belongs to another user; not recorded into", dir);
        return RL_EIO;
    }
    for (n = 1; n <= RL_RECORD_MAX_DRIVES; n++) {
        /* room for any int: GCC under the sanitizers (-O1) does not see
         * n's lower bound and warns of a truncation */
        char sub[24];
        snprintf(sub, sizeof sub, "drive_%03d", n);
        if (mkdirat(fd, sub, 0755) == 0)
            break;
        if (errno != EEXIST) {
            snprintf(err, errlen, "%s/%s: %s", dir, sub, strerror(errno));
            close(fd);
            return RL_EIO;
        }
    }
    close(fd);
    if (n > RL_RECORD_MAX_DRIVES) {
        snprintf(err, errlen, "%s: holds %d drives already; give another folder", dir, RL_RECORD_MAX_DRIVES);
        return RL_ELIMIT;
    }
    snprintf(r->dir, sizeof r->dir, "%s/drive_%03d", dir, n);
    {
        char list[600];
        snprintf(list, sizeof list, "%s/frames.txt", r->dir);
        r->list_fd = open(list, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_APPEND | O_CLOEXEC, 0644);
        if (r->list_fd < 0) {
            snprintf(err, errlen, "%s: %s", list, strerror(errno));
            (void)rmdir(r->dir);
            return RL_EIO;
        }
    }
    return RL_OK;
}

/* The drive's folder and its empty frames.txt removed (a start that failed,
 * or a run that recorded nothing): only what this run made. */
static void remove_drive(rl_record *r)
{
    char list[600];
    snprintf(list, sizeof list, "%s/frames.txt", r->dir);
    (void)unlink(list);
    (void)rmdir(r->dir);
}

rl_err rl_record_start(rl_record *r, const rl_record_config *c, int w, int h, char *err, size_t errlen)
{
    int s;
    rl_err e;
    memset(r, 0, sizeof *r);
    r->list_fd = -1;
    r->every = c->every > 0 ? c->every : 1;
    r->max_bytes = (uint64_t)(c->max_mb * 1e6);
    r->width = w;
    r->height = h;
    if (strlen(c->dir) > sizeof r->dir - 16) {
        snprintf(err, errlen, "%.200s...: recording folder's path too long", c->dir);
        return RL_EINVAL;
    }
    if ((e = make_drive_folder(r, c->dir, err, errlen)) != RL_OK)
        return e;
    for (s = 0; s < RL_RECORD_SLOTS; s++)
        if ((r->buf[s] = (uint8_t *)malloc((size_t)w * (size_t)h)) == NULL) {
            while (s-- > 0)
                free(r->buf[s]);
            close(r->list_fd);
            remove_drive(r);
            snprintf(err, errlen, "%s: out of memory for the recording's buffers", r->dir);
            return RL_ENOMEM;
        }
    pthread_mutex_init(&r->lock, NULL);
    pthread_cond_init(&r->wake, NULL);
    if (pthread_create(&r->writer, NULL, writer, r) != 0) {
        for (s = 0; s < RL_RECORD_SLOTS; s++)
            free(r->buf[s]);
        close(r->list_fd);
        remove_drive(r);
        snprintf(err, errlen, "%s: cannot start the recording's writer", r->dir);
        return RL_ENOMEM;
    }
    r->running = 1;
    return RL_OK;
}

const char *rl_record_news(rl_record *r)
{
    const char *news = NULL;
    if (!r->running) { /* stopped (the writer joined) or never started: no lock */
        if (!r->stopped || r->told)
            return NULL;
        r->told = 1;
        return r->error;
    }
    pthread_mutex_lock(&r->lock);
    if (r->stopped && !r->told) {
        r->told = 1;
        news = r->error;
    }
    pthread_mutex_unlock(&r->lock);
    return news;
}

void rl_record_offer(rl_record *r, const rl_image *img, long index, uint64_t t_us)
{
    int s, y, slot = -1, stopped;
    if (!r->running || img->width != r->width || img->height != r->height)
        return;
    if (r->offered++ % r->every != 0)
        return;
    pthread_mutex_lock(&r->lock);
    stopped = r->stopped;
    for (s = 0; s < RL_RECORD_SLOTS && slot < 0; s++)
        if (!r->full[s])
            slot = s;
    pthread_mutex_unlock(&r->lock);
    if (stopped)
        return;
    if (slot < 0) {
        r->skipped++; /* the disk is behind: this frame is not kept */
        return;
    }
    for (y = 0; y < img->height; y++)
        memcpy(r->buf[slot] + (size_t)y * (size_t)r->width, img->data + (size_t)y * (size_t)img->stride,
               (size_t)r->width);
    r->index[slot] = index;
    r->t_us[slot] = t_us;
    pthread_mutex_lock(&r->lock);
    r->full[slot] = 1;
    r->kept++;
    pthread_cond_signal(&r->wake);
    pthread_mutex_unlock(&r->lock);
}

void rl_record_stop(rl_record *r)
{
    int s;
    if (!r->running)
        return;
    pthread_mutex_lock(&r->lock);
    r->quit = 1;
    pthread_cond_signal(&r->wake);
    pthread_mutex_unlock(&r->lock);
    pthread_join(r->writer, NULL);
    pthread_mutex_destroy(&r->lock);
    pthread_cond_destroy(&r->wake);
    for (s = 0; s < RL_RECORD_SLOTS; s++)
        free(r->buf[s]);
    close(r->list_fd);
    r->list_fd = -1;
    r->running = 0;
    if (r->saved == 0 && r->list_bytes == 0)
        remove_drive(r);
}
