/* rl_serial: where a pose leaves: a serial line (POSIX termios, raw 8N1),
 * or, on the host, a new file or standard output ("-"). A pseudo-terminal
 * works as a serial device. Nothing is ever created in /dev: a device
 * that is not there is RL_ENOTFOUND, for the caller to retry. Nothing is
 * written into a file the run did not create: an existing regular file is
 * refused, and a symbolic link (/dev/serial0, a pty monitor's link) is
 * followed only to a character device, which is opened with O_NOFOLLOW
 * and checked on the open descriptor.
 *
 *   rl_serial s;
 *   char err[256];
 *   const uint8_t frame_bytes[3] = {0xFA, 0xFB, 0};
 *   if (rl_serial_open(&s, "/dev/serial0", 115200, 0, err, sizeof err) == RL_OK) {
 *       if (rl_serial_write(&s, frame_bytes, 3, 100) == RL_ENODEV)
 *           use(s.path);                 // the line went away: close, reopen later
 *       rl_serial_close(&s);
 *   }
 */
#ifndef RL_SERIAL_H
#define RL_SERIAL_H

#include <stddef.h>
#include <stdint.h>
#include "rl_error.h"

typedef struct {
    int fd;
    int is_tty;
    int own;          /* fd is ours to close (not stdout) */
    int broken;       /* standard output's reader has gone (a broken pipe) */
    int errnum;       /* the last failed write's errno (0: none) */
    char path[256];
} rl_serial;

/* Baud rates accepted: 9600 .. 921600 (the termios ones). */
int rl_serial_baud_ok(int baud);

/* rl_serial_open flags: a path outside /dev that does not exist is
 * created as a file to record into (a first open; an existing file is
 * refused then). Without it (a reopen after a failure) the file the first
 * open created is appended to, and a missing one is RL_ENOTFOUND. */
#define RL_SERIAL_MAY_CREATE 1u

/* Open path: "-" (standard output), a character device or a link to one
 * (a serial line or a pty: raw 8N1 at baud), or a regular file outside
 * /dev (see the flags). RL_ENOTFOUND when the device, the file or a
 * link's target is not there; RL_ENODEV for anything else there (an
 * existing file at a first open, a link to a file, a FIFO), err naming
 * path; RL_EINVAL for an unsupported baud rate. */
RL_CHECK rl_err rl_serial_open(rl_serial *s, const char *path, int baud, unsigned flags, char *err,
                               size_t errlen);

/* Write all n bytes (waiting at most timeout_ms for a congested line).
 * RL_ENODEV when the device went away, RL_ETIMEOUT when it would not take
 * the bytes, RL_EIO otherwise; on standard output a reader that went away
 * (a broken pipe) is RL_EIO with s->broken set: nothing can reopen it. */
RL_CHECK rl_err rl_serial_write(rl_serial *s, const uint8_t *p, size_t n, int timeout_ms);

void rl_serial_close(rl_serial *s);

#endif
