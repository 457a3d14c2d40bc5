/* rl_fw_http: the firmware's live web view, started and stopped at the
 * program's edge: the view's memory made once at start (the loop then
 * only copies into it: rl_run_view.h), the server (rl_http.h) on the
 * configured address, and a summary line at the end. Off unless asked
 * for (`--http ADDR:PORT`, or `http: {listen: ADDR:PORT}` in ringloc.yaml).
 * With the site (NULL: none), the page says what the recognizer accepts
 * and, with a pinhole calibration and a mount, draws the map into the
 * image.
 *
 *   static rl_fw_http web;
 *   static rl_runner runner;
 *   static rl_map map;
 *   char err[256];
 *   if (rl_fw_http_start(&web, "127.0.0.1:8080", "", 640, 480, NULL, &map, &runner, "/dev/serial0",
 *                        NULL, err, sizeof err) == RL_OK) {
 *       // the loop's observer: rl_run_view_report with &web.rv
 *       rl_fw_http_stop(&web, NULL);
 *   }
 */
#ifndef RL_FW_HTTP_H
#define RL_FW_HTTP_H

#include <stddef.h>
#include "rl_http.h"
#include "rl_run_view.h"

typedef struct {
    rl_view view;
    rl_run_view rv;
    void *mem;
    rl_http *http;
    int on;
} rl_fw_http;

/* Make the view for w x h frames and serve it on listen (token: "" for
 * none). RL_OK, or the error with one line in err naming the address. */
RL_CHECK rl_err rl_fw_http_start(rl_fw_http *web, const char *listen, const char *token, int w, int h,
                                 const rl_site *site, const rl_map *map, const rl_runner *runner, const char *serial,
                                 const rl_record *rec, char *err, size_t errlen);

/* Stop the server and free the view (nothing when it was not started);
 * with a prefix, one summary line on stderr (requests served, refused). */
void rl_fw_http_stop(rl_fw_http *web, const char *prefix);

#endif
