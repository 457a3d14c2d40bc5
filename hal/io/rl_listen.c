#include "rl_listen.h"

#include <arpa/inet.h>
#include <stdio.h>
#include <string.h>

static rl_err bad(const char *s, const char *why, char *err, size_t errlen)
{
    snprintf(err, errlen, "'%.80s' is not ADDR:PORT (%s; e.g. 127.0.0.1:8080)", s, why);
    return RL_EFORMAT;
}

rl_err rl_listen_parse(const char *s, rl_listen *l, char *err, size_t errlen)
{
    const char *colon = strrchr(s, ':'), *h = s, *p;
    size_t n;
    long port = 0;
    unsigned char addr[16];
    memset(l, 0, sizeof *l);
    if (colon == NULL)
        return bad(s, "no port", err, errlen);
    n = (size_t)(colon - s);
    if (n >= 2 && s[0] == '[' && s[n - 1] == ']') {
        h = s + 1;
        n -= 2;
        l->ipv6 = 1;
    }
    if (n == 0 || n >= sizeof l->host)
        return bad(s, "no address", err, errlen);
    memcpy(l->host, h, n);
    l->host[n] = 0;
    if (strcmp(l->host, "localhost") == 0 && !l->ipv6)
        snprintf(l->host, sizeof l->host, "127.0.0.1");
    if (inet_pton(l->ipv6 ? AF_INET6 : AF_INET, l->host, addr) != 1)
        return bad(s, l->ipv6 ? "not an IPv6 address" : "not an IPv4 address", err, errlen);
    for (p = colon + 1; *p; p++) {
        if (*p < '0' || *p > '9' || port > 65535)
            return bad(s, "the port is not a number", err, errlen);
        port = port * 10 + (*p - '0');
    }
    if (p == colon + 1 || port < 1 || port > 65535)
        return bad(s, "the port is not 1 .. 65535", err, errlen);
    l->port = (int)port;
    return RL_OK;
}
