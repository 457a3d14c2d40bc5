/* rl_notify: telling systemd how the service is (the sd_notify protocol,
 * written here: one datagram of "KEY=VALUE" lines to the AF_UNIX socket
 * named by $NOTIFY_SOCKET, "@name" for the abstract namespace). Outside a
 * Type=notify service (no $NOTIFY_SOCKET) every call does nothing. With
 * WatchdogSec= in the unit ($WATCHDOG_USEC, for this process when
 * $WATCHDOG_PID is set), rl_notify_alive sends WATCHDOG=1 at most every
 * half period: the firmware calls it for each frame recognized only, so a
 * loop hung in a camera driver, or a camera that gives no frame, stops the
 * pings and systemd restarts the service.
 *
 *   rl_notify n;
 *   uint64_t now_us = 1000000;           // rl_clock_now_us() (rl_clock.h)
 *   rl_notify_open(&n);
 *   rl_notify_send(&n, "READY=1");       // started: the loop runs
 *   rl_notify_alive(&n, now_us);         // each frame recognized
 *   rl_notify_send(&n, "STOPPING=1");
 *   rl_notify_close(&n);
 */
#ifndef RL_NOTIFY_H
#define RL_NOTIFY_H

#include <stdint.h>

typedef struct {
    int fd;                  /* -1: not under systemd's notify, all calls do nothing */
    char path[108];          /* sun_path (a leading 0 for the abstract namespace) */
    int path_len;
    uint64_t watchdog_us;    /* 0: no watchdog */
    uint64_t next_ping_us;
} rl_notify;

/* From the environment; an unusable $NOTIFY_SOCKET is ignored (fd -1). */
void rl_notify_open(rl_notify *n);

/* Send one state ("READY=1", "STOPPING=1", "STATUS=..."); a failed send
 * is ignored (systemd's reading is not the robot's business). */
void rl_notify_send(rl_notify *n, const char *state);

/* WATCHDOG=1 when half the watchdog period has passed since the last. */
void rl_notify_alive(rl_notify *n, uint64_t now_us);

void rl_notify_close(rl_notify *n);

#endif
