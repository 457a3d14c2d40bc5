#include "rl_calibfile.h"

#include <stdio.h>
#include <string.h>
#include "rl_config.h"
#include "rl_outfile.h"
#include "rl_yaml.h"

/* Read a matrix node {rows, cols, data: [...]} (ROS and OpenCV share this
 * shape). *count gets the number of values; want_min..want_max bound it. */
static rl_err read_matrix(rl_yaml *y, yaml_node_t *root, const char *key, double *vals,
                          int want_min, int want_max, int *count, char *err, size_t errlen)
{
    yaml_node_t *m = rl_yaml_get(y, root, key), *data;
    int i, n, rows = -1, cols = -1;
    char label[64];
    rl_err e;
    if (m == NULL)
        return rl_yaml_fail(y, root, key, RL_EFORMAT, err, errlen, "missing key");
    data = m->type == YAML_MAPPING_NODE ? rl_yaml_get(y, m, "data") : m;
    n = rl_yaml_len(data);
    if (n < 0)
        return rl_yaml_fail(y, m, key, RL_EFORMAT, err, errlen,
                            "expected {rows, cols, data: [...]}");
    if (m->type == YAML_MAPPING_NODE) {
        snprintf(label, sizeof label, "%s.rows", key);
        if ((e = rl_yaml_int(y, m, "rows", label, 0, &rows, err, errlen)) != RL_OK)
            return e;
        snprintf(label, sizeof label, "%s.cols", key);
        if ((e = rl_yaml_int(y, m, "cols", label, 0, &cols, err, errlen)) != RL_OK)
            return e;
        if ((rl_yaml_get(y, m, "rows") != NULL && rows < 1) || (rl_yaml_get(y, m, "cols") != NULL && cols < 1))
            return rl_yaml_fail(y, m, key, RL_EFORMAT, err, errlen, "rows and cols must each be at least 1");
        if (rows >= 0 && cols >= 0 && (long long)rows * cols != n)
            return rl_yaml_fail(y, m, key, RL_EFORMAT, err, errlen,
                                "rows x cols is %dx%d but data has %d values", rows, cols, n);
    }
    if (n < want_min || n > want_max) {
        if (want_min == want_max)
            return rl_yaml_fail(y, m, key, RL_EFORMAT, err, errlen,
                                "expected %d values, got %d", want_min, n);
        return rl_yaml_fail(y, m, key, RL_EFORMAT, err, errlen,
                            "expected %d to %d values, got %d", want_min, want_max, n);
    }
    for (i = 0; i < n; i++) {
        yaml_node_t *it = rl_yaml_item(y, data, i);
        if (!rl_yaml_parse_double(rl_yaml_number_text(it), &vals[i])) {
            snprintf(label, sizeof label, "%s.data[%d]", key, i);
            return rl_yaml_fail(y, it, label, RL_EFORMAT, err, errlen, "expected a number");
        }
    }
    *count = n;
    return RL_OK;
}

/* The lens model from the model's name (ROS distortion_model, OpenCV's
 * fisheye_model flag) and the number of coefficients; a combination that
 * could mean two models is an error, never a guess. */
static rl_err distortion(rl_yaml *y, yaml_node_t *root, const char *model, const double *D, int nd,
                         rl_calib *cam, char *err, size_t errlen)
{
    yaml_node_t *dn = rl_yaml_get(y, root, "distortion_coefficients");
    int fisheye_flag = -1, i;
    rl_err e;
    if (rl_yaml_get(y, root, "fisheye_model") != NULL &&
        (e = rl_yaml_int(y, root, "fisheye_model", NULL, 0, &fisheye_flag, err, errlen)) != RL_OK)
        return e;
    if (fisheye_flag != -1 && fisheye_flag != 0 && fisheye_flag != 1)
        return rl_yaml_fail(y, rl_yaml_get(y, root, "fisheye_model"), "fisheye_model", RL_EFORMAT, err, errlen,
                            "%d is not 0 or 1", fisheye_flag);
    if (model != NULL && (strcmp(model, "equidistant") == 0 || strcmp(model, "fisheye") == 0)) {
        if (fisheye_flag == 0)
            return rl_yaml_fail(y, rl_yaml_get(y, root, "fisheye_model"), "fisheye_model", RL_EFORMAT, err,
                                errlen, "0 contradicts distortion_model %s", model);
        fisheye_flag = 1;
    } else if (model != NULL && strcmp(model, "plumb_bob") != 0 && strcmp(model, "rational_polynomial") != 0) {
        return rl_yaml_fail(y, rl_yaml_get(y, root, "distortion_model"), "distortion_model", RL_EUNSUPPORTED, err,
                            errlen, "'%s' is not supported (plumb_bob, rational_polynomial, equidistant)", model);
    } else if (model != NULL && fisheye_flag == 1) {
        return rl_yaml_fail(y, rl_yaml_get(y, root, "fisheye_model"), "fisheye_model", RL_EFORMAT, err, errlen,
                            "1 contradicts distortion_model %s", model);
    }
    if (fisheye_flag == 1) {
        if (nd != 4)
            return rl_yaml_fail(y, dn ? dn : root, "distortion_coefficients", RL_EFORMAT, err, errlen,
                                "a fisheye (equidistant) lens has 4 coefficients, not %d", nd);
        cam->model = RL_DIST_FISHEYE;
    } else if (model != NULL && strcmp(model, "plumb_bob") == 0) {
        if (nd != 5)
            return rl_yaml_fail(y, dn ? dn : root, "distortion_coefficients", RL_EFORMAT, err, errlen,
                                "plumb_bob has 5 coefficients, not %d", nd);
        cam->model = RL_DIST_PLUMB_BOB;
    } else if (nd == 4 && fisheye_flag == -1 && model == NULL) {
        return rl_yaml_fail(y, dn, "distortion_coefficients", RL_EFORMAT, err, errlen,
                            "4 coefficients and no model: k1 k2 p1 p2 or a fisheye's k1..k4? say "
                            "fisheye_model: 1 (or distortion_model: equidistant) or 0");
    } else if (nd == 0 || nd == 4 || nd == 5 || nd == 8 || nd == 12 || nd == 14) {
        /* OpenCV's standard model: 4, 5, 8, 12 or 14 coefficients */
        if (model != NULL && strcmp(model, "rational_polynomial") == 0 && nd < 5)
            return rl_yaml_fail(y, dn ? dn : root, "distortion_coefficients", RL_EFORMAT, err, errlen,
                                "rational_polynomial has 5, 8, 12 or 14 coefficients, not %d", nd);
        if (nd == 14 && (D[12] != 0.0 || D[13] != 0.0))
            return rl_yaml_fail(y, dn, "distortion_coefficients", RL_EUNSUPPORTED, err, errlen,
                                "the tilted-sensor terms tauX, tauY (%g, %g) are not supported", D[12], D[13]);
        cam->model = nd > 5 ? RL_DIST_RATIONAL : nd > 0 ? RL_DIST_PLUMB_BOB : RL_DIST_NONE;
        if (model != NULL && strcmp(model, "rational_polynomial") == 0)
            cam->model = RL_DIST_RATIONAL;
    } else {
        return rl_yaml_fail(y, dn, "distortion_coefficients", RL_EFORMAT, err, errlen,
                            "%d coefficients fit no model (plumb_bob 5, rational_polynomial 5, 8, 12 or 14, "
                            "fisheye 4)", nd);
    }
    for (i = 0; i < nd && i < RL_CALIB_MAX_COEFFS; i++)
        cam->k[i] = D[i];
    return RL_OK;
}

rl_err rl_calibfile_load(const char *path, rl_calib *cam, char *err, size_t errlen)
{
    return rl_calibfile_load_sized(path, 0, 0, cam, err, errlen);
}

rl_err rl_calibfile_load_sized(const char *path, int width, int height, rl_calib *cam, char *err, size_t errlen)
{
    rl_yaml y;
    yaml_node_t *root;
    double K[9], D[14];
    const char *model = NULL;
    int nk, nd = 0;
    rl_err e;

    memset(cam, 0, sizeof *cam);
    e = rl_yaml_load(&y, path, err, errlen);
    if (e != RL_OK)
        return e;
    root = rl_yaml_root(&y);
    if (root->type != YAML_MAPPING_NODE) {
        e = rl_yaml_fail(&y, root, "calibration", RL_EFORMAT, err, errlen,
                         "expected a ROS camera_info or OpenCV calibration mapping");
        goto out;
    }
    /* OpenCV's calibration files may leave the size out: then it is the
     * caller's (the run configuration, --size) */
    if (width > 0 && height > 0 && rl_yaml_get(&y, root, "image_width") == NULL &&
        rl_yaml_get(&y, root, "image_height") == NULL) {
        cam->width = width;
        cam->height = height;
    } else if (rl_yaml_get(&y, root, "image_width") == NULL && rl_yaml_get(&y, root, "image_height") == NULL) {
        e = rl_yaml_fail(&y, root, "image_width", RL_EFORMAT, err, errlen,
                         "missing, and no image size given (--size WxH, or camera width and height in "
                         "ringloc.yaml)");
        goto out;
    } else if ((e = rl_yaml_int(&y, root, "image_width", NULL, 1, &cam->width, err, errlen)) != RL_OK ||
               (e = rl_yaml_int(&y, root, "image_height", NULL, 1, &cam->height, err, errlen)) != RL_OK) {
        goto out;
    }
    if (cam->width <= 0 || cam->height <= 0) {
        e = rl_yaml_fail(&y, rl_yaml_get(&y, root, "image_width"), "image_width", RL_ERANGE,
                         err, errlen, "image size %dx%d is not positive", cam->width, cam->height);
        goto out;
    }
    if ((e = read_matrix(&y, root, "camera_matrix", K, 9, 9, &nk, err, errlen)) != RL_OK)
        goto out;
    if ((e = rl_yaml_string(&y, root, "distortion_model", NULL, 0, &model, err, errlen)) != RL_OK)
        goto out;
    if (rl_yaml_get(&y, root, "distortion_coefficients") != NULL) {
        if ((e = read_matrix(&y, root, "distortion_coefficients", D, 0, 14, &nd, err, errlen)) !=
            RL_OK)
            goto out;
    }
    cam->fx = K[0];
    cam->cx = K[2];
    cam->fy = K[4];
    cam->cy = K[5];
    if (K[1] != 0.0 || K[3] != 0.0 || K[6] != 0.0 || K[7] != 0.0 || K[8] != 1.0) {
        e = rl_yaml_fail(&y, rl_yaml_get(&y, root, "camera_matrix"), "camera_matrix",
                         RL_EFORMAT, err, errlen, "expected [fx 0 cx; 0 fy cy; 0 0 1]");
        goto out;
    }
    if ((e = distortion(&y, root, model, D, nd, cam, err, errlen)) != RL_OK)
        goto out;
    if (rl_calib_check(cam) != RL_OK) {
        e = rl_yaml_fail(&y, rl_yaml_get(&y, root, "camera_matrix"), "camera_matrix", RL_ERANGE,
                         err, errlen, "%dx%d, fx %g, fy %g, cx %g, cy %g or a distortion "
                         "coefficient out of range (sizes 1 .. %d, focal lengths %g .. %g px, the "
                         "principal point within a frame of the image, coefficients within +-%g)",
                         cam->width, cam->height, cam->fx, cam->fy, cam->cx, cam->cy,
                         RL_MAX_IMAGE_DIM, RL_CALIB_MIN_F, RL_CALIB_MAX_F, RL_CALIB_MAX_K);
        goto out;
    }
out:
    rl_yaml_free(&y);
    return e;
}

rl_err rl_calibfile_save(const char *path, const rl_calib *cam, char *err, size_t errlen)
{
    rl_outfile o;
    FILE *f;
    rl_err e;
    int i, n = cam->model == RL_DIST_FISHEYE ? 4 : cam->model != RL_DIST_RATIONAL ? 5
             : (cam->k[8] != 0 || cam->k[9] != 0 || cam->k[10] != 0 || cam->k[11] != 0) ? 12 : 8;
    if ((e = rl_outfile_open(&o, path, err, errlen)) != RL_OK)
        return e;
    f = o.f;
    fprintf(f, "image_width: %d\nimage_height: %d\ncamera_name: ringloc\n", cam->width,
            cam->height);
    fprintf(f, "camera_matrix:\n  rows: 3\n  cols: 3\n  data: [%.9g, 0, %.9g, 0, %.9g, %.9g, 0, 0, 1]\n",
            cam->fx, cam->cx, cam->fy, cam->cy);
    fprintf(f, "distortion_model: %s\n", cam->model == RL_DIST_FISHEYE ? "equidistant"
                                         : cam->model == RL_DIST_RATIONAL ? "rational_polynomial" : "plumb_bob");
    fprintf(f, "distortion_coefficients:\n  rows: 1\n  cols: %d\n  data: [", n);
    for (i = 0; i < n; i++)
        fprintf(f, "%s%.9g", i ? ", " : "", cam->k[i]);
    fprintf(f, "]\n");
    fprintf(f, "rectification_matrix:\n  rows: 3\n  cols: 3\n  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n");
    fprintf(f, "projection_matrix:\n  rows: 3\n  cols: 4\n  data: [%.9g, 0, %.9g, 0, 0, %.9g, %.9g, 0, 0, 0, 1, 0]\n",
            cam->fx, cam->cx, cam->fy, cam->cy);
    return rl_outfile_commit(&o, err, errlen);
}
