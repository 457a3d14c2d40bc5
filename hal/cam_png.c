/* PNG-sequence camera: a directory of PNGs (sorted by name), a text file
 * listing one PNG per line (relative to the list's folder), or the files
 * a command line names, played at a rate (frame k's capture time t0 + k
 * periods, its due time, t0 the opening's), or as fast as they decode (its
 * grab's). A loop slower than the rate takes each frame late; once a grab
 * comes more than a second (or three periods, if longer) after its due
 * time, t0 moves so that frame is due at its grab: the times show one gap,
 * as a camera's that dropped frames, and the latency stops growing. A frame is decoded when it is grabbed, into one block sized at
 * open, so memory does not grow with the list and grabbing never
 * allocates; a list file is read a line at a time. A frame that cannot be
 * read, or is not the camera's size, is reported (RL_EFORMAT, the reason
 * in c->error) and skipped; with loop set the sequence starts again at its
 * end. Files named on a command line without a size may each have their
 * own: the block then grows to the largest (the desktop's case). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "rl_cam.h"
#include "rl_infile.h"
#include "rl_png.h"

typedef struct {
    char **names;          /* a directory's PNGs, or NULL for a list file */
    const char *const *files; /* or the files given (not owned) */
    int any_size;          /* files without a configured size: each frame its own */
    int n, at;             /* names, and the next one */
    FILE *list;            /* a list file, read as frames are grabbed */
    int dirlen;            /* the list's folder: its first dirlen characters */
    char dev[512], path[1600];
    int width, height;     /* every frame's size */
    void *block;
    size_t cap;
    long next;
    uint64_t t0, period_us;
    int loop;
    int held;              /* s->path is a frame a grab timed out before: the next grab's */
} png_state;

static void png_close(rl_cam *c)
{
    png_state *s = (png_state *)c->state;
    if (s == NULL)
        return;
    if (s->files == NULL)
        rl_png_list_free(s->names, s->n);
    if (s->list != NULL)
        fclose(s->list);
    free(s->block);
    free(s);
}

/* The next frame's path into s->path; 0 at the end of the sequence. */
static int next_name(png_state *s)
{
    char line[1024];
    if (s->list == NULL) {
        if (s->at == s->n)
            return 0;
        snprintf(s->path, sizeof s->path, "%s", s->files ? s->files[s->at++] : s->names[s->at++]);
        return 1;
    }
    while (fgets(line, sizeof line, s->list) != NULL) {
        line[strcspn(line, "\r\n")] = '\0';
        if (line[0] == '\0' || line[0] == '#')
            continue;
        if (line[0] == '/')
            snprintf(s->path, sizeof s->path, "%s", line);
        else
            snprintf(s->path, sizeof s->path, "%.*s%s", s->dirlen, s->dev, line);
        return 1;
    }
    return 0;
}

static void rewind_names(png_state *s)
{
    s->at = 0;
    s->held = 0;
    if (s->list != NULL)
        rewind(s->list);
}

rl_err rl_cam_png_fit(const char *path, void **block, size_t *cap, int *w, int *h, char *err, size_t errlen)
{
    size_t need;
    void *grown;
    rl_err e;
    if ((e = rl_png_size(path, w, h, err, errlen)) != RL_OK)
        return e;
    if ((need = rl_png_block_size(*w, *h)) <= *cap)
        return RL_OK;
    if ((grown = realloc(*block, need)) == NULL) {
        snprintf(err, errlen, "%.160s: out of memory for %dx%d", path, *w, *h);
        return RL_ENOMEM;
    }
    *block = grown;
    *cap = need;
    return RL_OK;
}

/* Files of any size: the block made large enough for the next one. */
static rl_err grow_for(png_state *s, char *err, size_t errlen)
{
    int w, h;
    return rl_cam_png_fit(s->path, &s->block, &s->cap, &w, &h, err, errlen);
}

/* How far behind its due time a grab may come before the frames are
 * re-timed: the larger of a second and LAG_PERIODS periods. Within it a
 * loop catches up after a slow frame (a full search after a lost track)
 * and the replay keeps its times; a second holds a 30-frame hiccup at 30
 * frames a second, and LAG_PERIODS periods one of a few frames at a slow
 * rate. Beyond it a frame's latency (the pose packet's, capped at 6.55 s)
 * would only grow; the bound stays under that cap down to 0.46 frames a
 * second. */
#define LAG_PERIODS 3
static uint64_t behind_bound(uint64_t period_us)
{
    return period_us * LAG_PERIODS > 1000000u ? period_us * LAG_PERIODS : 1000000u;
}

static rl_err png_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f)
{
    png_state *s = (png_state *)c->state;
    uint64_t due, now;
    rl_err e;
    char err[sizeof c->error];
    if (s->held) {
        s->held = 0; /* a grab timed out before this frame was due: still the next */
    } else if (!next_name(s)) {
        if (!s->loop)
            return RL_ENOTFOUND;
        rewind_names(s);
        if (!next_name(s))
            return RL_ENOTFOUND; /* the list was emptied while playing */
    }
    /* pace to the rate: frame k is due at t0 + k * period */
    due = s->t0 + (uint64_t)s->next * s->period_us;
    now = rl_clock_now_us();
    if (s->period_us > 0 && now > due && now - due > behind_bound(s->period_us)) {
        /* the loop cannot keep the rate: this frame is due now, the ones
         * after it a period apart (one gap, as a camera dropping frames) */
        s->t0 = now - (uint64_t)s->next * s->period_us;
        due = now;
    }
    if (due > now) {
        uint64_t wait = due - now;
        if (timeout_ms >= 0 && wait > (uint64_t)timeout_ms * 1000u) {
            rl_clock_sleep_us((uint64_t)timeout_ms * 1000u);
            s->held = 1; /* not taken: the next grab plays it */
            return RL_ETIMEOUT;
        }
        rl_clock_sleep_us(wait);
    }
    f->index = s->next++;
    f->slot = 0;
    f->name = s->path;
    /* played at a rate, a frame's capture time is when it was due, not
     * when the loop came for it: the times a replay gives the loop (its
     * track's and prior's, a rolling shutter's moves) and the pose frames'
     * time_ms then come from the files and the rate alone, whatever the
     * machine's load, as long as the loop keeps within behind_bound of
     * them; a frame grabbed late is as old as it is (the pose frame's
     * latency). As fast as they decode, no frame is due: the grab's */
    f->t_us = s->period_us > 0 ? due : rl_clock_now_us();
    e = s->any_size ? grow_for(s, err, sizeof err) : RL_OK;
    if (e == RL_OK)
        e = rl_png_read_gray_into(s->path, s->block, s->cap, &f->img, err, sizeof err);
    if (e == RL_OK && !s->any_size && (f->img.width != s->width || f->img.height != s->height)) {
        snprintf(err, sizeof err, "%.160s: image is %dx%d but the camera is set to %dx%d", s->path,
                 f->img.width, f->img.height, s->width, s->height);
        e = RL_EFORMAT;
    }
    if (e != RL_OK) {
        snprintf(c->error, sizeof c->error, "%s", err);
        memset(&f->img, 0, sizeof f->img);
        return RL_EFORMAT;
    }
    return RL_OK;
}

static void png_release(rl_cam *c, rl_cam_frame *f)
{
    (void)c;
    (void)f;
}

static const rl_cam_ops png_ops = {png_grab, png_release, png_close};

/* The frames' size: the configured one, else the first frame whose
 * header reads. */
static rl_err frame_size(png_state *s, const rl_cam_config *cc, char *err, size_t errlen)
{
    char first[320];
    int tried = 0;
    if (!next_name(s)) {
        snprintf(err, errlen, "%s: no PNG frames", s->dev);
        return RL_ENOTFOUND;
    }
    rewind_names(s);
    if (cc->width > 0 && cc->height > 0) {
        s->width = cc->width;
        s->height = cc->height;
        return RL_OK;
    }
    first[0] = '\0';
    while (next_name(s)) {
        char why[320];
        if (rl_png_size(s->path, &s->width, &s->height, why, sizeof why) == RL_OK &&
            (cc->width <= 0 || s->width == cc->width) && (cc->height <= 0 || s->height == cc->height)) {
            rewind_names(s);
            return RL_OK;
        }
        if (tried++ == 0)
            snprintf(first, sizeof first, "%s", why);
    }
    rewind_names(s);
    snprintf(err, errlen, "%s: no readable PNG frame (the first: %s)", s->dev, first);
    return RL_ENOTFOUND;
}

/* The files a command line named, in its order. */
static rl_err open_files(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    png_state *s;
    if (cc->n_files <= 0) {
        snprintf(err, errlen, "no PNG files given");
        return RL_ENOTFOUND;
    }
    if ((s = calloc(1, sizeof *s)) == NULL) {
        snprintf(err, errlen, "out of memory");
        return RL_ENOMEM;
    }
    c->state = s;
    c->ops = &png_ops;
    s->files = cc->files;
    s->n = cc->n_files;
    s->any_size = !(cc->width > 0 && cc->height > 0);
    snprintf(s->dev, sizeof s->dev, "%d files", cc->n_files);
    s->width = cc->width;
    s->height = cc->height;
    if (!s->any_size && (s->block = malloc(s->cap = rl_png_block_size(s->width, s->height))) == NULL) {
        rl_cam_close(c);
        snprintf(err, errlen, "out of memory for %dx%d frames", cc->width, cc->height);
        return RL_ENOMEM;
    }
    s->loop = cc->loop;
    s->period_us = cc->rate > 0 ? (uint64_t)(1e6 / cc->rate) : 0;
    s->t0 = rl_clock_now_us();
    return RL_OK;
}

rl_err rl_cam_open_png(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    struct stat st;
    png_state *s;
    rl_err e;
    const char *dev = cc->device, *slash;
    if (cc->files != NULL)
        return open_files(c, cc, err, errlen);
    if (dev == NULL || dev[0] == '\0' || stat(dev, &st) != 0) {
        snprintf(err, errlen, "%s: %s", dev && dev[0] ? dev : "(none)",
                 dev && dev[0] ? strerror(errno) : "no PNG directory or list given");
        return RL_ENOTFOUND;
    }
    if ((s = calloc(1, sizeof *s)) == NULL) {
        snprintf(err, errlen, "%s: out of memory", dev);
        return RL_ENOMEM;
    }
    c->state = s;
    c->ops = &png_ops;
    snprintf(s->dev, sizeof s->dev, "%s", dev);
    slash = strrchr(s->dev, '/');
    s->dirlen = slash ? (int)(slash - s->dev + 1) : 0;
    if (S_ISDIR(st.st_mode))
        e = rl_png_list(dev, &s->names, &s->n, err, errlen);
    else if ((s->list = rl_infile_fopen(dev, "a folder of PNG images or a list of them", &e, err, errlen)) == NULL)
        e = e == RL_EIO ? RL_ENOTFOUND : e;
    else
        e = RL_OK;
    if (e == RL_OK)
        e = frame_size(s, cc, err, errlen);
    if (e == RL_OK) {
        s->cap = rl_png_block_size(s->width, s->height);
        if ((s->block = malloc(s->cap)) == NULL) {
            snprintf(err, errlen, "%s: out of memory for %dx%d frames", dev, s->width, s->height);
            e = RL_ENOMEM;
        }
    }
    if (e != RL_OK) {
        rl_cam_close(c);
        return e;
    }
    s->loop = cc->loop;
    s->period_us = cc->rate > 0 ? (uint64_t)(1e6 / cc->rate) : 0;
    s->t0 = rl_clock_now_us();
    return RL_OK;
}

rl_err rl_cam_probe_png(const rl_cam_config *cc, rl_cam_line_fn line, void *ctx, char *err, size_t errlen)
{
    rl_cam c;
    png_state *s;
    char text[700];
    long n = 0, bad = 0;
    int w = 0, h = 0;
    rl_err e;
    memset(&c, 0, sizeof c);
    if ((e = rl_cam_open_png(&c, cc, err, errlen)) != RL_OK)
        return e;
    s = (png_state *)c.state;
    while (next_name(s)) {
        char why[320];
        n++;
        if (rl_png_size(s->path, &w, &h, why, sizeof why) != RL_OK || w != s->width || h != s->height)
            bad++;
    }
    char rate[48];
    if (cc->rate > 0)
        snprintf(rate, sizeof rate, "%g frames per second", cc->rate);
    else
        snprintf(rate, sizeof rate, "as fast as they decode");
    snprintf(text, sizeof text, "png %s: %ld frames of %dx%d%s, %ld not readable or of another size, "
             "played at %s%s", s->dev, n, s->width, s->height, cc->width > 0 ? " (configured)" : "", bad,
             rate, cc->loop ? ", looping" : "");
    line(ctx, text);
    rl_cam_close(&c);
    return RL_OK;
}
