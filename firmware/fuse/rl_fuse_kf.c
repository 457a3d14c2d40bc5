/* rl_fuse_kf: see rl_fuse_kf.h. The motion model: the odometry's
 * increment (forward distance d, turn a) is the truth's divided by the
 * scales, d_true = s d, a_true = g a (a wheel diameter off scales both,
 * a track width off scales the turn only); the chord runs along the mid
 * heading, exact for an arc of constant curvature. */
#include <math.h>
#include <string.h>
#include "rl_fuse_kf.h"

#define N RL_FUSE_N

double rl_fuse_kf_wrap(double a)
{
    return atan2(sin(a), cos(a));
}

rl_fuse_kf_incr rl_fuse_kf_increment(const double *a, const double *b)
{
    rl_fuse_kf_incr d;
    double dx = b[0] - a[0], dy = b[1] - a[1], hm;
    d.turn = rl_fuse_kf_wrap(b[2] - a[2]);
    hm = a[2] + d.turn / 2;
    d.fwd = cos(hm) * dx + sin(hm) * dy;
    d.lat = -sin(hm) * dx + cos(hm) * dy;
    return d;
}

void rl_fuse_kf_advance(const double *o, rl_fuse_kf_incr d, double q, double *out)
{
    double hm = o[2] + q * d.turn / 2;
    out[0] = o[0] + q * (d.fwd * cos(hm) - d.lat * sin(hm));
    out[1] = o[1] + q * (d.fwd * sin(hm) + d.lat * cos(hm));
    out[2] = rl_fuse_kf_wrap(o[2] + q * d.turn);
}

void rl_fuse_kf_start(rl_fuse_kf_state *s, const double *z, double R[3][3], double scale,
                      double scale_var, double turn, double turn_var)
{
    int i, j;
    memset(s, 0, sizeof *s);
    for (i = 0; i < 3; i++) {
        s->m[i] = z[i];
        for (j = 0; j < 3; j++)
            s->P[i][j] = R[i][j];
    }
    s->m[3] = scale;
    s->m[4] = turn;
    s->P[3][3] = scale_var;
    s->P[4][4] = turn_var;
}

/* P := F P F' + G Q G' (G: N x 2) */
static void spread(double P[N][N], double F[N][N], double G[N][2], double Q[2][2])
{
    double T[N][N];
    int i, j, k;
    for (i = 0; i < N; i++)
        for (j = 0; j < N; j++) {
            T[i][j] = 0;
            for (k = 0; k < N; k++)
                T[i][j] += F[i][k] * P[k][j];
        }
    for (i = 0; i < N; i++)
        for (j = 0; j < N; j++) {
            double v = 0;
            for (k = 0; k < N; k++)
                v += T[i][k] * F[j][k];
            for (k = 0; k < 2; k++)
                v += G[i][k] * (Q[k][0] * G[j][0] + Q[k][1] * G[j][1]);
            P[i][j] = v;
        }
}

/* The covariance grows by the Jacobian, by the wheels' noise (each wheel's
 * variance wheel_noise^2 per metre it rolled, taken into the odometry's
 * distance and turn) and by the scales' drift. */
void rl_fuse_kf_propagate_part(rl_fuse_kf_state *s, rl_fuse_kf_incr d, double q,
                               const rl_fuse_config *cfg)
{
    double F[N][N], G[N][2], Q[2][2];
    double fwd = q * d.fwd, lat = q * d.lat, turn = q * d.turn;
    double sc = s->m[3], g = s->m[4], b = cfg->track;
    double hm = s->m[2] + g * turn / 2, c = cos(hm), sn = sin(hm);
    double dx = sc * (fwd * c - lat * sn), dy = sc * (fwd * sn + lat * c);
    double wr = fabs(fwd + turn * b / 2), wl = fabs(fwd - turn * b / 2);
    double w2 = cfg->wheel_noise * cfg->wheel_noise, drift = cfg->scale_drift * cfg->scale_drift;
    int i;
    memset(F, 0, sizeof F);
    memset(G, 0, sizeof G);
    for (i = 0; i < N; i++)
        F[i][i] = 1;
    F[0][2] = -dy;
    F[1][2] = dx;
    F[0][3] = fwd * c - lat * sn;
    F[1][3] = fwd * sn + lat * c;
    F[0][4] = -dy * turn / 2;
    F[1][4] = dx * turn / 2;
    F[2][4] = turn;
    Q[0][0] = w2 * (wr + wl) / 4;
    Q[1][1] = w2 * (wr + wl) / (b * b);
    Q[0][1] = Q[1][0] = w2 * (wr - wl) / (2 * b);
    G[0][0] = sc * c;
    G[1][0] = sc * sn;
    G[0][1] = -dy * g / 2;
    G[1][1] = dx * g / 2;
    G[2][1] = g;
    s->m[0] += dx;
    s->m[1] += dy;
    s->m[2] = rl_fuse_kf_wrap(s->m[2] + g * turn);
    spread(s->P, F, G, Q);
    s->P[3][3] += drift * fabs(sc * fwd);
    s->P[4][4] += drift * fabs(sc * fwd);
}

void rl_fuse_kf_propagate(rl_fuse_kf_state *s, rl_fuse_kf_incr d, const rl_fuse_config *cfg)
{
    rl_fuse_kf_propagate_part(s, d, 1.0, cfg);
}

/* inverse of a symmetric 3x3 matrix; 0 when singular */
static int inv3(double A[3][3], double B[3][3])
{
    double det;
    int i, j;
    B[0][0] = A[1][1] * A[2][2] - A[1][2] * A[2][1];
    B[0][1] = A[0][2] * A[2][1] - A[0][1] * A[2][2];
    B[0][2] = A[0][1] * A[1][2] - A[0][2] * A[1][1];
    B[1][0] = A[1][2] * A[2][0] - A[1][0] * A[2][2];
    B[1][1] = A[0][0] * A[2][2] - A[0][2] * A[2][0];
    B[1][2] = A[0][2] * A[1][0] - A[0][0] * A[1][2];
    B[2][0] = A[1][0] * A[2][1] - A[1][1] * A[2][0];
    B[2][1] = A[0][1] * A[2][0] - A[0][0] * A[2][1];
    B[2][2] = A[0][0] * A[1][1] - A[0][1] * A[1][0];
    det = A[0][0] * B[0][0] + A[0][1] * B[1][0] + A[0][2] * B[2][0];
    if (!(fabs(det) > 0))
        return 0;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            B[i][j] /= det;
    return 1;
}

/* innovation nu = z - pose (yaw wrapped) and the inverse of its covariance */
static int innovation(const rl_fuse_kf_state *s, const double *z, double R[3][3], double *nu,
                      double Si[3][3])
{
    double S[3][3];
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            S[i][j] = s->P[i][j] + R[i][j];
    nu[0] = z[0] - s->m[0];
    nu[1] = z[1] - s->m[1];
    nu[2] = rl_fuse_kf_wrap(z[2] - s->m[2]);
    return inv3(S, Si);
}

double rl_fuse_kf_distance(const rl_fuse_kf_state *s, const double *z, double R[3][3])
{
    double nu[3], Si[3][3], d = 0;
    int i, j;
    if (!innovation(s, z, R, nu, Si))
        return HUGE_VAL;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            d += nu[i] * Si[i][j] * nu[j];
    return d;
}

void rl_fuse_kf_update(rl_fuse_kf_state *s, const double *z, double R[3][3])
{
    double nu[3], Si[3][3], K[N][3], A[N][N], T[N][N];
    int i, j, k;
    if (!innovation(s, z, R, nu, Si))
        return;
    for (i = 0; i < N; i++) /* K = P H' S^-1, H = [I 0] */
        for (j = 0; j < 3; j++) {
            K[i][j] = 0;
            for (k = 0; k < 3; k++)
                K[i][j] += s->P[i][k] * Si[k][j];
        }
    for (i = 0; i < N; i++) {
        for (j = 0; j < 3; j++)
            s->m[i] += K[i][j] * nu[j];
        for (j = 0; j < N; j++) /* A = I - K H */
            A[i][j] = (i == j) - (j < 3 ? K[i][j] : 0);
    }
    s->m[2] = rl_fuse_kf_wrap(s->m[2]);
    for (i = 0; i < N; i++) /* P = A P A' + K R K' */
        for (j = 0; j < N; j++) {
            T[i][j] = 0;
            for (k = 0; k < N; k++)
                T[i][j] += A[i][k] * s->P[k][j];
        }
    for (i = 0; i < N; i++)
        for (j = 0; j < N; j++) {
            double v = 0;
            int l;
            for (k = 0; k < N; k++)
                v += T[i][k] * A[j][k];
            for (k = 0; k < 3; k++)
                for (l = 0; l < 3; l++)
                    v += K[i][k] * R[k][l] * K[j][l];
            s->P[i][j] = v;
        }
    for (i = 0; i < N; i++) /* symmetric to the last bit */
        for (j = 0; j < i; j++)
            s->P[i][j] = s->P[j][i] = (s->P[i][j] + s->P[j][i]) / 2;
}
