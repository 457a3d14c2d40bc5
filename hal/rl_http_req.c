#include "rl_http_req.h"

#include <string.h>

static int fail(rl_http_req *r, int status, const char *why)
{
    r->status = status;
    r->why = why;
    r->route = RL_ROUTE_NONE;
    return status;
}

/* Length of s, or max + 1 when it is longer than max (never reads past). */
static size_t bounded_len(const char *s, size_t max)
{
    size_t n = 0;
    while (n <= max && s[n])
        n++;
    return n;
}

/* Equal, in time that depends on the length of the configured token only. */
static int same_token(const char *given, const char *want)
{
    size_t n = strlen(want), g = bounded_len(given, RL_HTTP_MAX_TOKEN), i;
    unsigned diff = (unsigned)(g != n);
    for (i = 0; i < n; i++)
        diff |= (unsigned)(unsigned char)want[i] ^ (unsigned)(unsigned char)(i < g ? given[i] : 0);
    return diff == 0;
}

/* The value of a base64 digit, or -1. */
static int b64(char c)
{
    if (c >= 'A' && c <= 'Z')
        return c - 'A';
    if (c >= 'a' && c <= 'z')
        return c - 'a' + 26;
    if (c >= '0' && c <= '9')
        return c - '0' + 52;
    return c == '+' ? 62 : c == '/' ? 63 : -1;
}

/* HTTP Basic's "user:password" decoded into out[0..cap) (NUL-ended);
 * 0 when it is not base64 or does not fit. */
static int basic_decode(const char *s, char *out, size_t cap)
{
    size_t n = 0;
    unsigned acc = 0;
    int bits = 0, d;
    for (; *s && *s != '='; s++) {
        if ((d = b64(*s)) < 0)
            return 0;
        acc = (acc << 6) | (unsigned)d;
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            if (n + 1 >= cap)
                return 0;
            out[n++] = (char)((acc >> bits) & 0xff);
        }
    }
    out[n] = 0;
    return 1;
}

/* The password of an "Authorization: Basic" value (the browser's own
 * prompt: any user name, the token as the password), or NULL. */
static const char *basic_password(const char *a, char *buf, size_t cap)
{
    const char *colon;
    if (!basic_decode(a, buf, cap) || (colon = strchr(buf, ':')) == NULL)
        return NULL;
    return colon + 1;
}

/* 1 when the request carries the token (r->set_cookie when in its URL). */
static int token_ok(const rl_http_req_in *in, const char *token, rl_http_req *r)
{
    const char *a = in->auth;
    char basic[RL_HTTP_MAX_TOKEN + 192];
    if (token == NULL || token[0] == 0)
        return 1;
    if (in->token != NULL && same_token(in->token, token))
        return r->set_cookie = 1;
    if (in->cookie != NULL && same_token(in->cookie, token))
        return 1;
    if (a == NULL)
        return 0;
    if (strncmp(a, "Bearer ", 7) == 0)
        a += 7;
    else if (strncmp(a, "Basic ", 6) == 0 && (a = basic_password(a + 6, basic, sizeof basic)) == NULL)
        return 0;
    return same_token(a, token);
}

/* s[0..n) equals name, letters in any case. */
static int same_name(const char *s, size_t n, const char *name)
{
    size_t i;
    for (i = 0; i < n && name[i]; i++) {
        char a = s[i], b = name[i];
        if (a >= 'A' && a <= 'Z')
            a = (char)(a - 'A' + 'a');
        if (b >= 'A' && b <= 'Z')
            b = (char)(b - 'A' + 'a');
        if (a != b)
            return 0;
    }
    return i == n && name[i] == 0;
}

/* An IP address (IPv4 digits and dots, IPv6 in brackets), localhost or
 * self (or self.local), each with an optional :port. A name resolving to
 * the robot that is none of these is a page of another site
 * (DNS rebinding). */
static int host_ok(const char *host, const char *self)
{
    size_t n = bounded_len(host, 300), i, name;
    int digits = 1;
    if (n == 0 || n > 300)
        return 0;
    if (host[0] == '[') {
        for (i = 1; i < n && host[i] != ']'; i++)
            if (!((host[i] >= '0' && host[i] <= '9') || (host[i] >= 'a' && host[i] <= 'f') ||
                  (host[i] >= 'A' && host[i] <= 'F') || host[i] == ':' || host[i] == '.'))
                return 0;
        name = i < n ? i + 1 : 0;
        if (name == 0)
            return 0;
        digits = 0;
    } else {
        for (name = 0; name < n && host[name] != ':'; name++)
            digits &= (host[name] >= '0' && host[name] <= '9') || host[name] == '.';
    }
    if (name < n) { /* :port */
        if (host[name] != ':' || name + 1 == n)
            return 0;
        for (i = name + 1; i < n; i++)
            if (host[i] < '0' || host[i] > '9')
                return 0;
    }
    if (host[0] == '[' || (digits && name > 0))
        return 1;
    if (same_name(host, name, "localhost"))
        return 1;
    if (self == NULL || self[0] == 0)
        return 0;
    {
        size_t k = strlen(self);
        return same_name(host, name, self) ||
               (name == k + 6 && same_name(host, k, self) && same_name(host + k, 6, ".local"));
    }
}

/* A decimal number of at most `digits` digits within lo .. hi. */
static int number(const char *s, int digits, long lo, long hi, long *out)
{
    long v = 0;
    int n = 0;
    for (; *s; s++, n++) {
        if (*s < '0' || *s > '9' || n == digits)
            return 0;
        v = v * 10 + (*s - '0');
    }
    if (n == 0 || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

static rl_http_route route_of(const char *url)
{
    if (strcmp(url, "/") == 0 || strcmp(url, "/index.html") == 0)
        return RL_ROUTE_PAGE;
    if (strcmp(url, "/frame.jpg") == 0)
        return RL_ROUTE_FRAME;
    if (strcmp(url, "/status.json") == 0)
        return RL_ROUTE_STATUS;
    if (strcmp(url, "/map.json") == 0)
        return RL_ROUTE_MAP;
    if (strcmp(url, "/snapshot.png") == 0)
        return RL_ROUTE_SNAPSHOT;
    if (strcmp(url, "/record") == 0)
        return RL_ROUTE_RECORD;
    return RL_ROUTE_NONE;
}

/* POST /record?on=1|0 with X-Ringloc-Action (the token and Host already
 * judged). */
static int judge_record(const rl_http_req_in *in, rl_http_req *r)
{
    if (in->method == NULL || strcmp(in->method, "POST") != 0)
        return fail(r, 405, "POST /record?on=1 or ?on=0 starts or stops recording");
    if (in->action == NULL || in->action[0] == 0)
        return fail(r, 405, "POST /record needs the X-Ringloc-Action header (the page sends it)");
    if (in->on == NULL || (strcmp(in->on, "1") != 0 && strcmp(in->on, "0") != 0))
        return fail(r, 400, "on is not 1 (start) or 0 (stop)");
    r->on = in->on[0] == '1';
    r->route = RL_ROUTE_RECORD;
    r->status = 200;
    r->why = "";
    return 200;
}

int rl_http_req_judge(const rl_http_req_in *in, const char *token, rl_http_req *r)
{
    rl_http_route route;
    long v;
    r->width = 0;
    r->seq = -1;
    r->set_cookie = 0;
    r->redirect = 0;
    r->on = 0;
    r->crop_x = r->crop_y = r->crop_size = 0;
    /* the token first: without it nothing is said, not even what exists */
    if (!token_ok(in, token, r))
        return fail(r, 401, "access token missing or wrong");
    if (in->host == NULL)
        return fail(r, 400, "no Host header");
    if (!host_ok(in->host, in->self))
        return fail(r, 421, "Host is not this robot (an IP address, localhost or its own name)");
    if (in->url != NULL && strcmp(in->url, "/record") == 0)
        return judge_record(in, r);
    if (in->method == NULL || (strcmp(in->method, "GET") != 0 && strcmp(in->method, "HEAD") != 0))
        return fail(r, 405, "only GET and HEAD: the view is read-only but for POST /record");
    if (in->url == NULL || in->url[0] != '/')
        return fail(r, 404, "no such page");
    if (bounded_len(in->url, RL_HTTP_MAX_URL) > RL_HTTP_MAX_URL)
        return fail(r, 414, "path too long");
    if ((route = route_of(in->url)) == RL_ROUTE_NONE)
        return fail(r, 404, "no such page");
    if (in->w != NULL) {
        if (!number(in->w, 5, 16, 8192, &v))
            return fail(r, 400, "w is not a width (16 .. 8192)");
        r->width = (int)v;
    }
    if (in->seq != NULL) {
        if (!number(in->seq, 9, 0, 999999999L, &v))
            return fail(r, 400, "seq is not a snapshot number");
        r->seq = v;
    }
    if (in->size != NULL || in->x != NULL || in->y != NULL) {
        long x, y, s;
        if (in->size == NULL || in->x == NULL || in->y == NULL || !number(in->x, 5, 0, 8191, &x) ||
            !number(in->y, 5, 0, 8191, &y) || !number(in->size, 3, 16, 512, &s))
            return fail(r, 400, "a crop is x, y (0 .. 8191) and size (16 .. 512) together");
        r->crop_x = (int)x, r->crop_y = (int)y, r->crop_size = (int)s;
    }
    r->route = route;
    /* the page asked with ?token=: a cookie and a redirect to the same
     * page without it (the token leaves the address bar and the history) */
    r->redirect = r->set_cookie && route == RL_ROUTE_PAGE;
    r->status = 200;
    r->why = "";
    return 200;
}
