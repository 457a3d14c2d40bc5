/* PNG-sequence camera: a directory of PNGs (sorted by name) or a text file
 * listing one PNG per line, played at a rate. Every frame is decoded at
 * open, so grabbing never allocates or touches the disk. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "rl_cam.h"
#include "rl_png.h"

typedef struct {
    rl_image *frames;
    int n;
    long next;
    uint64_t t0, period_us;
    int loop;
} png_state;

static void png_close(rl_cam *c)
{
    png_state *s = (png_state *)c->state;
    int i;
    if (s == NULL)
        return;
    for (i = 0; i < s->n; i++)
        rl_png_free(&s->frames[i]);
    free(s->frames);
    free(s);
}

static rl_err png_grab(rl_cam *c, int timeout_ms, rl_cam_frame *f)
{
    png_state *s = (png_state *)c->state;
    uint64_t due, now;
    if (s->next >= s->n && !s->loop)
        return RL_ENOTFOUND;
    /* pace to the rate: frame k is due at t0 + k * period */
    due = s->t0 + (uint64_t)s->next * s->period_us;
    now = rl_clock_now_us();
    if (due > now) {
        uint64_t wait = due - now;
        if (timeout_ms >= 0 && wait > (uint64_t)timeout_ms * 1000u) {
            rl_clock_sleep_us((uint64_t)timeout_ms * 1000u);
            return RL_ETIMEOUT;
        }
        rl_clock_sleep_us(wait);
    }
    f->index = s->next;
    f->slot = (int)(s->next % s->n);
    f->img = s->frames[f->slot];
    f->t_us = rl_clock_now_us();
    s->next++;
    return RL_OK;
}

static void png_release(rl_cam *c, rl_cam_frame *f)
{
    (void)c;
    (void)f;
}

static const rl_cam_ops png_ops = {png_grab, png_release, png_close};

rl_err rl_cam_open_png(rl_cam *c, const rl_cam_config *cc, char *err, size_t errlen)
{
    char **names = NULL, line[1024];
    int n = 0, cap = 0, i;
    struct stat st;
    png_state *s;
    rl_err e = RL_OK;
    const char *dev = cc->device;
    if (dev == NULL || stat(dev, &st) != 0) {
        snprintf(err, errlen, "%s: %s", dev ? dev : "(none)", dev ? strerror(errno) : "no PNG directory or list given");
        return RL_ENOTFOUND;
    }
    if (S_ISDIR(st.st_mode)) {
        if ((e = rl_png_list(dev, &names, &n, err, errlen)) != RL_OK)
            return e;
        cap = n;
    } else {
        /* a list file: one PNG per line, relative to the list's folder */
        FILE *f = fopen(dev, "r");
        const char *slash = strrchr(dev, '/');
        int dirlen = slash ? (int)(slash - dev + 1) : 0;
        if (f == NULL) {
            snprintf(err, errlen, "%s: %s", dev, strerror(errno));
            return RL_ENOTFOUND;
        }
        while (fgets(line, sizeof line, f)) {
            size_t len;
            line[strcspn(line, "\r\n")] = '\0';
            if (line[0] == '\0' || line[0] == '#')
                continue;
            if (n == cap) {
                char **more = realloc(names, sizeof *names * (size_t)(cap ? 2 * cap : 64));
                if (more == NULL)
                    break;
                names = more;
                cap = cap ? 2 * cap : 64;
            }
            len = (size_t)dirlen + strlen(line) + 1;
            if ((names[n] = malloc(len)) == NULL)
                break;
            if (line[0] == '/')
                snprintf(names[n], len, "%s", line);
            else
                snprintf(names[n], len, "%.*s%s", dirlen, dev, line);
            n++;
        }
        if (!feof(f)) {
            fclose(f);
            rl_png_list_free(names, n);
            snprintf(err, errlen, "%s: out of memory reading the list", dev);
            return RL_ENOMEM;
        }
        fclose(f);
    }
    if (n == 0) {
        snprintf(err, errlen, "%s: no PNG frames", dev);
        rl_png_list_free(names, 0);
        return RL_ENOTFOUND;
    }
    s = calloc(1, sizeof *s);
    if (s == NULL || (s->frames = calloc((size_t)n, sizeof *s->frames)) == NULL) {
        free(s);
        rl_png_list_free(names, n);
        snprintf(err, errlen, "%s: out of memory for %d frames", dev, n);
        return RL_ENOMEM;
    }
    for (i = 0; i < n; i++) {
        if (e == RL_OK && (e = rl_png_read_gray(names[i], &s->frames[i], err, errlen)) == RL_OK) {
            s->n++;
            if ((cc->width && s->frames[i].width != cc->width) ||
                (cc->height && s->frames[i].height != cc->height)) {
                snprintf(err, errlen, "%s: frame is %dx%d, the camera is configured for %dx%d",
                         names[i], s->frames[i].width, s->frames[i].height, cc->width, cc->height);
                e = RL_EINVAL;
            }
        }
        free(names[i]);
    }
    free(names);
    c->state = s;
    c->ops = &png_ops;
    if (e != RL_OK) {
        rl_cam_close(c);
        return e;
    }
    s->loop = cc->loop;
    s->period_us = cc->rate > 0 ? (uint64_t)(1e6 / cc->rate) : 0;
    s->t0 = rl_clock_now_us();
    return RL_OK;
}
