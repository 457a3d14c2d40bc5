#include "rl_survey_input.h"

#include <errno.h>
#include <json-c/json.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "rl_infile.h"
#include "rl_png.h"
#include "rl_pngrun.h"

void rl_survey_input_init(rl_survey_input *in, const rl_calib *cam, const rl_family *fam, rl_survey *sv,
                          rl_site *site)
{
    memset(in, 0, sizeof *in);
    in->cam = cam;
    in->fam = fam;
    in->sv = sv;
    in->site = site;
}

/* One frame's detections (the identified ones) into the survey. */
static rl_err add_frame(rl_survey_input *in, const char *name, const rl_detection *d, int n)
{
    rl_survey_obs obs[RL_MAX_LANDMARKS];
    int i, m = 0;
    for (i = 0; i < n && m < RL_MAX_LANDMARKS; i++) {
        rl_survey_obs *o = &obs[m];
        double r = d[i].radius / in->cam->fx;
        o->rn = 0;
        o->noise = d[i].complete ? 1.0 : 4.0;
        if (d[i].complete)
            r = rl_calib_radius(in->cam, d[i].u, d[i].v, d[i].radius);
        rl_calib_centre(in->cam, d[i].u, d[i].v, r, &o->xn, &o->yn);
        /* the scale from radii measured both ways across the outer black
         * band (unbiased), near the optical axis (where the lens
         * distorts the landmark least) */
        if (d[i].complete && rl_family_band_inner(in->fam, d[i].id) > 0 &&
            o->xn * o->xn + o->yn * o->yn < RL_SURVEY_RADIUS_FIELD * RL_SURVEY_RADIUS_FIELD)
            o->rn = r;
        o->id = d[i].id;
        if (o->xn == o->xn && o->yn == o->yn && (o->rn == o->rn))
            m++;
    }
    in->frames++;
    if (in->progress && in->frames % 50 == 0)
        fprintf(stderr, "ringloc survey: %d frames read\r", in->frames);
    return rl_survey_add_frame(in->sv, name, obs, m) == RL_OK ? RL_OK : RL_ENOMEM;
}

/* Each recognized frame into the survey. */
static rl_err png_put(void *ctx, const rl_run_report *rep)
{
    rl_survey_input *in = (rl_survey_input *)ctx;
    if (add_frame(in, rep->frame->name, rep->res->landmarks, rep->res->n_landmarks) != RL_OK) {
        snprintf(in->err, sizeof in->err, "out of memory after %d frames", in->frames);
        in->failed = 1;
    }
    return RL_OK;
}

/* PNG frames through the loop: a file that cannot be read or used is
 * left out with one line saying why. */
static rl_err png_frames(rl_survey_input *in, char *const *paths, int n)
{
    rl_pngrun pr;
    if (in->site == NULL) {
        snprintf(in->err, sizeof in->err, "%s: PNG frames need the recognizer", paths[0]);
        return RL_EINVAL;
    }
    rl_pngrun_defaults(&pr, "survey");
    pr.run.alone = 1;
    pr.put = png_put;
    pr.ctx = in;
    pr.bad_suffix = "; left out";
    in->unreadable += (int)rl_pngrun_files(&pr, in->site, paths, n);
    return in->failed ? RL_ENOMEM : RL_OK;
}

/* A number field of a JSON object; 0 if missing or not a number. */
static int json_num(json_object *o, const char *key, double *out)
{
    json_object *v;
    if (!json_object_object_get_ex(o, key, &v) ||
        !(json_object_is_type(v, json_type_double) || json_object_is_type(v, json_type_int)))
        return 0;
    *out = json_object_get_double(v);
    return *out == *out;
}

/* One line of detect output: {"image", "width", "height", "landmarks": [{"id", "u", "v", "radius",
 * "complete"}...]}. */
static rl_err json_frame(rl_survey_input *in, const char *path, long line, const char *text)
{
    static rl_detection d[RL_MAX_LANDMARKS];
    enum json_tokener_error je;
    json_object *o = json_tokener_parse_verbose(text, &je), *lms, *v;
    const char *name = NULL;
    char label[1200];
    int i, n, m = 0;
    double w, h;
    rl_err e = RL_EFORMAT;
    if (o == NULL || !json_object_is_type(o, json_type_object)) {
        snprintf(in->err, sizeof in->err, "%s:%ld: not a JSON object (%s)", path, line,
                 o ? "another JSON value" : json_tokener_error_desc(je));
        goto out;
    }
    if (!json_object_object_get_ex(o, "landmarks", &lms) || !json_object_is_type(lms, json_type_array)) {
        snprintf(in->err, sizeof in->err, "%s:%ld: no \"landmarks\" list (is it `ringloc detect` output?)", path,
                 line);
        goto out;
    }
    if (json_num(o, "width", &w) && json_num(o, "height", &h) &&
        (w != in->cam->width || h != in->cam->height)) {
        snprintf(in->err, sizeof in->err, "%s:%ld: a %gx%g frame, the calibration is for %dx%d", path, line, w, h,
                 in->cam->width, in->cam->height);
        goto out;
    }
    if (json_object_object_get_ex(o, "image", &v) && json_object_is_type(v, json_type_string))
        name = json_object_get_string(v);
    n = (int)json_object_array_length(lms);
    for (i = 0; i < n; i++) {
        json_object *l = json_object_array_get_idx(lms, (size_t)i), *c;
        double id;
        if (!json_object_is_type(l, json_type_object) || !json_num(l, "id", &id) || !json_num(l, "u", &d[m].u) ||
            !json_num(l, "v", &d[m].v) || !json_num(l, "radius", &d[m].radius)) {
            snprintf(in->err, sizeof in->err, "%s:%ld: landmarks[%d] lacks a number id, u, v or radius", path, line,
                     i);
            goto out;
        }
        if (!(id >= 1 && id <= 1 << 20) || id != floor(id) || !rl_family_valid(in->fam, (int)id)) {
            snprintf(in->err, sizeof in->err, "%s:%ld: landmarks[%d]: id %g is not in ring%d (1 .. %d)", path, line,
                     i, id, in->fam->bits, rl_family_count(in->fam));
            goto out;
        }
        if (!(d[m].radius > 0 && d[m].radius < 1e5 && d[m].u > -1e5 && d[m].u < 1e5 && d[m].v > -1e5 &&
              d[m].v < 1e5)) {
            snprintf(in->err, sizeof in->err, "%s:%ld: landmarks[%d]: u, v or radius out of range", path, line, i);
            goto out;
        }
        d[m].id = (int)id;
        d[m].complete = !json_object_object_get_ex(l, "complete", &c) || json_object_get_boolean(c);
        if (m < RL_MAX_LANDMARKS - 1)
            m++;
    }
    if (name == NULL) {
        snprintf(label, sizeof label, "%s:%ld", path, line);
        name = label;
    }
    e = add_frame(in, name, d, m);
    if (e != RL_OK)
        snprintf(in->err, sizeof in->err, "out of memory after %d frames", in->frames);
out:
    if (o)
        json_object_put(o);
    return e;
}

static rl_err json_file(rl_survey_input *in, const char *path)
{
    char *buf = NULL;
    size_t cap = 0;
    long line = 0;
    ssize_t len;
    rl_err e = RL_OK;
    FILE *f = rl_infile_fopen(path, "a file of detect JSON lines", &e, in->err, sizeof in->err);
    if (f == NULL)
        return e == RL_EIO ? RL_ENOTFOUND : e;
    while (e == RL_OK && (len = getline(&buf, &cap, f)) >= 0) {
        line++;
        while (len > 0 && (buf[len - 1] == '\n' || buf[len - 1] == '\r' || buf[len - 1] == ' '))
            buf[--len] = '\0';
        if (len == 0)
            continue;
        if (memchr(buf, '\0', (size_t)len)) {
            snprintf(in->err, sizeof in->err, "%s:%ld: not text", path, line);
            e = RL_EFORMAT;
            break;
        }
        e = json_frame(in, path, line, buf);
    }
    if (e == RL_OK && ferror(f)) {
        snprintf(in->err, sizeof in->err, "%s: read failed", path);
        e = RL_EIO;
    } else if (e == RL_OK && line == 0) {
        snprintf(in->err, sizeof in->err, "%s: no frames in the file (empty)", path);
        e = RL_ENOTFOUND;
    }
    free(buf);
    fclose(f);
    return e;
}

static int has_suffix(const char *s, const char *suf)
{
    size_t n = strlen(s), m = strlen(suf);
    return n >= m && strcmp(s + n - m, suf) == 0;
}

static rl_err folder(rl_survey_input *in, const char *path)
{
    char **names = NULL;
    int n = 0;
    rl_err e;
    if ((e = rl_png_list(path, &names, &n, in->err, sizeof in->err)) != RL_OK)
        return e;
    if (n == 0) {
        snprintf(in->err, sizeof in->err, "%s: no PNG frames in the folder", path);
        e = RL_ENOTFOUND;
    } else {
        e = png_frames(in, names, n);
    }
    rl_png_list_free(names, n);
    return e;
}

rl_err rl_survey_input_path(rl_survey_input *in, const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        snprintf(in->err, sizeof in->err, "%s: %s", path, strerror(errno));
        return RL_ENOTFOUND;
    }
    if (S_ISDIR(st.st_mode))
        return folder(in, path);
    if (has_suffix(path, ".json") || has_suffix(path, ".jsonl") || has_suffix(path, ".ndjson"))
        return json_file(in, path);
    return png_frames(in, (char *const *)&path, 1);
}
