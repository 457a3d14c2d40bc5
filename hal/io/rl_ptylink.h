/* rl_ptylink: a pseudo-terminal reached through a symbolic link the user
 * names (`ringloc monitor --pty LINK`, `ringloc-standin --frames-pty
 * LINK`), for `ringloc run` to take as its serial device.
 *
 * Only a link this kind of program leaves behind is replaced: nothing at
 * LINK, or a link into /dev/pts whose pseudo-terminal is gone (a monitor
 * that was killed). A file, a folder, any other link, or a link to a live
 * pseudo-terminal is refused with one line ("tty: exists and is a regular
 * file; not replaced (remove it, or give --force)"); with force, anything
 * but a folder is replaced. On removal the link goes only while it still
 * points at this pseudo-terminal.
 *
 *   rl_ptylink pt;
 *   char err[600];
 *   if (rl_ptylink_open(&pt, "tty", 0, 0, err, sizeof err) == RL_OK) {
 *       use(pt.fd);                // read what the other side writes
 *       rl_ptylink_close(&pt);     // the link removed, the pty closed
 *   }
 */
#ifndef RL_PTYLINK_H
#define RL_PTYLINK_H

#include <stddef.h>
#include "rl_error.h"

typedef struct {
    int fd;             /* the pseudo-terminal's master (-1: none) */
    const char *link;   /* the caller's LINK (kept, not copied) */
    char name[128];     /* the device LINK points to ("/dev/pts/4") */
} rl_ptylink;

/* Create the pseudo-terminal (O_NONBLOCK when nonblock) and LINK to it.
 * RL_EINVAL when LINK is there and may not be replaced, RL_EIO when the
 * system refuses; err says why, naming LINK. Nothing is left on failure. */
RL_CHECK rl_err rl_ptylink_open(rl_ptylink *p, const char *link, int force, int nonblock, char *err,
                                size_t errlen);

/* Remove LINK if it still points at ours, and close the pseudo-terminal. */
void rl_ptylink_close(rl_ptylink *p);

#endif
