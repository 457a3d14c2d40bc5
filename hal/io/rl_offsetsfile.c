#include "rl_offsetsfile.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rl_outfile.h"
#include "rl_yaml.h"

static rl_err read_list(rl_yaml *y, yaml_node_t *root, const char *key, double *c, int n,
                        char *err, size_t errlen)
{
    yaml_node_t *seq = rl_yaml_get(y, root, key);
    int i;
    if (rl_yaml_len(seq) != n)
        return rl_yaml_fail(y, seq ? seq : root, key, RL_EFORMAT, err, errlen,
                            "expected a list of %d coefficients", n);
    for (i = 0; i < n; i++)
        if (!rl_yaml_parse_double(rl_yaml_number_text(rl_yaml_item(y, seq, i)), &c[i]))
            return rl_yaml_fail(y, rl_yaml_item(y, seq, i), key, RL_EFORMAT, err, errlen,
                                "item %d is not a number", i);
    return RL_OK;
}

static const char *const keys[] = {"type", "degree", "u0", "v0", "scale", "distance", "forward", "left", NULL};

rl_err rl_offsetsfile_load(const char *path, rl_offsets *o, char *err, size_t errlen)
{
    rl_yaml y;
    yaml_node_t *root;
    const char *type = NULL;
    rl_err e;
    memset(o, 0, sizeof *o);
    if ((e = rl_yaml_load(&y, path, err, errlen)) != RL_OK)
        return e;
    root = rl_yaml_root(&y);
    if ((e = rl_yaml_only(&y, root, NULL, keys, err, errlen)) != RL_OK ||
        (e = rl_yaml_string(&y, root, "type", NULL, 1, &type, err, errlen)) != RL_OK)
        goto out;
    if (strcmp(type, "ringloc_offsets") != 0) {
        e = rl_yaml_fail(&y, rl_yaml_get(&y, root, "type"), "type", RL_EFORMAT, err, errlen,
                         "'%s' is not ringloc_offsets", type);
        goto out;
    }
    if ((e = rl_yaml_int(&y, root, "degree", NULL, 1, &o->degree, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, root, "u0", NULL, 1, -1e5, 1e5, &o->u0, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, root, "v0", NULL, 1, -1e5, 1e5, &o->v0, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, root, "scale", NULL, 1, 1e-3, 1e5, &o->scale, err, errlen)) != RL_OK ||
        (e = rl_yaml_double_in(&y, root, "distance", NULL, 1, 1e-3, 100, &o->distance, err, errlen)) != RL_OK)
        goto out;
    if (o->degree < 1 || o->degree > 3 || !(o->scale > 0) || !(o->distance > 0)) {
        e = rl_yaml_fail(&y, root, "degree", RL_ERANGE, err, errlen,
                         "degree must be 1..3 and scale, distance positive");
        goto out;
    }
    if ((e = read_list(&y, root, "forward", o->cx, rl_offsets_terms(o->degree), err, errlen)) != RL_OK ||
        (e = read_list(&y, root, "left", o->cy, rl_offsets_terms(o->degree), err, errlen)) != RL_OK)
        goto out;
out:
    rl_yaml_free(&y);
    return e;
}

rl_err rl_offsetsfile_save(const char *path, const rl_offsets *o, char *err, size_t errlen)
{
    rl_outfile out;
    FILE *f;
    rl_err e;
    int i, n = rl_offsets_terms(o->degree);
    if ((e = rl_outfile_open(&out, path, err, errlen)) != RL_OK)
        return e;
    f = out.f;
    fprintf(f, "type: ringloc_offsets\ndegree: %d\nu0: %.6f\nv0: %.6f\nscale: %.6f\ndistance: %.6f\n",
            o->degree, o->u0, o->v0, o->scale, o->distance);
    fprintf(f, "forward: [");
    for (i = 0; i < n; i++)
        fprintf(f, "%s%.12g", i ? ", " : "", o->cx[i]);
    fprintf(f, "]\nleft: [");
    for (i = 0; i < n; i++)
        fprintf(f, "%s%.12g", i ? ", " : "", o->cy[i]);
    fprintf(f, "]\n");
    return rl_outfile_commit(&out, err, errlen);
}

/* Solve the normal equations A c = b (n x n) by Gaussian elimination. */
static int solve(double A[RL_OFFSET_TERMS][RL_OFFSET_TERMS + 2], int n, double *c, int col)
{
    double M[RL_OFFSET_TERMS][RL_OFFSET_TERMS + 1];
    int i, j, k;
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++)
            M[i][j] = A[i][j];
        M[i][n] = A[i][RL_OFFSET_TERMS + col];
    }
    for (k = 0; k < n; k++) {
        int piv = k;
        for (i = k + 1; i < n; i++)
            if (fabs(M[i][k]) > fabs(M[piv][k]))
                piv = i;
        if (fabs(M[piv][k]) < 1e-12)
            return -1;
        for (j = 0; j <= n; j++) {
            double t = M[k][j];
            M[k][j] = M[piv][j];
            M[piv][j] = t;
        }
        for (i = k + 1; i < n; i++) {
            double q = M[i][k] / M[k][k];
            for (j = k; j <= n; j++)
                M[i][j] -= q * M[k][j];
        }
    }
    for (k = n - 1; k >= 0; k--) {
        double v = M[k][n];
        for (j = k + 1; j < n; j++)
            v -= M[k][j] * c[j];
        c[k] = v / M[k][k];
    }
    return 0;
}

rl_err rl_offsets_fit(rl_offsets *o, const double *u, const double *v, const double *fwd,
                      const double *left, int n)
{
    double A[RL_OFFSET_TERMS][RL_OFFSET_TERMS + 2];
    int terms = rl_offsets_terms(o->degree), i, j, k;
    if (n < terms + 2)
        return RL_ETOOFEW;
    memset(A, 0, sizeof A);
    for (k = 0; k < n; k++) {
        rl_offsets one = *o;
        double t[RL_OFFSET_TERMS], f, l;
        /* the monomials: evaluate a unit coefficient at a time */
        for (i = 0; i < terms; i++) {
            memset(one.cx, 0, sizeof one.cx);
            one.cx[i] = 1;
            rl_offsets_eval(&one, u[k], v[k], &t[i], &f);
        }
        (void)l;
        for (i = 0; i < terms; i++) {
            for (j = 0; j < terms; j++)
                A[i][j] += t[i] * t[j];
            A[i][RL_OFFSET_TERMS] += t[i] * fwd[k];
            A[i][RL_OFFSET_TERMS + 1] += t[i] * left[k];
        }
    }
    if (solve(A, terms, o->cx, 0) != 0 || solve(A, terms, o->cy, 1) != 0)
        return RL_ERANGE;
    return RL_OK;
}
