/* rl_http_req: one request to the live web view judged, before anything
 * is served, in this order: the access token when one is configured (the
 * query's ?token=, an "Authorization: Bearer" or "X-Ringloc-Token" header,
 * "Authorization: Basic" with the token as the password (a browser's own
 * prompt, asked for by the 401's WWW-Authenticate: Basic),
 * or the ringloc_token cookie set after the first request that gave it,
 * compared in constant time: nothing, not even a 404, is answered before
 * it), the Host header (an IP address, localhost, or this computer's name,
 * with or without ".local": a DNS-rebinding page that calls the robot by
 * its own name is refused), the method (GET or HEAD; POST for /record
 * only, with the X-Ringloc-Action header, which a page of another site
 * cannot send without asking first), the path (one of the seven routes;
 * nothing is ever served from disk) and the query's numbers
 * (w, the JPEG's width; seq, the snapshot an overlay was drawn for). Pure:
 * no I/O, no allocation, any bytes in (the fuzz target's contract).
 *
 *   rl_http_req_in in = {"GET", "/frame.jpg", "320", NULL, NULL, NULL, NULL, "127.0.0.1:8080", NULL,
 *                         NULL, NULL, NULL, NULL, NULL};
 *   rl_http_req r;
 *   if (rl_http_req_judge(&in, "", &r) == 200)
 *       use(r.route, r.width);          // RL_ROUTE_FRAME, 320
 *   else
 *       use(r.why);                     // "w is not a width (16 .. 8192)"
 */
#ifndef RL_HTTP_REQ_H
#define RL_HTTP_REQ_H

#define RL_HTTP_MAX_URL 64     /* longer paths are refused (414) */
#define RL_HTTP_MAX_TOKEN 128  /* longest access token */

typedef enum {
    RL_ROUTE_NONE = 0,
    RL_ROUTE_PAGE,    /* / and /index.html: the page */
    RL_ROUTE_FRAME,   /* /frame.jpg */
    RL_ROUTE_STATUS,  /* /status.json */
    RL_ROUTE_MAP,     /* /map.json */
    RL_ROUTE_SNAPSHOT,/* /snapshot.png: the frame, lossless */
    RL_ROUTE_RECORD   /* POST /record?on=1|0: recording started or stopped */
} rl_http_route;

/* What the server read of a request; any field may be NULL. */
typedef struct {
    const char *method, *url;     /* the path, without the query */
    const char *w, *seq;          /* query arguments */
    const char *token;            /* ?token= */
    const char *auth;             /* the Authorization or X-Ringloc-Token header */
    const char *cookie;           /* the ringloc_token cookie's value */
    const char *host;             /* the Host header (NULL: refused, 400) */
    const char *self;             /* this computer's name (gethostname), or NULL */
    const char *on;               /* query argument of /record */
    const char *action;           /* the X-Ringloc-Action header (a page of another site cannot send it) */
    const char *x, *y, *size;     /* /snapshot.png's crop: its centre and side, px */
} rl_http_req_in;

typedef struct {
    rl_http_route route;
    int width;        /* w (0: not asked: full size) */
    long seq;         /* seq (-1: not asked) */
    int status;       /* 200, or the 4xx returned */
    const char *why;  /* a short static reason for a 4xx */
    int set_cookie;   /* 1: the token came in the URL; answer with the cookie (then the page drops it) */
    int redirect;     /* 1: the page with ?token=: answer 303 to the page without it, with the cookie */
    int on;           /* /record: 1 start, 0 stop */
    int crop_x, crop_y, crop_size; /* /snapshot.png: a crop of size px (16 .. 512) about x, y; size 0: whole */
} rl_http_req;

/* Judge in against the configured token ("" or NULL: none needed).
 * Returns r->status: 200, 401 (token missing or wrong), 400 (no Host, or
 * a bad number), 421 (a Host that is not this computer), 405 (not GET or
 * HEAD, or POST to /record without X-Ringloc-Action), 404 (no such
 * path), 414 (path too long). */
int rl_http_req_judge(const rl_http_req_in *in, const char *token, rl_http_req *r);

#endif
