#include "rl_pose_fit.h"

#include <math.h>
#include <string.h>

void rl_pose_fit_mul(const double *a, const double *b, double *c)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            c[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
}

/* Rz(yaw) Ry(pitch) Rx(roll) from the angles' cosines and sines */
static void rotation_cs(double cz, double sz, double cy, double sy, double cx, double sx, double *R)
{
    R[0] = cz * cy;
    R[1] = cz * sy * sx - sz * cx;
    R[2] = cz * sy * cx + sz * sx;
    R[3] = sz * cy;
    R[4] = sz * sy * sx + cz * cx;
    R[5] = sz * sy * cx - cz * sx;
    R[6] = -sy;
    R[7] = cy * sx;
    R[8] = cy * cx;
}

void rl_pose_fit_rotation(double yaw, double pitch, double roll, double *R)
{
    rotation_cs(cos(yaw), sin(yaw), cos(pitch), sin(pitch), cos(roll), sin(roll), R);
}

void rl_pose_fit_model(rl_pose_model *md, const rl_mount *mount, double height, double radius)
{
    double T[9], Y[9];
    /* the mount's tilt about the robot's axes, then the camera's yaw */
    rl_pose_fit_rotation(0, mount->pitch, mount->roll, T);
    rl_pose_fit_rotation(mount->yaw, 0, 0, Y);
    rl_pose_fit_mul(T, Y, md->Rm);
    md->mount = mount;
    md->height = height;
    md->radius = radius;
    md->sn = 1.0;
    md->prior[0] = md->prior[1] = 1.0;
}

int rl_pose_fit_level_point(const rl_pose_model *md, double Z, double xn, double yn, double *px, double *py)
{
    const double *R = md->Rm;
    double bf = R[0] * -yn + R[1] * xn + R[2], bl = R[3] * -yn + R[4] * xn + R[5],
           bu = R[6] * -yn + R[7] * xn + R[8];
    if (!(bu > 1e-6))
        return 0;
    *px = md->mount->x + Z / bu * bf;
    *py = md->mount->y + Z / bu * bl;
    return 1;
}

/* Least-squares rotation and translation taking p onto m (2-D Procrustes
 * without scale): the rotation angle has a closed form. */
void rl_pose_fit_rigid(const rl_pose_pt *pt, int n, double *tx, double *ty, double *yaw)
{
    double pcx = 0, pcy = 0, mcx = 0, mcy = 0, sc = 0, ss = 0, c, s;
    int i;
    for (i = 0; i < n; i++) {
        pcx += pt[i].px;
        pcy += pt[i].py;
        mcx += pt[i].mx;
        mcy += pt[i].my;
    }
    pcx /= n;
    pcy /= n;
    mcx /= n;
    mcy /= n;
    for (i = 0; i < n; i++) {
        double ax = pt[i].px - pcx, ay = pt[i].py - pcy, bx = pt[i].mx - mcx, by = pt[i].my - mcy;
        sc += ax * bx + ay * by;
        ss += ax * by - ay * bx;
    }
    *yaw = atan2(ss, sc);
    c = cos(*yaw);
    s = sin(*yaw);
    *tx = mcx - (c * pcx - s * pcy);
    *ty = mcy - (s * pcx + c * pcy);
}


/* The camera's rotation and centre on the robot rotated by Rr at q. */
static void camera_of(const rl_pose_model *md, const double *q, const double *Rr, double *Rc, double *C)
{
    const rl_mount *m = md->mount;
    rl_pose_fit_mul(Rr, md->Rm, Rc);
    C[0] = q[0] + Rr[0] * m->x + Rr[1] * m->y + Rr[2] * m->z;
    C[1] = q[1] + Rr[3] * m->x + Rr[4] * m->y + Rr[5] * m->z;
    C[2] = Rr[6] * m->x + Rr[7] * m->y + Rr[8] * m->z;
}

void rl_pose_fit_camera(const rl_pose_model *md, const double *q, double *Rc, double *C)
{
    double Rr[9];
    rl_pose_fit_rotation(q[2], q[4], q[3], Rr);
    camera_of(md, q, Rr, Rc, C);
}

/* The robot's rotation's derivatives: by yaw [ez]x Rr (Rz's turn comes
 * first), by roll Rr [ex]x (Rx's last), by pitch each entry's own. A
 * landmark's camera coordinates c = Rc' (P - C) move by dRc' (P - C) -
 * Rc' dC: the second part the same for every landmark, kept in v->dc. */
void rl_pose_fit_view_of(const rl_pose_model *md, const double *q, rl_pose_fit_view *v)
{
    double cz = cos(q[2]), sz = sin(q[2]), cy = cos(q[4]), sy = sin(q[4]), cx = cos(q[3]), sx = sin(q[3]);
    double Rr[9], D[9];
    const rl_mount *m = md->mount;
    const double *Rc = v->Rc;
    int a, k;
    rotation_cs(cz, sz, cy, sy, cx, sx, Rr);
    camera_of(md, q, Rr, v->Rc, v->C);
    for (a = 2; a < RL_POSE_NQ; a++) {
        double dC[3];
        if (a == 2) {
            for (k = 0; k < 3; k++) {
                D[k] = -Rr[3 + k];
                D[3 + k] = Rr[k];
                D[6 + k] = 0;
            }
        } else if (a == 3) {
            for (k = 0; k < 9; k += 3) {
                D[k] = 0;
                D[k + 1] = Rr[k + 2];
                D[k + 2] = -Rr[k + 1];
            }
        } else {
            D[0] = -cz * sy;
            D[1] = cz * cy * sx;
            D[2] = cz * cy * cx;
            D[3] = -sz * sy;
            D[4] = sz * cy * sx;
            D[5] = sz * cy * cx;
            D[6] = -cy;
            D[7] = -sy * sx;
            D[8] = -sy * cx;
        }
        rl_pose_fit_mul(D, md->Rm, v->dRc[a]);
        for (k = 0; k < 3; k++)
            dC[k] = D[3 * k] * m->x + D[3 * k + 1] * m->y + D[3 * k + 2] * m->z;
        for (k = 0; k < 3; k++)
            v->dc[a][k] = -(Rc[k] * dC[0] + Rc[3 + k] * dC[1] + Rc[6 + k] * dC[2]);
    }
    for (k = 0; k < 3; k++) { /* x and y move the camera, not its axes */
        v->dc[0][k] = -Rc[k];
        v->dc[1][k] = -Rc[3 + k];
    }
    memset(v->dRc, 0, 2 * sizeof v->dRc[0]);
}

/* What the recognizer measures for the landmark at (X, Y), seen by the
 * camera Rc, C: the centre of its outer edge, which a tilted view puts off
 * the image of its centre by (R^2 / 4) times the plane-to-image map's
 * Laplacian (R the landmark's radius; the mean of the map over the
 * circle, to second order), from the images of four points R away. */
int rl_pose_fit_predict(const rl_pose_model *md, const double *Rc, const double *C, double X, double Y, double Z,
                        double *xn, double *yn)
{
    double dx = X - C[0], dy = Y - C[1], dz = Z - C[2], r = md->radius, sx = 0, sy = 0;
    double f = Rc[0] * dx + Rc[3] * dy + Rc[6] * dz, l = Rc[1] * dx + Rc[4] * dy + Rc[7] * dz,
           u = Rc[2] * dx + Rc[5] * dy + Rc[8] * dz;
    int i;
    if (!(u > 1e-6))
        return 0;
    *xn = l / u;
    *yn = -f / u;
    if (r <= 0)
        return 1;
    for (i = 0; i < 4; i++) {
        /* the map's step of r along x (rows 0, 1 of Rc's columns) or y */
        double s = i & 1 ? -r : r, sf = s * Rc[i < 2 ? 0 : 3], sl = s * Rc[i < 2 ? 1 : 4],
               su = s * Rc[i < 2 ? 2 : 5];
        if (!(u + su > 1e-6))
            return 0;
        sx += (l + sl) / (u + su) - *xn;
        sy += -(f + sf) / (u + su) - *yn;
    }
    *xn += sx / 4;
    *yn += sy / 4;
    return 1;
}

/* rl_pose_fit_predict's arithmetic for the value (the same bits), and
 * beside it the quotients' derivatives: x = l / u moves by (dl - x du) / u.
 * With a radius the prediction is the mean of the four points' images
 * (the centre's own cancels), so its derivative is theirs averaged: the
 * sums over the points that do not depend on the parameter are made once
 * (P, Q; E, F for the points' steps along the map's x and y, whose own
 * derivatives are those of Rc's rows 0 and 1). */
int rl_pose_fit_predict_d(const rl_pose_model *md, const rl_pose_fit_view *v, double X, double Y, double Z,
                          int nq, double *xn, double *yn, double *dxn, double *dyn)
{
    const double *Rc = v->Rc, *C = v->C;
    double dx = X - C[0], dy = Y - C[1], dz = Z - C[2], r = md->radius, sx = 0, sy = 0;
    double f = Rc[0] * dx + Rc[3] * dy + Rc[6] * dz, l = Rc[1] * dx + Rc[4] * dy + Rc[7] * dz,
           u = Rc[2] * dx + Rc[5] * dy + Rc[8] * dz;
    double P = 0, Qx = 0, Qy = 0, E[2] = {0, 0}, Fx[2] = {0, 0}, Fy[2] = {0, 0};
    int i, a;
    if (!(u > 1e-6))
        return 0;
    *xn = l / u;
    *yn = -f / u;
    if (r <= 0) {
        P = 1 / u;
        Qx = *xn * P;
        Qy = *yn * P;
    } else {
        for (i = 0; i < 4; i++) {
            int row = i < 2 ? 0 : 3;
            double s = i & 1 ? -r : r, sf = s * Rc[row], sl = s * Rc[row + 1], su = s * Rc[row + 2], xi, yi, iu;
            if (!(u + su > 1e-6))
                return 0;
            xi = (l + sl) / (u + su);
            yi = -(f + sf) / (u + su);
            sx += xi - *xn;
            sy += yi - *yn;
            iu = 0.25 / (u + su);
            P += iu;
            Qx += xi * iu;
            Qy += yi * iu;
            E[i >> 1] += s * iu;
            Fx[i >> 1] += s * xi * iu;
            Fy[i >> 1] += s * yi * iu;
        }
        *xn += sx / 4;
        *yn += sy / 4;
    }
    for (a = 0; a < nq; a++) {
        const double *D = v->dRc[a];
        double df = v->dc[a][0], dl = v->dc[a][1], du = v->dc[a][2];
        if (a < 2) { /* x, y: the camera moves, its axes stay */
            dxn[a] = dl * P - du * Qx;
            dyn[a] = -df * P - du * Qy;
            continue;
        }
        df += D[0] * dx + D[3] * dy + D[6] * dz;
        dl += D[1] * dx + D[4] * dy + D[7] * dz;
        du += D[2] * dx + D[5] * dy + D[8] * dz;
        dxn[a] = dl * P - du * Qx + D[1] * E[0] - D[2] * Fx[0] + D[4] * E[1] - D[5] * Fx[1];
        dyn[a] = -df * P - du * Qy - D[0] * E[0] - D[2] * Fy[0] - D[3] * E[1] - D[5] * Fy[1];
    }
    return 1;
}

/* Solve A x = b (n x n, row-major) by elimination with partial pivoting;
 * A and b are overwritten. 0 if singular. */
static int solve(double *A, double *b, int n)
{
    int i, j, k;
    for (k = 0; k < n; k++) {
        int p = k;
        for (i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > fabs(A[p * n + k]))
                p = i;
        if (!(fabs(A[p * n + k]) > 1e-300))
            return 0;
        if (p != k) {
            for (j = 0; j < n; j++) {
                double t = A[k * n + j];
                A[k * n + j] = A[p * n + j];
                A[p * n + j] = t;
            }
            {
                double t = b[k];
                b[k] = b[p];
                b[p] = t;
            }
        }
        for (i = k + 1; i < n; i++) {
            double f = A[i * n + k] / A[k * n + k];
            for (j = k; j < n; j++)
                A[i * n + j] -= f * A[k * n + j];
            b[i] -= f * b[k];
        }
    }
    for (i = n - 1; i >= 0; i--) {
        for (j = i + 1; j < n; j++)
            b[i] -= A[i * n + j] * b[j];
        b[i] /= A[i * n + i];
    }
    return 1;
}

/* The normal matrix J'J and gradient J'r of the free parameters (the
 * first nf of q), J analytic (rl_pose_fit_predict_d): two rows a
 * landmark, its image residual in units of its noise, and two for the
 * tilt prior; chi2 of the image rows. With reweight, each landmark's
 * Huber weight from its residual here first. 0 if a landmark fell
 * behind. */
static int normal_equations(const rl_pose_model *md, rl_pose_pt *pt, int m, const double *q, int nf,
                            int reweight, double *A, double *g, double *chi2)
{
    rl_pose_fit_view v;
    int i, a, b;
    rl_pose_fit_view_of(md, q, &v);
    memset(A, 0, sizeof *A * (size_t)(nf * nf));
    memset(g, 0, sizeof *g * (size_t)nf);
    *chi2 = 0;
    for (i = 0; i < m; i++) {
        double xn, yn, jx[RL_POSE_NQ], jy[RL_POSE_NQ], rx, ry, k;
        if (!rl_pose_fit_predict_d(md, &v, pt[i].mx, pt[i].my, pt[i].mz, nf, &xn, &yn, jx, jy))
            return 0;
        if (reweight)
            pt[i].w = 1;
        rx = (pt[i].xn - xn) / (md->sn * pt[i].noise) * pt[i].w;
        ry = (pt[i].yn - yn) / (md->sn * pt[i].noise) * pt[i].w;
        if (reweight) {
            /* Huber weights from these residuals: a centre more than two
             * of its sigmas off counts less (the residuals are linear in
             * them) */
            double e = sqrt(rx * rx + ry * ry);
            pt[i].w = e > 2.0 ? sqrt(2.0 / e) : 1.0;
            rx *= pt[i].w;
            ry *= pt[i].w;
        }
        *chi2 += rx * rx;
        *chi2 += ry * ry;
        k = pt[i].w / (md->sn * pt[i].noise);
        for (a = 0; a < nf; a++) {
            jx[a] *= k; /* d(prediction)/dq, weighted */
            jy[a] *= k;
            g[a] += jx[a] * rx + jy[a] * ry;
            for (b = 0; b <= a; b++)
                A[a * nf + b] += jx[a] * jx[b] + jy[a] * jy[b];
        }
    }
    for (a = 3; a < nf; a++) { /* the prior's rows: residual -q / sigma, its derivative 1 / sigma */
        double p2 = md->prior[a - 3] * md->prior[a - 3];
        A[a * nf + a] += 1 / p2;
        g[a] += -q[a] / p2;
    }
    for (a = 0; a < nf; a++)
        for (b = a + 1; b < nf; b++)
            A[a * nf + b] = A[b * nf + a];
    return 1;
}

/* the held parameter k's prior variance: the tilt's roll (3), pitch (4) */
#define P(k) ((k) >= 3 ? prior[(k)-3] * prior[(k)-3] : 0.0)

/* The covariance of all five parameters at q into cov: the free ones'
 * (the first nf) from the centres, with those held at their value
 * (nf < 5) as unsure as the prior says, "considered": the free ones
 * moved by as much as the held ones can be wrong (S = -A_ff^-1 A_fh, cov
 * += S P S'). A held tilt the centres could have measured does not make
 * the free ones surer: a level fit is off by as much as the robot leans
 * (the demo's level frames: 3-7 mm off with sigmas of 0.1-0.3 mm when the
 * tilt's prior was counted as a measurement). A the normal matrix of all
 * five (the prior only on the held ones' diagonal), factor the centres'
 * noise factor (on A_ff^-1 only: S is the same at any noise). 0 if
 * singular. */
static int considered(const double *A, int nf, const double *prior, double factor, double *cov)
{
    double Aff[RL_POSE_NQ * RL_POSE_NQ], S[RL_POSE_NQ][RL_POSE_NQ], e[RL_POSE_NQ];
    int a, b, j, n = RL_POSE_NQ;
    for (b = 0; b < nf; b++) { /* A_ff^-1, column by column */
        for (a = 0; a < nf; a++)
            memcpy(&Aff[a * nf], &A[a * n], (size_t)nf * sizeof *A);
        for (a = 0; a < nf; a++)
            e[a] = a == b;
        if (!solve(Aff, e, nf))
            return 0;
        for (a = 0; a < nf; a++)
            cov[a * n + b] = e[a];
    }
    for (a = 0; a < nf; a++)
        for (j = nf; j < n; j++) {
            S[a][j] = 0;
            for (b = 0; b < nf; b++)
                S[a][j] -= cov[a * n + b] * A[b * n + j];
        }
    for (a = 0; a < n; a++)
        for (b = 0; b < n; b++) {
            double sum = a < nf && b < nf ? factor * cov[a * n + b] : (a == b ? P(a) : 0);
            for (j = nf; j < n; j++)
                sum += (a < nf ? S[a][j] : a == j) * (b < nf ? S[b][j] : b == j) * P(j) * (a < nf || b < nf);
            cov[a * n + b] = sum;
        }
    return 1;
}
#undef P

/* Gauss-Newton on the first nf parameters of q; the covariance of all
 * five (the held ones through the prior, considered) into cov, the
 * centres' noise pooled with what their residuals show. 0 if it failed. */
int rl_pose_fit_solve(const rl_pose_model *md, rl_pose_pt *pt, int m, int nf, double *q, double *cov, double *chi2)
{
    double A[RL_POSE_NQ * RL_POSE_NQ], g[RL_POSE_NQ], factor;
    int it, a, b, dof;
    for (it = 0; it < 16; it++) {
        double step = 0;
        /* robust weights from the third step on, once near the answer */
        if (!normal_equations(md, pt, m, q, nf, it >= 2, A, g, chi2) || !solve(A, g, nf))
            return 0;
        for (a = 0; a < nf; a++) {
            q[a] += g[a];
            step += g[a] * g[a];
        }
        if (!(fabs(q[3]) < 0.5 && fabs(q[4]) < 0.5) || !isfinite(step))
            return 0;
        if (step < 1e-18 && it >= 3)
            break;
    }
    /* the residuals say how noisy the centres were: pooled with the
     * expected noise (three observations' worth) into a factor on the
     * covariance; a held tilt's prior is what the robot may lean whatever
     * the centres show, so a level fit scales only the centres' part */
    if (!normal_equations(md, pt, m, q, RL_POSE_NQ, 0, A, g, chi2))
        return 0;
    dof = 2 * m - nf;
    factor = dof > 0 ? (*chi2 + 3.0) / (dof + 3.0) : 1.0;
    if (nf < RL_POSE_NQ)
        return considered(A, nf, md->prior, factor, cov);
    for (b = 0; b < RL_POSE_NQ; b++) { /* (J'J)^-1, the prior bounding the tilt */
        double Ac[RL_POSE_NQ * RL_POSE_NQ], e[RL_POSE_NQ];
        memcpy(Ac, A, sizeof Ac);
        for (a = 0; a < RL_POSE_NQ; a++)
            e[a] = a == b;
        if (!solve(Ac, e, RL_POSE_NQ))
            return 0;
        for (a = 0; a < RL_POSE_NQ; a++)
            cov[a * RL_POSE_NQ + b] = e[a] * factor;
    }
    return 1;
}

