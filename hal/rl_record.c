#include "rl_record.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "rl_png.h"

void rl_record_defaults(rl_record_config *c)
{
    c->dir = NULL;
    c->every = 10;
    c->max_mb = 1000;
}

/* Write slot s (the lock not held: the loop does not touch a full slot). */
static void write_slot(rl_record *r, int s)
{
    char name[64], path[600], err[512];
    rl_image img = rl_image_view(r->width, r->height, r->width, r->buf[s]);
    struct stat st;
    FILE *list;
    snprintf(name, sizeof name, "frame_%07ld.png", r->index[s]);
    snprintf(path, sizeof path, "%s/%s", r->dir, name);
    if (rl_png_write_gray(path, &img, err, sizeof err) != RL_OK) {
        snprintf(r->error, sizeof r->error, "%s", err);
        r->write_failed = 1;
        return;
    }
    if (stat(path, &st) == 0)
        r->bytes += (uint64_t)st.st_size;
    snprintf(path, sizeof path, "%s/frames.txt", r->dir);
    if ((list = fopen(path, "a")) == NULL || fprintf(list, "%s %llu\n", name,
                                                       (unsigned long long)(r->t_us[s] / 1000u)) < 0) {
        snprintf(r->error, sizeof r->error, "%s: %s", path, strerror(errno));
        r->write_failed = 1;
    }
    if (list != NULL && fclose(list) != 0 && !r->write_failed) {
        snprintf(r->error, sizeof r->error, "%s: %s", path, strerror(errno));
        r->write_failed = 1;
    }
    r->saved++;
    if (!r->write_failed && r->bytes >= r->max_bytes) {
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

rl_err rl_record_start(rl_record *r, const rl_record_config *c, int w, int h, char *err, size_t errlen)
{
    struct stat st;
    int s;
    memset(r, 0, sizeof *r);
    snprintf(r->dir, sizeof r->dir, "%s", c->dir);
    r->every = c->every > 0 ? c->every : 1;
    r->max_bytes = (uint64_t)(c->max_mb * 1e6);
    r->width = w;
    r->height = h;
    if (mkdir(r->dir, 0755) != 0 && errno != EEXIST) {
        snprintf(err, errlen, "%s: cannot make the recording folder: %s", r->dir, strerror(errno));
        return RL_EIO;
    }
    if (stat(r->dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        snprintf(err, errlen, "%s: not a folder", r->dir);
        return RL_EIO;
    }
    for (s = 0; s < RL_RECORD_SLOTS; s++)
        if ((r->buf[s] = (uint8_t *)malloc((size_t)w * (size_t)h)) == NULL) {
            while (s-- > 0)
                free(r->buf[s]);
            snprintf(err, errlen, "%s: out of memory for the recording's buffers", r->dir);
            return RL_ENOMEM;
        }
    pthread_mutex_init(&r->lock, NULL);
    pthread_cond_init(&r->wake, NULL);
    if (pthread_create(&r->writer, NULL, writer, r) != 0) {
        for (s = 0; s < RL_RECORD_SLOTS; s++)
            free(r->buf[s]);
        snprintf(err, errlen, "%s: cannot start the recording's writer", r->dir);
        return RL_ENOMEM;
    }
    r->running = 1;
    return RL_OK;
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
    r->running = 0;
}
