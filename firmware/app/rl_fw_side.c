/* rl_fw_side: recording and the web view beside the loop (rl_fw_side.h). */
#include "rl_fw_side.h"

#include <stdio.h>
#include <string.h>
#include <sys/random.h>
#include "rl_listen.h"

void rl_fw_side_init(rl_fw_side *s, const char *prefix, const rl_runner *runner, int w, int h)
{
    memset(s, 0, sizeof *s);
    rl_record_defaults(&s->rcc);
    s->listen = "";
    s->token = "";
    s->prefix = prefix;
    s->runner = runner;
    s->width = w;
    s->height = h;
    s->retry_us = RL_FW_SIDE_RETRY_US;
}

static int rec_wanted(const rl_fw_side *s)
{
    return s->rcc.dir != NULL && s->rcc.dir[0];
}

static int web_wanted(const rl_fw_side *s)
{
    return s->listen != NULL && s->listen[0];
}

/* A failed start: logged when its reason is new (a retry failing the same
 * way says nothing), kept as the note, tried again later. */
static void failed(rl_fw_side *s, char *note, size_t cap, const char *what, const char *err, uint64_t *retry_at,
                   uint64_t now)
{
    size_t n;
    if (strcmp(note, err) != 0)
        fprintf(stderr, "%s: %s; the robot's poses go on, %s tried again every %.0f s\n", s->prefix, err, what,
                s->retry_us / 1e6);
    n = strlen(err) < cap ? strlen(err) : cap - 1; /* the note may be cut: the log has it whole */
    memcpy(note, err, n);
    note[n] = '\0';
    *retry_at = now + s->retry_us;
}

static void try_recording(rl_fw_side *s, uint64_t now)
{
    char err[512], why[520];
    if (!rec_wanted(s) || s->rec.running || now < s->rec_retry_at)
        return;
    if (rl_record_start(&s->rec, &s->rcc, s->width, s->height, err, sizeof err) != RL_OK) {
        snprintf(why, sizeof why, "record: %s", err);
        failed(s, s->rec_note, sizeof s->rec_note, "recording", why, &s->rec_retry_at, now);
        return;
    }
    fprintf(stderr, "%s: recording one frame in %d to %s\n", s->prefix, s->rec.every, s->rec.dir);
    s->rec_note[0] = 0;
}

/* 1 when listen is on this computer only (127.0.0.0/8, ::1). */
static int loopback_only(const char *listen)
{
    rl_listen l;
    char err[160];
    if (rl_listen_parse(listen, &l, err, sizeof err) != RL_OK)
        return 1; /* refused at start anyway */
    return l.ipv6 ? strcmp(l.host, "::1") == 0 : strncmp(l.host, "127.", 4) == 0;
}

/* A web view heard beyond this computer without a token gets one made
 * up (32 hex digits from the kernel's random source), printed once. */
static void make_token(rl_fw_side *s)
{
    unsigned char b[16];
    int i;
    if (s->token != NULL && s->token[0])
        return;
    if (getrandom(b, sizeof b, 0) != (ssize_t)sizeof b) {
        fprintf(stderr, "%s: http: no random token could be made; the web view is open to anyone who can "
                        "reach %s (set http.token)\n", s->prefix, s->listen);
        return;
    }
    for (i = 0; i < 16; i++)
        snprintf(s->made_token + 2 * i, 3, "%02x", b[i]);
    s->token = s->made_token;
    fprintf(stderr, "%s: http: %s is heard beyond this computer and http.token is not set: the token for this "
                    "run is %s (open http://ADDRESS:PORT/?token=%s once; set http.token to choose one)\n",
            s->prefix, s->listen, s->made_token, s->made_token);
}

static void try_web(rl_fw_side *s, uint64_t now)
{
    char err[512];
    if (!web_wanted(s) || s->web.on || now < s->web_retry_at)
        return;
    if (!loopback_only(s->listen))
        make_token(s);
    if (rl_fw_http_start(&s->web, s->listen, s->token, s->width, s->height, s->site, s->map, s->runner, s->serial,
                         rec_wanted(s) ? &s->rec : NULL, err, sizeof err) != RL_OK) {
        failed(s, s->web_note, sizeof s->web_note, "the web view", err, &s->web_retry_at, now);
        return;
    }
    s->web.rv.rec_note = s->rec_note;
    fprintf(stderr, "%s: web view on http://%s/%s\n", s->prefix, s->listen,
            s->token && s->token[0] ? " (token required)" : "");
    s->web_note[0] = 0;
}

void rl_fw_side_start(rl_fw_side *s, uint64_t now_us)
{
    try_recording(s, now_us);
    try_web(s, now_us);
}

/* Recording started or stopped from the page: a stop only stops
 * offering frames (nothing in the loop waits for the writer), a start
 * offers them again, or tries a recorder that could not start at once. */
static void page_asked(rl_fw_side *s)
{
    int on = rl_view_record_asked(&s->web.view);
    if (on < 0 || !rec_wanted(s))
        return;
    s->rec_paused = !on;
    if (on)
        s->rec_retry_at = 0;
    snprintf(s->rec_note, sizeof s->rec_note, "%s", on ? "" : "stopped from the web view");
    fprintf(stderr, "%s: recording %s from the web view\n", s->prefix, on ? "started" : "stopped");
    s->web.rv.rec_paused = s->rec_paused;
}

void rl_fw_side_observe(void *ctx, const rl_run_report *rep)
{
    rl_fw_side *s = (rl_fw_side *)ctx;
    const char *news;
    if (s->web.on)
        page_asked(s);
    if (s->rec.running && !s->rec_paused && rep->frame != NULL) {
        rl_record_offer(&s->rec, &rep->frame->img, rep->frame->index, rep->frame->t_us);
        /* stopped by the writer (a full disk, the folder gone, max_mb):
         * said once, shown on the page, not restarted */
        if ((news = rl_record_news(&s->rec)) != NULL) {
            fprintf(stderr, "%s: %s\n", s->prefix, news);
            snprintf(s->rec_note, sizeof s->rec_note, "%s", news);
        }
    }
    if (s->web.on)
        rl_run_view_report(&s->web.rv, rep);
    rl_fw_side_start(s, rep->sent_us);
}

static void stop_recording(rl_fw_side *s)
{
    const char *news;
    if (!s->rec.running)
        return;
    rl_record_stop(&s->rec);
    /* a stop the writer met after the last frame is logged now */
    if ((news = rl_record_news(&s->rec)) != NULL)
        fprintf(stderr, "%s: %s\n", s->prefix, news);
    fprintf(stderr, "%s: recorded %ld frames (%.1f MB) to %s%s, %ld skipped while the disk was behind%s%s\n",
            s->prefix, s->rec.saved, s->rec.bytes / 1e6, s->rec.dir, s->rec.saved ? "" : " (removed: empty)",
            s->rec.skipped, s->rec.error[0] ? "; " : "", s->rec.error);
}

void rl_fw_side_stop(rl_fw_side *s)
{
    rl_fw_http_stop(&s->web, s->prefix);
    stop_recording(s);
}
