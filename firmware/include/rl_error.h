/* rl_error: the one error enum of ringloc.
 *
 * Every function that can fail returns rl_err (0 = success, negative =
 * error) and is marked RL_CHECK so that an ignored result warns.
 *
 *   void *buf;
 *   rl_err e = rl_ws_alloc(&ws, 4096, RL_WS_ALIGN, &buf);
 *   if (e != RL_OK)
 *       fprintf(stderr, "ringloc: %s\n", rl_strerror(e));
 */
#ifndef RL_ERROR_H
#define RL_ERROR_H

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__) || defined(__clang__)
#define RL_CHECK __attribute__((warn_unused_result))
#else
#define RL_CHECK
#endif

typedef enum {
    RL_OK = 0,
    RL_EINVAL = -1,     /* an argument is out of its documented domain */
    RL_ENOMEM = -2,     /* the caller's workspace or buffer is too small */
    RL_ELIMIT = -3,     /* a compile-time limit (rl_config.h) was reached */
    RL_ERANGE = -4,     /* a value is outside what the spec allows */
    RL_EFORMAT = -5,    /* input data is malformed (file, frame, YAML) */
    RL_EIO = -6,        /* a read or write on a file or device failed */
    RL_ENOTFOUND = -7,  /* a named thing (file, key, id) does not exist */
    RL_ETIMEOUT = -8,   /* a device did not answer in time */
    RL_ENODEV = -9,     /* a device is missing or went away */
    RL_ETOOFEW = -10,   /* too few landmarks for a pose */
    RL_EUNSUPPORTED = -11, /* a feature not built in or not supported */
    RL_EAMBIGUOUS = -12  /* the landmarks fit more than one place of the map */
} rl_err;

/* Short static message for an error code; never NULL, never allocates. */
const char *rl_strerror(rl_err e);

#ifdef __cplusplus
}
#endif

#endif
