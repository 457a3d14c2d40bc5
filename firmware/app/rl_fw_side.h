/* rl_fw_side: the firmware's side features, recording (rl_record.h) and
 * the web view (rl_fw_http.h), beside the loop that sends the pose
 * frames, which they never stop. One that cannot start (the port taken,
 * the address not there yet at boot, no network in the service's
 * sandbox; a recording folder that is read-only or holds 999 drives) is
 * logged in one line and tried again every retry_us from the loop's
 * observer (a new line only when the reason changes, and one when it
 * starts); recording that stops later (a full disk, max_mb) stays off,
 * and the page says why. The page may stop and start recording
 * (rl_view_record_asked): a stop only stops offering frames. A web view that listens beyond this computer
 * (not 127.0.0.0/8 or ::1) without http.token gets a random token for the
 * run, printed once. Each report of the loop is offered to the recorder
 * and the view (rl_run_io.observe).
 *
 *   static rl_fw_side side;
 *   static rl_runner runner;
 *   rl_run_io io;                                    // the loop's, before rl_run_init
 *   rl_fw_side_init(&side, "ringloc-fw", &runner, 640, 480);
 *   side.rcc.dir = "/var/lib/ringloc/drive";         // or NULL: no recording
 *   side.listen = "127.0.0.1:8080";                  // or "": no web view
 *   side.map = &map; side.serial = "/dev/serial0"; side.token = "";
 *   rl_fw_side_start(&side, rl_clock_now_us());      // the first try of each
 *   io.observe = rl_fw_side_observe;                 // then retried from the loop
 *   io.observe_ctx = &side;
 *   // ... the loop runs ...
 *   rl_fw_side_stop(&side);                          // summary lines on stderr
 */
#ifndef RL_FW_SIDE_H
#define RL_FW_SIDE_H

#include <stdint.h>
#include "rl_fw_http.h"
#include "rl_record.h"
#include "rl_run.h"

/* A side feature that cannot start is tried again this often (5 s). */
#define RL_FW_SIDE_RETRY_US 5000000u

typedef struct {
    /* what is asked for, set after rl_fw_side_init */
    rl_record_config rcc;       /* rcc.dir NULL or "": no recording */
    const char *listen;         /* "" or NULL: no web view */
    const char *token;          /* the web view's token, "" for none */
    const rl_map *map;          /* shown on the page */
    const rl_site *site;        /* its camera, mount and recognizer's thresholds, for the page (may be NULL) */
    const char *serial;         /* the serial device's name, for the page */
    uint64_t retry_us;          /* RL_FW_SIDE_RETRY_US */
    /* the features' state (the loop's thread) */
    const char *prefix;
    const rl_runner *runner;
    int width, height;
    rl_record rec;
    uint64_t rec_retry_at;
    char rec_note[512];         /* why recording is off though asked for, or "" */
    int rec_paused;             /* 1: stopped from the web view's page (frames not offered) */
    rl_fw_http web;
    uint64_t web_retry_at;
    char web_note[512];         /* why the web view is not up, or "" */
    char made_token[33];        /* the token made up for a view heard beyond loopback without one */
} rl_fw_side;

/* Nothing asked for yet; prefix starts every log line (stderr). */
void rl_fw_side_init(rl_fw_side *s, const char *prefix, const rl_runner *runner, int w, int h);

/* The first try of each side feature asked for: one line each on
 * stderr, saying it started or why not (it is then retried). */
void rl_fw_side_start(rl_fw_side *s, uint64_t now_us);

/* The loop's observer (rl_run_io.observe; ctx is an rl_fw_side): the
 * frame to the recorder, the report to the view, a retry when due. */
void rl_fw_side_observe(void *ctx, const rl_run_report *rep);

/* Stop both, with their summary lines. */
void rl_fw_side_stop(rl_fw_side *s);

#endif
