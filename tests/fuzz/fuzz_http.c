/* The web view's request handling on arbitrary bytes: a request's method,
 * path, query numbers, token, header, cookie and Host (fields split at newlines, a
 * field of one byte 0x01 standing for "absent") judged against a token;
 * its answer must be one of the documented codes, a 200 a real route with
 * numbers in range. The rest of the input fills a snapshot (any doubles:
 * NaN, infinities) whose status JSON is written into a buffer of a fuzzed
 * size: never past it, always NUL-terminated, never a non-JSON number. */
#include <stdlib.h>
#include <string.h>
#include "fuzz_take.h"
#include "rl_http_req.h"
#include "rl_view_json.h"

#define FIELDS 8

static int split(const uint8_t **p, size_t *n, char fields[FIELDS][96], const char *out[FIELDS])
{
    int f;
    for (f = 0; f < FIELDS; f++) {
        size_t k = 0;
        while (*n > 0 && **p != '\n') {
            if (k < 95)
                fields[f][k++] = (char)**p;
            (*p)++, (*n)--;
        }
        if (*n > 0)
            (*p)++, (*n)--;
        fields[f][k] = 0;
        out[f] = (k == 1 && fields[f][0] == 1) ? NULL : fields[f];
    }
    return 1;
}

static void judge(const char *f[FIELDS])
{
    rl_http_req_in in = {f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], "ringbot", f[2], f[3], f[2], f[3], f[2]};
    rl_http_req r;
    int s = rl_http_req_judge(&in, "secret", &r);
    if (s != r.status || r.why == NULL)
        abort();
    if (s == 200) {
        if (r.route == RL_ROUTE_NONE || (r.width != 0 && (r.width < 16 || r.width > 8192)))
            abort();
    } else if (s != 400 && s != 401 && s != 404 && s != 405 && s != 414 && s != 421) {
        abort();
    }
}

static void snapshot(const uint8_t *p, size_t n)
{
    static rl_result res;
    static uint8_t image[32 * 24];
    static rl_view_snap s;
    static char buf[RL_VIEW_JSON_STATUS_MAX + 1];
    size_t cap, len;
    int i;
    memset(&s, 0, sizeof s);
    memset(&res, 0, sizeof res);
    s.width = 32, s.height = 24, s.image = image, s.res = &res;
    s.have_image = n > 0 && (p[0] & 1);
    s.have_result = 1;
    cap = n > 1 ? (size_t)p[1] * 64 : 0;
    res.n_landmarks = n > 2 ? p[2] % (RL_MAX_LANDMARKS + 1) : 0;
    res.n_unidentified = n > 3 ? p[3] % 8 : 0;
    res.n_lights = n > 4 ? p[4] % (RL_MAX_LIGHTS + 1) : 0;
    s.n_track = n > 5 ? p[5] % 16 : 0;
    for (i = 0; i < res.n_landmarks; i++) {
        res.landmarks[i].u = fuzz_take(&p, &n);
        res.landmarks[i].score = fuzz_take(&p, &n);
    }
    s.pose.x = fuzz_take(&p, &n);
    s.pose.sigma_x = fuzz_take(&p, &n);
    s.fps = fuzz_take(&p, &n);
    for (i = 0; i < s.n_track; i++)
        s.track[i].x = fuzz_take(&p, &n);
    s.place = (int)(n > 0 ? (int8_t)p[0] : 0);
    s.reason = (int)(n > 1 ? (int8_t)p[1] : 0);
    memset(buf, 0x55, sizeof buf);
    len = rl_view_json_status(&s, buf, cap);
    if (buf[cap] != 0x55) /* cap < sizeof buf: nothing written past it */
        abort();
    if (len > 0 && (len >= cap || buf[len] != 0 || strstr(buf, "nan") || strstr(buf, "inf")))
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char fields[FIELDS][96];
    const char *f[FIELDS];
    split(&data, &size, fields, f);
    judge(f);
    snapshot(data, size);
    return 0;
}
