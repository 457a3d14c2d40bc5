#include "rl_runcfg.h"

#include <stdio.h>
#include <string.h>
#include "rl_cam_backends.h"
#include "rl_listen.h"
#include "rl_yaml.h"

/* `value` relative to the folder of `base` unless absolute (or "-"). */
static void relative(char *out, size_t len, const char *base, const char *value)
{
    const char *slash = strrchr(base, '/');
    if (value[0] == '/' || strcmp(value, "-") == 0 || slash == NULL)
        snprintf(out, len, "%s", value);
    else
        snprintf(out, len, "%.*s/%s", (int)(slash - base), base, value);
}

static rl_err path_key(rl_yaml *y, yaml_node_t *map, const char *key, const char *label,
                       int required, const char *base, char *out, size_t len, char *err,
                       size_t errlen)
{
    const char *v = NULL;
    rl_err e = rl_yaml_string(y, map, key, label, required, &v, err, errlen);
    if (e == RL_OK && v != NULL)
        relative(out, len, base, v);
    return e;
}

/* A correlation threshold in (0, 1], if given. */
static rl_err score_key(rl_yaml *y, yaml_node_t *map, const char *key, const char *label,
                        double *v, char *err, size_t errlen)
{
    rl_err e = rl_yaml_double(y, map, key, label, 0, v, err, errlen);
    if (e == RL_OK && !(*v > 0 && *v <= 1))
        e = rl_yaml_fail(y, rl_yaml_get(y, map, key), label, RL_ERANGE, err, errlen,
                         "must be in (0, 1]");
    return e;
}

static const char *const top_keys[] = {"camera", "calibration", "map", "robot", "offsets",
                                       "serial", "recognition", "log_interval", "record", "http", NULL};
static const char *const record_keys[] = {"dir", "every", "max_mb", NULL};
static const char *const camera_keys[] = {"backend", "device", "width", "height", "rate", "loop",
                                          "exposure", "gain", "readout", "stamp", NULL};

/* "auto" (0) or a number within lo .. hi */
static rl_err auto_or(rl_yaml *y, yaml_node_t *cam, const char *key, const char *label, double lo, double hi,
                      double *out, char *err, size_t errlen)
{
    yaml_node_t *n = rl_yaml_get(y, cam, key);
    const char *t = rl_yaml_text(n);
    if (n != NULL && t != NULL && strcmp(t, "auto") == 0) {
        *out = 0;
        return RL_OK;
    }
    return rl_yaml_double_in(y, cam, key, label, 0, lo, hi, out, err, errlen);
}
/* recognition.gamma: auto (0), or a tone curve's exponent 1 .. 3. */
static rl_err gamma_key(rl_yaml *y, yaml_node_t *rec, double *out, char *err, size_t errlen)
{
    const char *t = rl_yaml_text(rl_yaml_get(y, rec, "gamma"));
    if (t != NULL && strcmp(t, "auto") == 0) {
        *out = 0;
        return RL_OK;
    }
    return rl_yaml_double_in(y, rec, "gamma", "recognition.gamma", 0, 1.0, 3.0, out, err, errlen);
}

static const char *const http_keys[] = {"listen", "token", NULL};

/* http: {listen: ADDR:PORT, token: ...}: the web view, off when absent. */
static rl_err http_section(rl_yaml *y, yaml_node_t *root, rl_runcfg *c, char *err, size_t errlen)
{
    yaml_node_t *h = rl_yaml_get(y, root, "http");
    const char *s = NULL;
    rl_listen l;
    char why[160];
    rl_err e;
    if (h == NULL)
        return RL_OK;
    if (h->type != YAML_MAPPING_NODE)
        return rl_yaml_fail(y, h, "http", RL_EFORMAT, err, errlen, "expected {listen, token}");
    if ((e = rl_yaml_only(y, h, "http", http_keys, err, errlen)) != RL_OK ||
        (e = rl_yaml_string(y, h, "listen", "http.listen", 1, &s, err, errlen)) != RL_OK)
        return e;
    if (rl_listen_parse(s, &l, why, sizeof why) != RL_OK)
        return rl_yaml_fail(y, rl_yaml_get(y, h, "listen"), "http.listen", RL_EFORMAT, err, errlen, "%s", why);
    snprintf(c->http_listen, sizeof c->http_listen, "%s", s);
    s = NULL;
    if ((e = rl_yaml_string(y, h, "token", "http.token", 0, &s, err, errlen)) != RL_OK)
        return e;
    if (s != NULL && strlen(s) >= sizeof c->http_token)
        return rl_yaml_fail(y, rl_yaml_get(y, h, "token"), "http.token", RL_ERANGE, err, errlen,
                            "longer than %d characters", (int)sizeof c->http_token - 1);
    snprintf(c->http_token, sizeof c->http_token, "%s", s ? s : "");
    return RL_OK;
}

static const char *const serial_keys[] = {"device", "baud", NULL};
static const char *const recognition_keys[] = {"local", "min_score", "local_min_score", "gamma", "track_every",
                                                NULL};

/* What a file that leaves everything out says: the recognition's
 * settings from rl_recog_defaults, the PNG camera at 10 frames a second. */
static void runcfg_defaults(rl_runcfg *c)
{
    rl_recog_config rd;
    rl_recog_defaults(&rd);
    memset(c, 0, sizeof *c);
    c->cam_rate = 10.0;
    c->baud = 115200;
    c->local = rd.local;
    c->min_score = rd.min_score;
    c->local_min_score = rd.local_min_score;
    c->gamma = rd.gamma; /* auto */
    c->track_every = 0; /* tracking windows are asked for (docs/tracking.md) */
    snprintf(c->cam_stamp, sizeof c->cam_stamp, "auto");
    c->log_interval = 5.0;
    c->record_every = 10;
    c->record_max_mb = 1000;
    snprintf(c->cam_backend, sizeof c->cam_backend, "%s", rl_cam_backend_names[0]);
}

/* The sections' shapes and that no key is unknown. */
static rl_err check_sections(rl_yaml *y, yaml_node_t *root, yaml_node_t *cam, yaml_node_t *ser, yaml_node_t *rec,
                             char *err, size_t errlen)
{
    rl_err e;
    if (cam == NULL || cam->type != YAML_MAPPING_NODE)
        return rl_yaml_fail(y, cam ? cam : root, "camera", RL_EFORMAT, err, errlen,
                            cam ? "expected {backend, device, width, height, rate}" : "missing key");
    if (ser == NULL || ser->type != YAML_MAPPING_NODE)
        return rl_yaml_fail(y, ser ? ser : root, "serial", RL_EFORMAT, err, errlen,
                            ser ? "expected {device, baud}" : "missing key");
    if (rec != NULL && rec->type != YAML_MAPPING_NODE)
        return rl_yaml_fail(y, rec, "recognition", RL_EFORMAT, err, errlen,
                            "expected {local, min_score, local_min_score, gamma, track_every}");
    if ((e = rl_yaml_only(y, root, NULL, top_keys, err, errlen)) != RL_OK ||
        (e = rl_yaml_only(y, cam, "camera", camera_keys, err, errlen)) != RL_OK ||
        (e = rl_yaml_only(y, ser, "serial", serial_keys, err, errlen)) != RL_OK ||
        (e = rl_yaml_only(y, rec, "recognition", recognition_keys, err, errlen)) != RL_OK)
        return e;
    return RL_OK;
}

/* camera.stamp: auto, exposure_start, frame_start or frame_end */
static rl_err stamp_key(rl_yaml *y, yaml_node_t *cam, rl_runcfg *c, char *err, size_t errlen)
{
    static const char *const names[] = {"auto", "exposure_start", "frame_start", "frame_end"};
    const char *s = NULL;
    int i;
    rl_err e = rl_yaml_string(y, cam, "stamp", "camera.stamp", 0, &s, err, errlen);
    if (e != RL_OK || s == NULL)
        return e;
    for (i = 0; i < 4; i++)
        if (strcmp(s, names[i]) == 0) {
            snprintf(c->cam_stamp, sizeof c->cam_stamp, "%s", s);
            return RL_OK;
        }
    return rl_yaml_fail(y, rl_yaml_get(y, cam, "stamp"), "camera.stamp", RL_EFORMAT, err, errlen,
                        "'%s' is not auto, exposure_start, frame_start or frame_end", s);
}

/* camera: {backend, device, width, height, rate, loop, exposure, gain, readout, stamp} */
static rl_err camera_section(rl_yaml *y, yaml_node_t *cam, const char *path, rl_runcfg *c, char *err,
                             size_t errlen)
{
    const char *s = NULL;
    char names[64];
    rl_err e;
    if ((e = rl_yaml_string(y, cam, "backend", "camera.backend", 1, &s, err, errlen)) != RL_OK)
        return e;
    if (rl_cam_backend_find(s) < 0)
        return rl_yaml_fail(y, rl_yaml_get(y, cam, "backend"), "camera.backend", RL_EFORMAT, err, errlen,
                            "'%s' is not %s", s, rl_cam_backend_list(names, sizeof names));
    snprintf(c->cam_backend, sizeof c->cam_backend, "%s", s);
    s = NULL;
    if ((e = rl_yaml_string(y, cam, "device", "camera.device", 1, &s, err, errlen)) != RL_OK)
        return e;
    if (strcmp(c->cam_backend, "png") == 0)
        relative(c->cam_device, sizeof c->cam_device, path, s);
    else
        snprintf(c->cam_device, sizeof c->cam_device, "%s", s);
    if ((e = rl_yaml_int(y, cam, "width", "camera.width", 0, &c->cam_width, err, errlen)) != RL_OK ||
        (e = rl_yaml_int(y, cam, "height", "camera.height", 0, &c->cam_height, err, errlen)) != RL_OK ||
        (e = rl_yaml_double(y, cam, "rate", "camera.rate", 0, &c->cam_rate, err, errlen)) != RL_OK ||
        (e = rl_yaml_bool(y, cam, "loop", "camera.loop", 0, &c->cam_loop, err, errlen)) != RL_OK ||
        (e = auto_or(y, cam, "exposure", "camera.exposure", 1, 10e6, &c->cam_exposure_us, err, errlen)) != RL_OK ||
        (e = auto_or(y, cam, "gain", "camera.gain", 1e-3, 1e4, &c->cam_gain, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(y, cam, "readout", "camera.readout", 0, 0, 200, &c->cam_readout_ms, err, errlen)) !=
            RL_OK ||
        (e = stamp_key(y, cam, c, err, errlen)) != RL_OK)
        return e;
    if (c->cam_width < 0 || c->cam_height < 0 || c->cam_rate < 0 || c->cam_rate > 1000)
        return rl_yaml_fail(y, cam, "camera", RL_ERANGE, err, errlen,
                            "width, height must be >= 0 and rate 0 .. 1000");
    return RL_OK;
}

/* The site's files, the serial line and the log's interval. */
static rl_err files_and_serial(rl_yaml *y, yaml_node_t *root, yaml_node_t *ser, const char *path, rl_runcfg *c,
                               char *err, size_t errlen)
{
    rl_err e;
    if ((e = path_key(y, root, "calibration", NULL, 1, path, c->calibration, sizeof c->calibration, err, errlen)) != RL_OK ||
        (e = path_key(y, root, "map", NULL, 1, path, c->map, sizeof c->map, err, errlen)) != RL_OK ||
        (e = path_key(y, root, "robot", NULL, 1, path, c->robot, sizeof c->robot, err, errlen)) != RL_OK ||
        (e = path_key(y, root, "offsets", NULL, 0, path, c->offsets, sizeof c->offsets, err, errlen)) != RL_OK ||
        (e = path_key(y, ser, "device", "serial.device", 1, path, c->serial, sizeof c->serial, err, errlen)) != RL_OK ||
        (e = rl_yaml_int(y, ser, "baud", "serial.baud", 0, &c->baud, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(y, root, "log_interval", NULL, 0, 0, 86400, &c->log_interval, err, errlen)) != RL_OK)
        return e;
    /* device paths like /dev/serial0 are absolute; relative ones are files */
    if (rl_yaml_get(y, ser, "baud") != NULL)
        c->baud_line = (int)rl_yaml_get(y, ser, "baud")->start_mark.line + 1;
    return RL_OK;
}

/* record: {dir, every, max_mb}, optional */
static rl_err record_section(rl_yaml *y, yaml_node_t *root, const char *path, rl_runcfg *c, char *err,
                             size_t errlen)
{
    yaml_node_t *recd = rl_yaml_get(y, root, "record");
    rl_err e;
    if (recd != NULL && recd->type != YAML_MAPPING_NODE)
        return rl_yaml_fail(y, recd, "record", RL_EFORMAT, err, errlen, "expected {dir, every, max_mb}");
    if (recd != NULL &&
        ((e = rl_yaml_only(y, recd, "record", record_keys, err, errlen)) != RL_OK ||
         (e = path_key(y, recd, "dir", "record.dir", 1, path, c->record_dir, sizeof c->record_dir, err,
                       errlen)) != RL_OK ||
         (e = rl_yaml_int(y, recd, "every", "record.every", 0, &c->record_every, err, errlen)) != RL_OK ||
         (e = rl_yaml_double_in(y, recd, "max_mb", "record.max_mb", 0, 0.1, 1e7, &c->record_max_mb, err,
                                errlen)) != RL_OK))
        return e;
    if (c->record_every < 1 || c->record_every > 100000)
        return rl_yaml_fail(y, rl_yaml_get(y, recd, "every"), "record.every", RL_ERANGE, err, errlen,
                            "%d is out of range (1 .. 100000)", c->record_every);
    return RL_OK;
}

/* recognition: {local, min_score, local_min_score, gamma, track_every}, optional */
static rl_err recognition_section(rl_yaml *y, yaml_node_t *rec, rl_runcfg *c, char *err, size_t errlen)
{
    const char *s = NULL;
    rl_err e;
    if (rec == NULL)
        return RL_OK;
    if ((e = rl_yaml_string(y, rec, "local", "recognition.local", 0, &s, err, errlen)) != RL_OK)
        return e;
    if (s != NULL) {
        if (strcmp(s, "auto") == 0) c->local = RL_LOCAL_AUTO;
        else if (strcmp(s, "always") == 0) c->local = RL_LOCAL_ALWAYS;
        else if (strcmp(s, "never") == 0) c->local = RL_LOCAL_NEVER;
        else
            return rl_yaml_fail(y, rl_yaml_get(y, rec, "local"), "recognition.local", RL_EFORMAT, err, errlen,
                                "'%s' is not auto, always or never", s);
    }
    if ((e = score_key(y, rec, "min_score", "recognition.min_score", &c->min_score, err, errlen)) != RL_OK ||
        (e = score_key(y, rec, "local_min_score", "recognition.local_min_score", &c->local_min_score, err,
                       errlen)) != RL_OK ||
        (e = rl_yaml_int(y, rec, "track_every", "recognition.track_every", 0, &c->track_every, err, errlen)) != RL_OK)
        return e;
    if (c->track_every < 0 || c->track_every > 1000)
        return rl_yaml_fail(y, rl_yaml_get(y, rec, "track_every"), "recognition.track_every", RL_ERANGE, err,
                            errlen, "must be 0 (every frame full) .. 1000");
    return gamma_key(y, rec, &c->gamma, err, errlen);
}

rl_err rl_runcfg_load(const char *path, rl_runcfg *c, char *err, size_t errlen)
{
    rl_yaml y;
    yaml_node_t *root, *cam, *ser, *rec;
    rl_err e;
    runcfg_defaults(c);
    if ((e = rl_yaml_load(&y, path, err, errlen)) != RL_OK)
        return e;
    root = rl_yaml_root(&y);
    cam = rl_yaml_get(&y, root, "camera");
    ser = rl_yaml_get(&y, root, "serial");
    rec = rl_yaml_get(&y, root, "recognition");
    if ((e = check_sections(&y, root, cam, ser, rec, err, errlen)) == RL_OK &&
        (e = camera_section(&y, cam, path, c, err, errlen)) == RL_OK &&
        (e = files_and_serial(&y, root, ser, path, c, err, errlen)) == RL_OK &&
        (e = record_section(&y, root, path, c, err, errlen)) == RL_OK &&
        (e = http_section(&y, root, c, err, errlen)) == RL_OK)
        e = recognition_section(&y, rec, c, err, errlen);
    rl_yaml_free(&y);
    return e;
}
