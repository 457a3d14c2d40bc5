/* rl_infile: opening a file the user named for reading, refusing at once
 * what is not a regular file. A FIFO, a socket or a device where a file is
 * expected would block (a FIFO without a writer) or never end; it is
 * opened with O_NONBLOCK and looked at with fstat before anything is
 * read, so no command ever waits on one.
 *
 *   rl_err e;
 *   char err[600];
 *   FILE *f = rl_infile_fopen("map.yaml", "a YAML file", &e, err, sizeof err);
 *   if (f == NULL)
 *       use(err);   // "map.yaml: a FIFO, not a YAML file"
 *   else
 *       fclose(f);
 */
#ifndef RL_INFILE_H
#define RL_INFILE_H

#include <stddef.h>
#include <stdio.h>
#include "rl_error.h"

/* A descriptor on the regular file path (blocking, close-on-exec), or -1
 * with *e set (RL_ENOTFOUND: missing, RL_EIO: cannot open, RL_EFORMAT: not
 * a regular file) and err "PATH: reason"; `what` names what was expected
 * ("a PNG image"). */
RL_CHECK int rl_infile_open(const char *path, const char *what, rl_err *e, char *err, size_t errlen);

/* The same as a stream ("rb"); NULL on failure. */
RL_CHECK FILE *rl_infile_fopen(const char *path, const char *what, rl_err *e, char *err, size_t errlen);

#endif
