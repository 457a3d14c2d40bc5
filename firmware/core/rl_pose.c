#include "rl_pose.h"

#include <math.h>
#include <string.h>
#include "rl_pose_fit.h"

void rl_mount_defaults(rl_mount *m, double z)
{
    m->x = m->y = m->yaw = m->roll = m->pitch = 0.0;
    m->z = z;
    m->rocking = RL_POSE_TILT_PRIOR;
}

int rl_offsets_terms(int degree)
{
    return degree <= 1 ? 3 : degree == 2 ? 6 : 10;
}

/* Monomials 1, u, v, u^2, uv, v^2, u^3, u^2 v, u v^2, v^3. */
static void monomials(double u, double v, double *t)
{
    t[0] = 1;
    t[1] = u;
    t[2] = v;
    t[3] = u * u;
    t[4] = u * v;
    t[5] = v * v;
    t[6] = u * u * u;
    t[7] = u * u * v;
    t[8] = u * v * v;
    t[9] = v * v * v;
}

void rl_offsets_eval(const rl_offsets *o, double u, double v, double *fwd, double *left)
{
    double t[RL_OFFSET_TERMS];
    int i, n = rl_offsets_terms(o->degree);
    monomials((u - o->u0) / o->scale, (v - o->v0) / o->scale, t);
    *fwd = *left = 0;
    for (i = 0; i < n; i++) {
        *fwd += o->cx[i] * t[i];
        *left += o->cy[i] * t[i];
    }
}

void rl_pose_ceiling_point(const rl_calib *cam, const rl_offsets *offsets, double distance,
                           double u, double v, double *fwd, double *left)
{
    if (offsets != NULL) {
        /* offsets scale with the distance to the ceiling (similar triangles) */
        double k = distance / offsets->distance;
        rl_offsets_eval(offsets, u, v, fwd, left);
        *fwd *= k;
        *left *= k;
    } else {
        double xn, yn;
        rl_calib_unproject(cam, u, v, &xn, &yn);
        /* image top (-v) is forward, +u is left */
        *fwd = -yn * distance;
        *left = xn * distance;
    }
}

/* The mount's rotation, the ceiling and the centre noise. */
static void make_model(const rl_calib *cam, const rl_map *map, const rl_mount *mount, rl_pose_model *md)
{
    rl_pose_fit_model(md, mount, map->ceiling_height, 0.5 * map->diameter);
    md->sn = RL_POSE_PIXEL_SIGMA / sqrt(cam->fx * cam->fy);
    md->prior[0] = md->prior[1] = fmax(RL_POSE_TILT_LEVEL, mount->rocking);
}

/* One detection as a point: its ray and, for a level robot, where that
 * meets the ceiling in the robot frame (the offset map's point with
 * offsets). 0 if the ray misses the ceiling. */
static int observe(const rl_calib *cam, const rl_map *map, const rl_pose_model *md, const rl_offsets *offsets,
                   const rl_detection *d, double Z, rl_pose_pt *p)
{
    const rl_mount *mount = md->mount;
    if (offsets != NULL) {
        /* the offset map is in the camera's horizontal frame */
        double f, l;
        rl_pose_ceiling_point(cam, offsets, Z, d->u, d->v, &f, &l);
        p->px = mount->x + cos(mount->yaw) * f - sin(mount->yaw) * l;
        p->py = mount->y + sin(mount->yaw) * f + cos(mount->yaw) * l;
        p->xn = p->yn = 0;
    } else {
        /* the ray, tilted by the mount, meets the ceiling of a level robot */
        rl_calib_centre(cam, d->u, d->v, 0.5 * map->diameter / Z, &p->xn, &p->yn);
        if (!rl_pose_fit_level_point(md, Z, p->xn, p->yn, &p->px, &p->py))
            return 0;
    }
    p->id = d->id;
    /* a centre from an arc the border left is less sure */
    p->noise = d->complete ? 1.0 : 4.0;
    p->w = 1.0;
    return 1;
}

/* Consistency: distances between observed points must match the map's
 * (a rigid motion keeps them). Drop the landmark that disagrees with most
 * others until all agree; two that disagree cannot be told apart. Returns
 * how many are left. */
static int drop_inconsistent(rl_pose_pt *pt, int m, rl_pose *out)
{
    int i, j;
    for (;;) {
        int worst = -1, worst_bad = 0, bad[RL_MAX_LANDMARKS];
        memset(bad, 0, sizeof *bad * (size_t)m);
        for (i = 0; i < m; i++) /* each pair once: it counts against both */
            for (j = i + 1; j < m; j++) {
                double dp = hypot(pt[i].px - pt[j].px, pt[i].py - pt[j].py),
                       dm = hypot(pt[i].mx - pt[j].mx, pt[i].my - pt[j].my);
                int off = fabs(dp - dm) > RL_POSE_PAIR_TOLERANCE + 0.04 * dm;
                bad[i] += off;
                bad[j] += off;
            }
        for (i = 0; i < m; i++)
            if (bad[i] > worst_bad) {
                worst_bad = bad[i];
                worst = i;
            }
        if (worst < 0)
            return m;
        if (m <= 2) {
            for (i = 0; i < m; i++)
                out->dropped[out->n_dropped++] = pt[i].id;
            return 0;
        }
        out->dropped[out->n_dropped++] = pt[worst].id;
        pt[worst] = pt[--m];
    }
}

/* The weight of the tilted fit against the level one: the probability of
 * the tilted model given the centres (Bayesian model averaging), from how
 * much its two parameters lower the misfit in units of its own residuals
 * (`evidence`): one half at RL_POSE_TILT_EVIDENCE, log-odds rising by one
 * half per unit, so a frame near the line takes a little of both fits
 * rather than all of one (a 0.03 px shift of one centre had moved a pose
 * by 13 mm). */
double rl_pose_tilt_weight(double evidence)
{
    double z = 0.5 * (evidence - RL_POSE_TILT_EVIDENCE);
    if (isnan(z))
        return 0.0;
    return z > 40 ? 1.0 : z < -40 ? 0.0 : 1.0 / (1.0 + exp(-z));
}

/* 1 when the fit's variances in cov are numbers, not negative. */
static int variances_ok(const double *cov)
{
    int i;
    for (i = 0; i < RL_POSE_NQ; i++)
        if (!(cov[i * RL_POSE_NQ + i] >= 0 && isfinite(cov[i * RL_POSE_NQ + i])))
            return 0;
    return 1;
}

/* The tilted fit (qt, its variances on covt's diagonal) averaged with
 * weight w into the level one's q and cov: the pose's variances take the
 * spread between the fits too. */
static void average_fits(double w, const double *qt, const double *covt, double *q, double *cov)
{
    double d[RL_POSE_NQ];
    int i;
    for (i = 0; i < RL_POSE_NQ; i++)
        d[i] = qt[i] - q[i];
    d[2] = atan2(sin(d[2]), cos(d[2]));
    for (i = 0; i < RL_POSE_NQ; i++) {
        double *v = &cov[i * RL_POSE_NQ + i];
        *v = w * covt[i * RL_POSE_NQ + i] + (1 - w) * *v + w * (1 - w) * d[i] * d[i];
        q[i] += w * d[i];
    }
}

/* The tilt about one axis a level fit leaves in its uncertainty (held,
 * "considered": the fit is off by as much as the robot leans): the
 * robot's rocking (rl_mount.rocking) as the tilted fit's lean and its
 * sigma s about that axis have narrowed it (combined as two independent
 * estimates are: the root of the posterior's variance plus its mean
 * squared).
 * Before, 20 urad wherever a tilted fit existed: the demo's level frames
 * (rocking 0.01 rad) were 3-7 mm off with sigmas of 0.1-0.3 mm. */
static double level_prior(const rl_pose_model *md, double lean, double s)
{
    double p2 = md->mount->rocking * md->mount->rocking, s2 = s * s;
    lean *= p2 / (p2 + s2);
    return fmax(RL_POSE_TILT_LEVEL, sqrt(p2 * s2 / (p2 + s2) + lean * lean));
}

/* The pinhole fits from the level start q: with three or more landmarks
 * the tilted one and the level one, averaged by rl_pose_tilt_weight
 * (tilt_solved when the tilted one weighs more). q and the variances on
 * the diagonal of cov of the average, chi2 the fits' chi2 averaged by
 * weight (an upper bound on the average pose's). */
static int fit_pinhole(rl_pose_model *md, rl_pose_pt *pt, int m, double *q, double *cov, double *chi2,
                       rl_pose *out)
{
    double qt[RL_POSE_NQ], covt[RL_POSE_NQ * RL_POSE_NQ], chi2t = 0, w = 0;
    int solved = 0, i;
    memcpy(qt, q, sizeof qt);
    if (m >= 3) {
        md->prior[0] = md->prior[1] = RL_POSE_TILT_WEAK;
        solved = rl_pose_fit_solve(md, pt, m, RL_POSE_NQ, qt, covt, &chi2t) && variances_ok(covt);
        if (solved) {
            out->fit_roll = qt[3];
            out->fit_pitch = qt[4];
            out->fit_sigma_roll = sqrt(covt[3 * RL_POSE_NQ + 3]);
            out->fit_sigma_pitch = sqrt(covt[4 * RL_POSE_NQ + 4]);
            out->fit_valid = 1;
        }
    }
    /* the paper's model: a level robot (the mount's tilt applied); its
     * rocking is in the uncertainty: with two landmarks all of it, with
     * more what the tilted fit could not rule out */
    md->prior[0] = md->prior[1] = fmax(RL_POSE_TILT_LEVEL, md->mount->rocking);
    if (solved) { /* each axis as the tilted fit found it */
        md->prior[0] = level_prior(md, out->fit_roll, out->fit_sigma_roll);
        md->prior[1] = level_prior(md, out->fit_pitch, out->fit_sigma_pitch);
    }
    for (i = 0; i < m; i++)
        pt[i].w = 1;
    if (!rl_pose_fit_solve(md, pt, m, 3, q, cov, chi2)) {
        if (!solved)
            return 0;
        w = 1;
    } else if (solved) {
        double unit = fmax(1.0, chi2t / fmax(1.0, 2.0 * m - RL_POSE_NQ));
        w = rl_pose_tilt_weight((*chi2 - chi2t) / unit);
    }
    if (w >= 1) {
        memcpy(q, qt, sizeof qt);
        memcpy(cov, covt, sizeof covt);
        *chi2 = chi2t;
    } else if (w > 0) {
        average_fits(w, qt, covt, q, cov);
        *chi2 = w * chi2t + (1 - w) * *chi2;
    }
    out->tilt_weight = w;
    out->tilt_solved = w > 0.5;
    return 1;
}

/* The pose, the camera and the uncertainty from q into out; RL_ERANGE
 * unless every number is finite and the pose within the map's limits. */
static rl_err finish(const rl_pose_model *md, const double *q, int offsets, rl_pose *out)
{
    double Rc[9], C[3];
    const rl_mount *mount = md->mount;
    out->x = q[0];
    out->y = q[1];
    out->yaw = atan2(sin(q[2]), cos(q[2]));
    rl_pose_fit_camera(md, q, Rc, C);
    if (offsets) {
        C[0] = q[0] + cos(q[2]) * mount->x - sin(q[2]) * mount->y;
        C[1] = q[1] + sin(q[2]) * mount->x + cos(q[2]) * mount->y;
    }
    out->cam_x = C[0];
    out->cam_y = C[1];
    out->cam_yaw = atan2(Rc[3], Rc[0]);
    out->roll = atan2(Rc[7], Rc[8]);
    out->pitch = -asin(fmax(-1.0, fmin(1.0, Rc[6])));
    /* what leaves for JSON or the wire is a number, or there is no pose */
    if (!isfinite(out->x) || !isfinite(out->y) || !isfinite(out->yaw) || !isfinite(out->residual) ||
        !isfinite(out->cam_x) || !isfinite(out->cam_y) || !isfinite(out->cam_yaw) ||
        !isfinite(out->sigma_x) || !isfinite(out->sigma_y) || !isfinite(out->sigma_yaw) ||
        !isfinite(out->roll) || !isfinite(out->pitch) ||
        !(fabs(out->x) <= 2 * RL_MAP_MAX_COORD) || !(fabs(out->y) <= 2 * RL_MAP_MAX_COORD))
        return RL_ERANGE;
    return RL_OK;
}

int rl_pose_level_point(const rl_calib *cam, const rl_map *map, const rl_mount *mount, const rl_offsets *offsets,
                        const rl_detection *d, double *x, double *y)
{
    rl_pose_model md;
    rl_pose_pt p;
    double Z = map->ceiling_height - mount->z;
    if (!(Z > 0))
        return 0;
    make_model(cam, map, mount, &md);
    if (!observe(cam, map, &md, offsets, d, Z, &p))
        return 0;
    *x = p.px;
    *y = p.py;
    return 1;
}

rl_err rl_pose_solve(const rl_calib *cam, const rl_map *map, const rl_mount *mount,
                     const rl_detection *lm, int n, const rl_offsets *offsets, rl_pose *out)
{
    int match[RL_MAX_LANDMARKS], i;
    if (map == NULL || n < 0 || (n > 0 && lm == NULL))
        return RL_EINVAL;
    if (n > RL_MAX_LANDMARKS)
        n = RL_MAX_LANDMARKS; /* more than a frame reports (rl_result) */
    for (i = 0; i < n; i++)
        match[i] = rl_map_find(map, lm[i].id);
    return rl_pose_solve_matched(cam, map, mount, lm, n, match, offsets, out);
}

rl_err rl_pose_solve_matched(const rl_calib *cam, const rl_map *map, const rl_mount *mount,
                             const rl_detection *lm, int n, const int *match, const rl_offsets *offsets,
                             rl_pose *out)
{
    rl_pose_pt pt[RL_MAX_LANDMARKS];
    int i, m = 0;
    double Z, c, s, sum2 = 0, q[RL_POSE_NQ], cov[RL_POSE_NQ * RL_POSE_NQ], chi2 = 0;
    rl_pose_model md;
    if (cam == NULL || map == NULL || mount == NULL || out == NULL || (n > 0 && (lm == NULL || match == NULL)) ||
        n < 0 || rl_calib_check(cam) != RL_OK)
        return RL_EINVAL;
    memset(out, 0, sizeof *out);
    if (n > RL_MAX_LANDMARKS)
        n = RL_MAX_LANDMARKS; /* more than a frame reports (rl_result) */
    Z = map->ceiling_height - mount->z;
    if (!(Z > 0) || !(fabs(mount->roll) < 0.5) || !(fabs(mount->pitch) < 0.5) ||
        !(mount->rocking >= 0 && mount->rocking <= RL_POSE_ROCKING_MAX))
        return RL_ERANGE;
    make_model(cam, map, mount, &md);
    for (i = 0; i < n && m < RL_MAX_LANDMARKS; i++) {
        int k = match[i] < map->count ? match[i] : -1;
        double Zk = k >= 0 ? rl_map_height(map, k) - mount->z : 0; /* its own height above the camera */
        if (!(fabs(lm[i].u - 0.5 * cam->width) <= 1.5 * cam->width) ||
            !(fabs(lm[i].v - 0.5 * cam->height) <= 1.5 * cam->height)) {
            /* no camera of this size sees a landmark there */
            out->dropped[out->n_dropped++] = lm[i].id;
        } else if (k < 0) {
            out->n_unknown++;
        } else if (!(Zk >= RL_POSE_MIN_DEPTH) || !observe(cam, map, &md, offsets, &lm[i], Zk, &pt[m])) {
            /* a landmark hung down to the camera, or a ray that misses it */
            out->dropped[out->n_dropped++] = lm[i].id;
        } else {
            pt[m].mx = map->lm[k].x;
            pt[m].my = map->lm[k].y;
            pt[m].mz = rl_map_height(map, k);
            m++;
        }
    }
    out->used = m = drop_inconsistent(pt, m, out);
    if (m < 2)
        return RL_ETOOFEW;
    /* the level robot's pose: a rigid fit in the floor plane */
    rl_pose_fit_rigid(pt, m, &q[0], &q[1], &q[2]);
    q[3] = q[4] = 0;
    if (offsets != NULL) {
        /* no camera model to fit against: the misfit and spread of the
         * rigid fit */
        double spread = 0, noise;
        c = cos(q[2]);
        s = sin(q[2]);
        for (i = 0; i < m; i++) {
            double fx = q[0] + c * pt[i].px - s * pt[i].py, fy = q[1] + s * pt[i].px + c * pt[i].py;
            sum2 += (fx - pt[i].mx) * (fx - pt[i].mx) + (fy - pt[i].my) * (fy - pt[i].my);
        }
        out->residual = sqrt(sum2 / m);
        noise = fmax(out->residual, 0.001);
        for (i = 0; i < m; i++)
            spread += (pt[i].px * pt[i].px + pt[i].py * pt[i].py);
        out->sigma_x = out->sigma_y = noise / sqrt((double)m);
        out->sigma_yaw = noise / sqrt(fmax(spread, 1e-6));
    } else {
        if (!fit_pinhole(&md, pt, m, q, cov, &chi2, out))
            return RL_ERANGE;
        out->sigma_x = sqrt(cov[0]);
        out->sigma_y = sqrt(cov[RL_POSE_NQ + 1]);
        out->sigma_yaw = sqrt(cov[2 * RL_POSE_NQ + 2]);
        out->residual = sqrt(chi2 / m) * md.sn * Z;
    }
    return finish(&md, q, offsets != NULL, out);
}

int rl_pose_project(const rl_calib *cam, const rl_map *map, const rl_mount *mount, const rl_pose *p, double X,
                    double Y, double Z, double *u, double *v)
{
    rl_pose_model md;
    double q[RL_POSE_NQ], Rc[9], C[3], xn, yn;
    rl_pose_fit_model(&md, mount, map->ceiling_height, 0.5 * map->diameter);
    q[0] = p->x;
    q[1] = p->y;
    q[2] = p->yaw;
    q[3] = p->fit_valid ? p->tilt_weight * p->fit_roll : 0.0;
    q[4] = p->fit_valid ? p->tilt_weight * p->fit_pitch : 0.0;
    rl_pose_fit_camera(&md, q, Rc, C);
    if (!rl_pose_fit_predict(&md, Rc, C, X, Y, Z, &xn, &yn))
        return 0;
    rl_calib_project(cam, xn, yn, u, v);
    return 1;
}
