#include "rl_http.h"

#include <arpa/inet.h>
#include <microhttpd.h>
#include <netinet/in.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <unistd.h>
#include "rl_clock.h"
#include "rl_http_req.h"
#include "rl_listen.h"
#include "rl_png.h"
#include "rl_view_focus.h"
#include "rl_view_jpeg.h"
#include "rl_view_json.h"

/* The page, built in from rl_view_page.html (rl_view_page.c, generated). */
extern const unsigned char rl_view_page[];
extern const size_t rl_view_page_len;

/* Snapshots kept: the page asks for the frame of the status it drew, by
 * seq, after other clients may have moved the newest on. */
#define RING 3

/* A connection's slot for the whole-request deadline: the time its
 * current request may have started (its opening, or the last answer). */
typedef struct {
    int used, shut, fd;
    uint64_t since_us;
} rl_http_slot;

struct rl_http {
    struct MHD_Daemon *d;
    rl_view *view;
    rl_view_snap ring[RING];
    void *ring_mem[RING];
    int newest;
    rl_view_jpeg *jpeg;
    char *status;             /* RL_VIEW_JSON_STATUS_MAX */
    char *map;                /* the map's JSON, made at start */
    size_t map_len;
    char token[RL_HTTP_MAX_TOKEN + 1];
    rl_http_counts counts;    /* the server thread's */
    int niced;                /* the server thread's priority lowered */
    long jpeg_seq;            /* the JPEG last encoded: of this snapshot ... */
    int jpeg_width;           /* ... at this width (two pages ask for the same) */
    size_t jpeg_len;
    uint8_t *png;             /* the last /snapshot.png ... */
    size_t png_cap, png_len;
    long png_seq;             /* ... of this snapshot */
    char self[256];           /* this computer's name, for the Host check */
    rl_view_geom geom;        /* the map into the image */
    long focus_seq;           /* the snapshot last measured for ... */
    double focus_best;        /* ... the sharpest frame's focus since start */
    long focus_best_frame;
    char cookie[RL_HTTP_MAX_TOKEN + 64]; /* Set-Cookie with the token */
    int set_cookie;           /* the request being answered gave the token in its URL */
    /* the deadline's watch: a thread that shuts a connection whose request
     * is not answered within deadline_us of its start, however it trickles */
    rl_http_slot *slots;
    int n_slots;
    uint64_t deadline_us;
    pthread_t watch;
    pthread_mutex_t lock;
    pthread_cond_t wake;
    int watching, quit;
    long late;                /* connections shut at the deadline (under lock) */
};

/* The newest snapshot, taken from the view when it has a newer one. */
static rl_view_snap *latest(rl_http *h)
{
    int next = (h->newest + 1) % RING;
    if (rl_view_seq(h->view) != h->ring[h->newest].seq) {
        h->ring[next].seq = h->ring[h->newest].seq; /* makes take copy the fields */
        if (rl_view_take(h->view, &h->ring[next]))
            h->newest = next;
    }
    return &h->ring[h->newest];
}

static rl_view_snap *by_seq(rl_http *h, long seq)
{
    int i;
    for (i = 0; seq > 0 && i < RING; i++)
        if (h->ring[i].seq == seq)
            return &h->ring[i];
    return latest(h);
}

static enum MHD_Result reply(rl_http *h, struct MHD_Connection *c, unsigned status, const char *type,
                             const void *p, size_t n, enum MHD_ResponseMemoryMode mode, long seq)
{
    const char *cookie = h->set_cookie ? h->cookie : NULL;
    struct MHD_Response *r = MHD_create_response_from_buffer(n, (void *)p, mode);
    enum MHD_Result ok;
    char s[32];
    if (r == NULL)
        return MHD_NO;
    MHD_add_response_header(r, "Content-Type", type);
    MHD_add_response_header(r, "Cache-Control", "no-store");
    MHD_add_response_header(r, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(r, "Content-Security-Policy",
                            "default-src 'self'; img-src 'self' blob:; style-src 'unsafe-inline'; "
                            "script-src 'unsafe-inline'; connect-src 'self'; frame-ancestors 'none'");
    if (seq > 0) {
        snprintf(s, sizeof s, "%ld", seq);
        MHD_add_response_header(r, "X-Ringloc-Seq", s);
    }
    if ((status == MHD_HTTP_OK || status == MHD_HTTP_SEE_OTHER) && cookie != NULL)
        MHD_add_response_header(r, "Set-Cookie", cookie);
    if (status == MHD_HTTP_SEE_OTHER)
        MHD_add_response_header(r, "Location", "/");
    if (status == MHD_HTTP_UNAUTHORIZED) {
        /* Basic first: a browser asks for it in its own prompt (any user
         * name, the token as the password); scripts send a Bearer */
        MHD_add_response_header(r, "WWW-Authenticate",
                                "Basic realm=\"ringloc: any user name, the access token as the password\", "
                                "charset=\"UTF-8\"");
        MHD_add_response_header(r, "WWW-Authenticate", "Bearer realm=\"ringloc\"");
    }
    ok = MHD_queue_response(c, status, r);
    MHD_destroy_response(r);
    return ok;
}

static enum MHD_Result refuse(rl_http *h, struct MHD_Connection *c, unsigned status, const char *why)
{
    char line[128];
    int n = snprintf(line, sizeof line, "%u %s\n", status, why);
    h->counts.refused++;
    return reply(h, c, status, "text/plain; charset=utf-8", line, (size_t)n, MHD_RESPMEM_MUST_COPY, 0);
}

static enum MHD_Result frame(rl_http *h, struct MHD_Connection *c, const rl_http_req *q)
{
    const rl_view_snap *s = q->seq > 0 ? by_seq(h, q->seq) : latest(h);
    int w = q->width ? q->width : s->width;
    const uint8_t *jpeg;
    size_t n;
    if (!s->have_image)
        return refuse(h, c, MHD_HTTP_SERVICE_UNAVAILABLE, "no frame yet");
    if (s->seq != h->jpeg_seq || w != h->jpeg_width) {
        h->jpeg_seq = 0;
        if (rl_view_jpeg_encode(h->jpeg, s->image, s->width, s->height, w, &jpeg, &n) != RL_OK)
            return refuse(h, c, MHD_HTTP_INTERNAL_SERVER_ERROR, "JPEG encoding failed");
        h->jpeg_seq = s->seq;
        h->jpeg_width = w;
        h->jpeg_len = n;
    }
    h->counts.served++;
    return reply(h, c, MHD_HTTP_OK, "image/jpeg", rl_view_jpeg_data(h->jpeg), h->jpeg_len, MHD_RESPMEM_MUST_COPY,
                 s->seq);
}

/* The sharpest frame's focus since start, counted once per snapshot. */
static void best_focus(rl_http *h, rl_view_snap *s)
{
    if (s->seq != h->focus_seq && s->have_image && s->have_result) {
        double f = rl_view_focus_frame(s->image, s->width, s->height, s->res, NULL);
        h->focus_seq = s->seq;
        if (f > h->focus_best) {
            h->focus_best = f;
            h->focus_best_frame = s->frame_index;
        }
    }
    s->focus_best = h->focus_best;
    s->focus_best_frame = h->focus_best_frame;
}

/* The frame as recognized, lossless (its status: /status.json?seq=). */
static enum MHD_Result snapshot(rl_http *h, struct MHD_Connection *c, const rl_http_req *q)
{
    const rl_view_snap *s = q->seq > 0 ? by_seq(h, q->seq) : latest(h);
    rl_image img;
    if (!s->have_image)
        return refuse(h, c, MHD_HTTP_SERVICE_UNAVAILABLE, "no frame yet");
    if (q->crop_size > 0) {
        /* a crop at 1:1, kept inside the frame (never cached) */
        int n = q->crop_size < s->width && q->crop_size < s->height ? q->crop_size
                : s->width < s->height ? s->width : s->height;
        int x0 = q->crop_x - n / 2, y0 = q->crop_y - n / 2;
        x0 = x0 < 0 ? 0 : x0 > s->width - n ? s->width - n : x0;
        y0 = y0 < 0 ? 0 : y0 > s->height - n ? s->height - n : y0;
        img.width = img.height = n;
        img.stride = s->width;
        img.data = s->image + (size_t)y0 * (size_t)s->width + (size_t)x0;
        h->png_seq = 0;
        if (rl_png_encode_gray(&img, h->png, h->png_cap, &h->png_len) != RL_OK)
            return refuse(h, c, MHD_HTTP_INTERNAL_SERVER_ERROR, "PNG encoding failed");
        h->counts.served++;
        return reply(h, c, MHD_HTTP_OK, "image/png", h->png, h->png_len, MHD_RESPMEM_MUST_COPY, s->seq);
    }
    if (s->seq != h->png_seq) {
        h->png_seq = 0;
        img.width = s->width;
        img.height = s->height;
        img.stride = s->width;
        img.data = s->image;
        if (rl_png_encode_gray(&img, h->png, h->png_cap, &h->png_len) != RL_OK)
            return refuse(h, c, MHD_HTTP_INTERNAL_SERVER_ERROR, "PNG encoding failed");
        h->png_seq = s->seq;
    }
    h->counts.served++;
    return reply(h, c, MHD_HTTP_OK, "image/png", h->png, h->png_len, MHD_RESPMEM_MUST_COPY, s->seq);
}

static enum MHD_Result respond(rl_http *h, struct MHD_Connection *c, const rl_http_req *q)
{
    size_t n;
    rl_view_snap *s;
    if (q->redirect) {
        static const char moved[] = "303 the token is kept in a cookie: /\n";
        h->counts.served++;
        return reply(h, c, MHD_HTTP_SEE_OTHER, "text/plain; charset=utf-8", moved, sizeof moved - 1,
                     MHD_RESPMEM_PERSISTENT, 0);
    }
    switch (q->route) {
    case RL_ROUTE_RECORD:
        rl_view_ask_record(h->view, q->on);
        h->counts.served++;
        return reply(h, c, MHD_HTTP_OK, "text/plain; charset=utf-8", q->on ? "recording asked to start\n"
                     : "recording asked to stop\n", q->on ? 25 : 24, MHD_RESPMEM_PERSISTENT, 0);
    case RL_ROUTE_SNAPSHOT:
        return snapshot(h, c, q);
    case RL_ROUTE_PAGE:
        h->counts.served++;
        return reply(h, c, MHD_HTTP_OK, "text/html; charset=utf-8", rl_view_page, rl_view_page_len,
                    MHD_RESPMEM_PERSISTENT, 0);
    case RL_ROUTE_MAP:
        h->counts.served++;
        return reply(h, c, MHD_HTTP_OK, "application/json", h->map, h->map_len, MHD_RESPMEM_PERSISTENT, 0);
    case RL_ROUTE_STATUS:
        s = q->seq > 0 ? by_seq(h, q->seq) : latest(h);
        s->served_us = rl_clock_now_us();
        s->geom = &h->geom;
        best_focus(h, s);
        if ((n = rl_view_json_status(s, h->status, RL_VIEW_JSON_STATUS_MAX)) == 0)
            return refuse(h, c, MHD_HTTP_INTERNAL_SERVER_ERROR, "status too large");
        h->counts.served++;
        return reply(h, c, MHD_HTTP_OK, "application/json", h->status, n, MHD_RESPMEM_MUST_COPY, s->seq);
    case RL_ROUTE_FRAME:
        return frame(h, c, q);
    default:
        return refuse(h, c, MHD_HTTP_NOT_FOUND, "no such page");
    }
}

/* A request came whole: the connection's next one is timed from now. */
static void answered(rl_http *h, struct MHD_Connection *c)
{
    const union MHD_ConnectionInfo *ci = MHD_get_connection_info(c, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
    rl_http_slot *s = ci != NULL ? (rl_http_slot *)ci->socket_context : NULL;
    if (s == NULL)
        return;
    pthread_mutex_lock(&h->lock);
    s->since_us = rl_clock_now_us();
    pthread_mutex_unlock(&h->lock);
}

/* Connections opened and closed (the server's thread; closed before the
 * socket is): each opened one takes a slot of the deadline's watch. */
static void on_connection(void *cls, struct MHD_Connection *c, void **ctx, enum MHD_ConnectionNotificationCode toe)
{
    rl_http *h = (rl_http *)cls;
    rl_http_slot *s = (rl_http_slot *)*ctx;
    int i;
    pthread_mutex_lock(&h->lock);
    if (toe == MHD_CONNECTION_NOTIFY_STARTED) {
        const union MHD_ConnectionInfo *ci = MHD_get_connection_info(c, MHD_CONNECTION_INFO_CONNECTION_FD);
        for (i = 0; i < h->n_slots && ci != NULL; i++)
            if (!h->slots[i].used) {
                h->slots[i].used = 1;
                h->slots[i].shut = 0;
                h->slots[i].fd = ci->connect_fd;
                h->slots[i].since_us = rl_clock_now_us();
                *ctx = &h->slots[i];
                break;
            }
    } else if (s != NULL) {
        s->used = 0;
        *ctx = NULL;
    }
    pthread_mutex_unlock(&h->lock);
}

/* The deadline's watch: a connection whose request is not whole within
 * the deadline of its start (a client trickling a byte at a time, which
 * an idle timeout never ends) is shut down; the server then closes it. */
static void *watch(void *arg)
{
    rl_http *h = (rl_http *)arg;
    pthread_mutex_lock(&h->lock);
    while (!h->quit) {
        struct timespec t;
        uint64_t now = rl_clock_now_us();
        int i;
        for (i = 0; i < h->n_slots; i++) {
            rl_http_slot *s = &h->slots[i];
            if (s->used && !s->shut && now > s->since_us + h->deadline_us) {
                (void)shutdown(s->fd, SHUT_RDWR);
                s->shut = 1;
                h->late++;
            }
        }
        clock_gettime(CLOCK_REALTIME, &t);
        t.tv_nsec += 250000000L;
        if (t.tv_nsec >= 1000000000L) {
            t.tv_sec++;
            t.tv_nsec -= 1000000000L;
        }
        pthread_cond_timedwait(&h->wake, &h->lock, &t);
    }
    pthread_mutex_unlock(&h->lock);
    return NULL;
}

static rl_err start_watch(rl_http *h, const rl_http_config *c)
{
    h->n_slots = c->max_clients > 0 ? c->max_clients : 1;
    h->deadline_us = (uint64_t)(c->timeout_s > 0 ? c->timeout_s : 1) * 1000000u;
    if ((h->slots = (rl_http_slot *)calloc((size_t)h->n_slots, sizeof *h->slots)) == NULL)
        return RL_ENOMEM;
    pthread_mutex_init(&h->lock, NULL);
    pthread_cond_init(&h->wake, NULL);
    if (pthread_create(&h->watch, NULL, watch, h) != 0) {
        pthread_mutex_destroy(&h->lock);
        pthread_cond_destroy(&h->wake);
        return RL_ENOMEM;
    }
    h->watching = 1;
    return RL_OK;
}

static void stop_watch(rl_http *h)
{
    if (h->watching) {
        pthread_mutex_lock(&h->lock);
        h->quit = 1;
        pthread_cond_signal(&h->wake);
        pthread_mutex_unlock(&h->lock);
        pthread_join(h->watch, NULL);
        pthread_mutex_destroy(&h->lock);
        pthread_cond_destroy(&h->wake);
        h->watching = 0;
    }
    free(h->slots);
}

static const char *arg(struct MHD_Connection *c, const char *key)
{
    return MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, key);
}

static enum MHD_Result on_request(void *cls, struct MHD_Connection *c, const char *url, const char *method,
                                  const char *version, const char *upload, size_t *upload_size, void **state)
{
    rl_http *h = (rl_http *)cls;
    rl_http_req_in in;
    rl_http_req q;
    (void)version;
    (void)upload;
    if (*state != NULL) {
        /* answered at its first call: a body sent with it is dropped */
        *upload_size = 0;
        return MHD_YES;
    }
    *state = h;
    if (!h->niced) {
        /* the loop first: where cores are short, the server waits (Linux
         * sets a nice value per thread) */
        (void)setpriority(PRIO_PROCESS, (id_t)syscall(SYS_gettid), 10);
        h->niced = 1;
    }
    in.method = method;
    in.url = url;
    in.w = arg(c, "w");
    in.seq = arg(c, "seq");
    in.token = arg(c, "token");
    in.auth = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "X-Ringloc-Token");
    if (in.auth == NULL)
        in.auth = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "Authorization");
    in.cookie = MHD_lookup_connection_value(c, MHD_COOKIE_KIND, "ringloc_token");
    in.host = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "Host");
    in.self = h->self;
    in.on = arg(c, "on");
    in.action = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "X-Ringloc-Action");
    in.x = arg(c, "x");
    in.y = arg(c, "y");
    in.size = arg(c, "size");
    answered(h, c);
    h->set_cookie = 0;
    if (rl_http_req_judge(&in, h->token, &q) != 200)
        return refuse(h, c, (unsigned)q.status, q.why);
    /* the token came in the URL: from now on the browser sends it as a
     * cookie, and the page takes it out of the address bar */
    h->set_cookie = q.set_cookie;
    return respond(h, c, &q);
}

/* libmicrohttpd's own messages (a client that sent garbage) are not the
 * robot's business: the client got its 4xx. */
static void quiet(void *cls, const char *fmt, va_list ap)
{
    (void)cls;
    (void)fmt;
    (void)ap;
}

static rl_err make_buffers(rl_http *h, const rl_map *map)
{
    rl_view_config vc;
    int i;
    vc = h->view->cfg;
    for (i = 0; i < RING; i++) {
        if ((h->ring_mem[i] = malloc(rl_view_size(&vc))) == NULL)
            return RL_ENOMEM;
        if (rl_view_snap_init(&h->ring[i], &vc, h->ring_mem[i], rl_view_size(&vc)) != RL_OK)
            return RL_ENOMEM;
    }
    h->status = (char *)malloc(RL_VIEW_JSON_STATUS_MAX);
    h->map = (char *)malloc(rl_view_json_map_size(map));
    h->jpeg = rl_view_jpeg_new(vc.width, vc.height);
    h->png_cap = rl_png_gray_max(vc.width, vc.height);
    h->png = (uint8_t *)malloc(h->png_cap);
    if (h->status == NULL || h->map == NULL || h->jpeg == NULL || h->png == NULL)
        return RL_ENOMEM;
    h->map_len = rl_view_json_map(map, h->map, rl_view_json_map_size(map));
    return h->map_len ? RL_OK : RL_ENOMEM;
}

static struct MHD_Daemon *listen_on(rl_http *h, const rl_http_config *c, const rl_listen *l)
{
    struct sockaddr_in a4;
    struct sockaddr_in6 a6;
    const struct sockaddr *a;
    memset(&a4, 0, sizeof a4);
    memset(&a6, 0, sizeof a6);
    if (l->ipv6) {
        a6.sin6_family = AF_INET6;
        a6.sin6_port = htons((uint16_t)l->port);
        (void)inet_pton(AF_INET6, l->host, &a6.sin6_addr);
        a = (const struct sockaddr *)&a6;
    } else {
        a4.sin_family = AF_INET;
        a4.sin_port = htons((uint16_t)l->port);
        (void)inet_pton(AF_INET, l->host, &a4.sin_addr);
        a = (const struct sockaddr *)&a4;
    }
    /* poll, not epoll: with epoll (libmicrohttpd 0.9.75) a server that
     * reached its connection limit stopped accepting for good once those
     * clients left (test_view_hostile's slowloris clients showed it) */
    return MHD_start_daemon(MHD_USE_POLL_INTERNAL_THREAD | (l->ipv6 ? MHD_USE_IPv6 : 0), (uint16_t)l->port,
                            NULL, NULL, on_request, h, MHD_OPTION_SOCK_ADDR, a,
                            MHD_OPTION_CONNECTION_LIMIT, (unsigned)c->max_clients,
                            MHD_OPTION_PER_IP_CONNECTION_LIMIT, (unsigned)c->max_per_client,
                            MHD_OPTION_NOTIFY_CONNECTION, on_connection, h,
                            MHD_OPTION_CONNECTION_TIMEOUT, (unsigned)c->timeout_s,
                            MHD_OPTION_CONNECTION_MEMORY_LIMIT, c->max_request,
                            MHD_OPTION_EXTERNAL_LOGGER, quiet, NULL, MHD_OPTION_END);
}

rl_err rl_http_start(rl_http **hp, const rl_http_config *c, rl_view *view, const rl_map *map, char *err,
                     size_t errlen)
{
    rl_listen l;
    rl_http *h;
    rl_err e;
    *hp = NULL;
    if (rl_listen_parse(c->listen ? c->listen : "", &l, err, errlen) != RL_OK)
        return RL_EFORMAT;
    if (c->token != NULL && strlen(c->token) > RL_HTTP_MAX_TOKEN) {
        snprintf(err, errlen, "the access token is longer than %d characters", RL_HTTP_MAX_TOKEN);
        return RL_EFORMAT;
    }
    if (c->token != NULL && c->token[strspn(c->token, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                       "0123456789-._~")] != 0) {
        /* it travels in a URL and a cookie as it is */
        snprintf(err, errlen, "the access token may hold letters, digits and -._~ only");
        return RL_EFORMAT;
    }
    if ((h = (rl_http *)calloc(1, sizeof *h)) == NULL)
        return RL_ENOMEM;
    h->view = view;
    h->geom.calib = c->calib;
    h->geom.map = c->calib != NULL && c->mount != NULL ? map : NULL;
    h->geom.mount = c->mount;
    snprintf(h->token, sizeof h->token, "%s", c->token ? c->token : "");
    snprintf(h->cookie, sizeof h->cookie, "ringloc_token=%s; Path=/; HttpOnly; SameSite=Strict", h->token);
    if (gethostname(h->self, sizeof h->self - 1) != 0)
        h->self[0] = 0;
    if ((e = make_buffers(h, map)) != RL_OK || (e = start_watch(h, c)) != RL_OK) {
        snprintf(err, errlen, "out of memory for the web view");
        rl_http_stop(h, NULL);
        return e;
    }
    if ((h->d = listen_on(h, c, &l)) == NULL) {
        snprintf(err, errlen, "cannot listen on %s (the port in use, or not this computer's address)",
                 c->listen);
        rl_http_stop(h, NULL);
        return RL_EIO;
    }
    *hp = h;
    return RL_OK;
}

void rl_http_stop(rl_http *h, rl_http_counts *counts)
{
    int i;
    if (counts != NULL)
        memset(counts, 0, sizeof *counts);
    if (h == NULL)
        return;
    if (h->d)
        MHD_stop_daemon(h->d); /* joins the server's thread */
    stop_watch(h);             /* the watch's too: the counts are final */
    if (counts != NULL) {
        *counts = h->counts;
        counts->refused += h->late;
    }
    for (i = 0; i < RING; i++)
        free(h->ring_mem[i]);
    rl_view_jpeg_free(h->jpeg);
    free(h->png);
    free(h->status);
    free(h->map);
    free(h);
}
