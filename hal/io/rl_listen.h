/* rl_listen: an address to listen on, "ADDR:PORT", as the command line
 * (`ringloc-fw --http`) and ringloc.yaml (`http: {listen: ...}`) give it:
 * a numeric IPv4 address ("127.0.0.1:8080", "0.0.0.0:8080" for every
 * interface), a bracketed IPv6 one ("[::1]:8080"), or "localhost". The
 * port is 1 .. 65535. No name is looked up (a robot may have no DNS).
 *
 *   rl_listen l;
 *   char err[160];
 *   if (rl_listen_parse("127.0.0.1:8080", &l, err, sizeof err) == RL_OK)
 *       use(l.host, l.port, l.ipv6);     // "127.0.0.1", 8080, 0
 *   else
 *       use(err);                        // "'x' is not ADDR:PORT (...)"
 */
#ifndef RL_LISTEN_H
#define RL_LISTEN_H

#include <stddef.h>
#include "rl_error.h"

typedef struct {
    char host[48];   /* the numeric address, without brackets */
    int port;
    int ipv6;
} rl_listen;

/* RL_EFORMAT (err says what is wrong, quoting s) or RL_OK. */
RL_CHECK rl_err rl_listen_parse(const char *s, rl_listen *l, char *err, size_t errlen);

#endif
