/* rl_http: the live web view's server (GNU libmicrohttpd): one page
 * (rl_view_page.html, built into the program), /frame.jpg (the latest
 * frame, ?w= to scale it down), /snapshot.png (a frame lossless, or a 1:1
 * crop of it: ?x=&y=&size=), /status.json (rl_view_json.h; ?seq= for a
 * snapshot's) and /map.json, from snapshots of the loop (rl_view.h); the
 * one thing that changes anything is POST /record?on=1|0, which asks the
 * loop to start or stop recording (rl_view_ask_record). The server
 * runs in one thread of its own that polls every client without blocking
 * (a slow or vanished browser holds nothing; at most max_clients at once,
 * max_per_client from one address, more are refused); a request that is
 * not whole within timeout_s of the connection's opening or last answer
 * is closed however slowly it trickles in (a second thread watches the
 * deadline), a request larger than max_request bytes gets 431 or is
 * closed. Every request is judged by rl_http_req before anything is
 * served, the token first (a 401 carries WWW-Authenticate: Basic, so a
 * browser asks for it, and Bearer; the page asked with ?token= is
 * answered 303 to itself with the token in an HttpOnly cookie, so no
 * address or request of the page carries it), then the Host header: bad ones get a 4xx and a one-line
 * reason. Nothing is read from disk: the loop never waits for the
 * server.
 *
 *   static rl_view view;               // rl_view_init'ed, offered by the loop
 *   static rl_map map;
 *   rl_http *h;
 *   rl_http_config hc;
 *   char err[256];
 *   rl_http_defaults(&hc);
 *   hc.listen = "127.0.0.1:8080";
 *   if (rl_http_start(&h, &hc, &view, &map, err, sizeof err) == RL_OK) {
 *       // ... the loop runs ...
 *       rl_http_stop(h, NULL);
 *   }
 */
#ifndef RL_HTTP_H
#define RL_HTTP_H

#include <stddef.h>
#include "rl_error.h"
#include "rl_map.h"
#include "rl_view.h"

typedef struct {
    const char *listen;      /* "ADDR:PORT" (rl_listen.h) */
    const char *token;       /* access token (letters, digits, -._~); "" or NULL: none */
    int max_clients;         /* connections at once (default 32) */
    int max_per_client;      /* of them from one address (default 8: a browser keeps a few open) */
    int timeout_s;           /* a request not whole this long after the connection opened or its
                                last answer, or a connection idle this long, is closed (default 10) */
    size_t max_request;      /* bytes of one request's line and headers (default 8192) */
    /* the camera's geometry, to draw the map's landmarks and the robot's
     * forward direction into the image (NULL: not drawn; kept while the
     * server runs) */
    const rl_calib *calib;
    const rl_mount *mount;
} rl_http_config;

typedef struct rl_http rl_http;

/* What the server did, for the firmware's summary line. */
typedef struct {
    long served, refused;
} rl_http_counts;

void rl_http_defaults(rl_http_config *c);

/* Start serving view (and map: kept while the server runs). RL_EFORMAT
 * for a bad listen address or token, RL_EIO when the socket cannot be bound (err
 * names the address and why), RL_ENOMEM, RL_EUNSUPPORTED when the
 * program was built without libmicrohttpd. */
RL_CHECK rl_err rl_http_start(rl_http **h, const rl_http_config *c, rl_view *view, const rl_map *map,
                              char *err, size_t errlen);

/* Stop (closing every connection) and free; then, when counts is not
 * NULL, what the server did. NULL h is fine (counts all 0). */
void rl_http_stop(rl_http *h, rl_http_counts *counts);

#endif
