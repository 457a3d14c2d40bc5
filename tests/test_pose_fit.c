/* The pose fit's derivatives (rl_pose_fit.h) against central differences
 * worked out here from the prediction itself (rl_pose_fit_camera and
 * rl_pose_fit_predict): on drawn mounts (offset, turned, tilted), fields
 * of view, poses (tilted robots), ceilings, landmark radii and sets of
 * landmarks at their own heights. Then the fit built on them: where it
 * stops, the misfit's gradient (by central differences of the misfit)
 * must be nil, and the tilted fit's covariance must be the inverse of
 * the normal matrix those differences give. */
#include "rl_test.h"
#include <math.h>
#include "rl_pose_fit.h"

#define CASES 400
#define MAXN 16
#define STEP_LEFT 1e-6 /* m, rad: what the fit may stop short of its minimum */

static unsigned long long seed = 88172645463325252ULL;

/* xorshift: a uniform draw in [lo, hi) */
static double draw(double lo, double hi)
{
    seed ^= seed << 13;
    seed ^= seed >> 7;
    seed ^= seed << 17;
    return lo + (hi - lo) * (double)(seed >> 11) / 9007199254740992.0;
}

static double gauss(void)
{
    double a = draw(1e-12, 1), b = draw(0, 1);
    return sqrt(-2 * log(a)) * cos(6.283185307179586 * b);
}

typedef struct {
    rl_mount mount;
    rl_pose_model md;
    double q[RL_POSE_NQ];
    double X[MAXN], Y[MAXN], Z[MAXN];
    int n;
} scene;

/* A camera, a robot's pose and up to MAXN landmarks in view: each drawn
 * in the image (within a field of view of 50 to 150 degrees) and put on
 * the ray at its own height, 0-0.6 m under a ceiling 2.2-4.5 m up. */
static void draw_scene(scene *s)
{
    double height = draw(2.2, 4.5), half = tan(draw(25, 75) * 3.141592653589793 / 180), Rc[9], C[3];
    int tries;
    memset(s, 0, sizeof *s);
    s->mount.x = draw(-0.3, 0.3);
    s->mount.y = draw(-0.3, 0.3);
    s->mount.z = draw(0.1, 1.2);
    s->mount.yaw = draw(-3.14, 3.14);
    s->mount.roll = draw(-0.25, 0.25);
    s->mount.pitch = draw(-0.25, 0.25);
    s->mount.rocking = RL_POSE_TILT_PRIOR;
    rl_pose_fit_model(&s->md, &s->mount, height, draw(0, 1) < 0.2 ? 0 : draw(0.03, 0.2));
    s->md.sn = RL_POSE_PIXEL_SIGMA / draw(200, 900);
    s->md.prior[0] = draw(0.001, 0.1);
    s->md.prior[1] = draw(0.001, 0.1);
    s->q[0] = draw(-20, 20);
    s->q[1] = draw(-20, 20);
    s->q[2] = draw(-3.14, 3.14);
    s->q[3] = draw(-0.2, 0.2);
    s->q[4] = draw(-0.2, 0.2);
    rl_pose_fit_camera(&s->md, s->q, Rc, C);
    s->n = 0;
    for (tries = 0; tries < 200 && s->n < 2 + (int)draw(0, MAXN - 1); tries++) {
        double xn = draw(-half, half), yn = draw(-half, half), Z = height - (draw(0, 1) < 0.3 ? draw(0, 0.6) : 0);
        double c[3] = {-yn, xn, 1}, d[3], t;
        int k;
        for (k = 0; k < 3; k++)
            d[k] = Rc[3 * k] * c[0] + Rc[3 * k + 1] * c[1] + Rc[3 * k + 2] * c[2];
        if (!(d[2] > 0.2) || !((Z - C[2]) > 0.4))
            continue;
        t = (Z - C[2]) / d[2];
        s->X[s->n] = C[0] + t * d[0];
        s->Y[s->n] = C[1] + t * d[1];
        s->Z[s->n] = Z;
        s->n++;
    }
}

/* The prediction at q with q[a] moved by h. */
static int predict_at(const scene *s, const double *q, int a, double h, int k, double *xn, double *yn)
{
    double qq[RL_POSE_NQ], Rc[9], C[3];
    memcpy(qq, q, sizeof qq);
    qq[a] += h;
    rl_pose_fit_camera(&s->md, qq, Rc, C);
    return rl_pose_fit_predict(&s->md, Rc, C, s->X[k], s->Y[k], s->Z[k], xn, yn);
}

/* d(prediction)/dq[a] by central differences, and by a second step of
 * twice the size: their difference says how far to trust them. */
static int central(const scene *s, const double *q, int a, int k, double *dx, double *dy, double *tol)
{
    const double h = 1e-5;
    double xp, yp, xm, ym, x2p, y2p, x2m, y2m;
    if (!predict_at(s, q, a, h, k, &xp, &yp) || !predict_at(s, q, a, -h, k, &xm, &ym) ||
        !predict_at(s, q, a, 2 * h, k, &x2p, &y2p) || !predict_at(s, q, a, -2 * h, k, &x2m, &y2m))
        return 0;
    *dx = (xp - xm) / (2 * h);
    *dy = (yp - ym) / (2 * h);
    /* the truncation error of the h step is a quarter of the 2h one's;
     * their difference bounds both, plus rounding */
    *tol = 2 * fmax(fabs((x2p - x2m) / (4 * h) - *dx), fabs((y2p - y2m) / (4 * h) - *dy)) + 1e-8;
    return 1;
}

/* Every derivative of every landmark's prediction, in every drawn
 * scene, against central differences; the value the same bits as
 * rl_pose_fit_predict's. */
static void test_jacobian(void **state)
{
    int c, k, a, checked = 0;
    double worst = 0, largest = 0;
    (void)state;
    seed = 88172645463325252ULL;
    for (c = 0; c < CASES; c++) {
        scene s;
        rl_pose_fit_view v;
        double Rc[9], C[3];
        draw_scene(&s);
        rl_pose_fit_view_of(&s.md, s.q, &v);
        rl_pose_fit_camera(&s.md, s.q, Rc, C);
        assert_memory_equal(Rc, v.Rc, sizeof Rc);
        assert_memory_equal(C, v.C, sizeof C);
        for (k = 0; k < s.n; k++) {
            double xn, yn, x0, y0, jx[RL_POSE_NQ], jy[RL_POSE_NQ];
            assert_true(rl_pose_fit_predict_d(&s.md, &v, s.X[k], s.Y[k], s.Z[k], RL_POSE_NQ, &xn, &yn, jx, jy));
            assert_true(rl_pose_fit_predict(&s.md, Rc, C, s.X[k], s.Y[k], s.Z[k], &x0, &y0));
            assert_true(xn == x0 && yn == y0);
            for (a = 0; a < RL_POSE_NQ; a++) {
                double dx, dy, tol, e;
                if (!central(&s, s.q, a, k, &dx, &dy, &tol))
                    continue;
                e = fmax(fabs(jx[a] - dx), fabs(jy[a] - dy));
                largest = fmax(largest, fmax(fabs(dx), fabs(dy)));
                worst = fmax(worst, e / (tol + 1e-6 * fmax(fabs(dx), fabs(dy))));
                if (e > tol + 1e-6 * fmax(fabs(dx), fabs(dy)))
                    fail_msg("scene %d landmark %d: d(x, y)/dq[%d] (%.9g, %.9g), central differences (%.9g, %.9g) "
                             "+- %.2g (radius %g, mount yaw %g roll %g pitch %g, q %g %g %g %g %g)",
                             c, k, a, jx[a], jy[a], dx, dy, tol, s.md.radius, s.mount.yaw, s.mount.roll,
                             s.mount.pitch, s.q[0], s.q[1], s.q[2], s.q[3], s.q[4]);
                checked++;
            }
        }
    }
    printf("  %d derivatives in %d scenes (the largest %.3g): at most %.3f of their tolerance off central "
           "differences\n", checked, CASES, largest, worst);
    assert_true(checked > 10 * CASES);
}

/* The misfit the fit minimizes (the weights it ended with): the image
 * residuals in units of their noise, and the tilt's prior. */
static double misfit(const scene *s, const rl_pose_pt *pt, const double *q)
{
    double Rc[9], C[3], F = 0;
    int k;
    rl_pose_fit_camera(&s->md, q, Rc, C);
    for (k = 0; k < s->n; k++) {
        double xn, yn, e = s->md.sn * pt[k].noise;
        if (!rl_pose_fit_predict(&s->md, Rc, C, pt[k].mx, pt[k].my, pt[k].mz, &xn, &yn))
            return NAN;
        F += pt[k].w * pt[k].w * ((pt[k].xn - xn) * (pt[k].xn - xn) + (pt[k].yn - yn) * (pt[k].yn - yn)) / (e * e);
    }
    return F + q[3] * q[3] / (s->md.prior[0] * s->md.prior[0]) + q[4] * q[4] / (s->md.prior[1] * s->md.prior[1]);
}

/* The normal matrix of the fit at q by central differences: J's rows the
 * weighted image residuals' derivatives, and the prior's two. */
static int normal_by_differences(const scene *s, const rl_pose_pt *pt, const double *q, double *A)
{
    double J[2 * MAXN + 2][RL_POSE_NQ], tol;
    int k, a, b, i;
    memset(J, 0, sizeof J);
    for (k = 0; k < s->n; k++)
        for (a = 0; a < RL_POSE_NQ; a++) {
            double e = s->md.sn * pt[k].noise;
            if (!central(s, q, a, k, &J[2 * k][a], &J[2 * k + 1][a], &tol))
                return 0;
            J[2 * k][a] *= pt[k].w / e;
            J[2 * k + 1][a] *= pt[k].w / e;
        }
    J[2 * s->n][3] = 1 / s->md.prior[0];
    J[2 * s->n + 1][4] = 1 / s->md.prior[1];
    for (a = 0; a < RL_POSE_NQ; a++)
        for (b = 0; b < RL_POSE_NQ; b++) {
            A[a * RL_POSE_NQ + b] = 0;
            for (i = 0; i < 2 * s->n + 2; i++)
                A[a * RL_POSE_NQ + b] += J[i][a] * J[i][b];
        }
    return 1;
}

/* The fit's robust weights are the ones its residuals at q give (Huber's
 * at two sigmas, rl_pose_fit.c): it stopped where its steps did, not
 * on their count, so q is the minimum of the misfit with them. */
static int weights_settled(const scene *s, const rl_pose_pt *pt, const double *q)
{
    double Rc[9], C[3];
    int k;
    rl_pose_fit_camera(&s->md, q, Rc, C);
    for (k = 0; k < s->n; k++) {
        double xn, yn, e, w;
        if (!rl_pose_fit_predict(&s->md, Rc, C, pt[k].mx, pt[k].my, pt[k].mz, &xn, &yn))
            return 0;
        e = hypot(pt[k].xn - xn, pt[k].yn - yn) / (s->md.sn * pt[k].noise);
        w = e > 2.0 ? sqrt(2.0 / e) : 1.0;
        if (fabs(w - pt[k].w) > 1e-6)
            return 0;
    }
    return 1;
}

/* M x = b by elimination (M symmetric positive definite: no pivoting);
 * x into b. */
static void eliminate(double *M, double *b, int n)
{
    int i, j, k;
    for (k = 0; k < n; k++)
        for (i = k + 1; i < n; i++) {
            double f = M[i * n + k] / M[k * n + k];
            for (j = k; j < n; j++)
                M[i * n + j] -= f * M[k * n + j];
            b[i] -= f * b[k];
        }
    for (i = n - 1; i >= 0; i--) {
        for (j = i + 1; j < n; j++)
            b[i] -= M[i * n + j] * b[j];
        b[i] /= M[i * n + i];
    }
}

/* Drawn scenes, their centres moved by noise (one in five a centre far
 * off: the robust weights at work), fitted from a start 5-20 cm and a
 * few degrees away, level (3) and tilted (5): where the fit stops, the
 * misfit's gradient by central differences is nil (the Gauss-Newton step
 * it asks is under a micrometre), and the tilted fit's covariance times
 * the normal matrix of central differences is the factor the residuals
 * give times the identity. */
static void test_fit_stops_at_the_minimum(void **state)
{
    int c, nf, fits = 0, unsettled = 0;
    double worst_step = 0, worst_cov = 0;
    (void)state;
    seed = 88172645463325252ULL;
    for (c = 0; c < CASES; c++)
        for (nf = 3; nf <= RL_POSE_NQ; nf += 2) {
            scene s;
            rl_pose_pt pt[MAXN];
            double q[RL_POSE_NQ], cov[RL_POSE_NQ * RL_POSE_NQ], chi2, Rc[9], C[3], grad[RL_POSE_NQ], A[25];
            double Fp, Fm, h = 1e-7, step = 0;
            int k, a, b;
            draw_scene(&s);
            if (s.n < 3)
                continue;
            if (nf == 3) /* a level fit of a level robot (one that leans is the tilted fit's) */
                s.q[3] = s.q[4] = 0;
            rl_pose_fit_camera(&s.md, s.q, Rc, C);
            for (k = 0; k < s.n; k++) {
                memset(&pt[k], 0, sizeof pt[k]);
                assert_true(rl_pose_fit_predict(&s.md, Rc, C, s.X[k], s.Y[k], s.Z[k], &pt[k].xn, &pt[k].yn));
                pt[k].noise = draw(0, 1) < 0.2 ? 4.0 : 1.0;
                pt[k].xn += s.md.sn * pt[k].noise * (draw(0, 1) < 0.2 ? 8 : 1) * gauss();
                pt[k].yn += s.md.sn * pt[k].noise * gauss();
                pt[k].mx = s.X[k];
                pt[k].my = s.Y[k];
                pt[k].mz = s.Z[k];
                pt[k].w = 1;
            }
            memcpy(q, s.q, sizeof q);
            q[0] += draw(-0.2, 0.2);
            q[1] += draw(-0.2, 0.2);
            q[2] += draw(-0.05, 0.05);
            if (nf == 3)
                q[3] = q[4] = 0;
            if (!rl_pose_fit_solve(&s.md, pt, s.n, nf, q, cov, &chi2))
                continue;
            if (!weights_settled(&s, pt, q)) {
                unsettled++; /* stopped by its count of steps, not at a minimum */
                continue;
            }
            fits++;
            for (a = 0; a < nf; a++) {
                double qq[RL_POSE_NQ];
                memcpy(qq, q, sizeof qq);
                qq[a] += h;
                Fp = misfit(&s, pt, qq);
                qq[a] -= 2 * h;
                Fm = misfit(&s, pt, qq);
                grad[a] = (Fp - Fm) / (2 * h) / 2; /* J'r */
            }
            if (!normal_by_differences(&s, pt, q, A))
                continue;
            {
                /* the step Gauss-Newton would still take: A_ff x = J'r */
                double M[25], x[RL_POSE_NQ];
                for (a = 0; a < nf; a++) {
                    for (b = 0; b < nf; b++)
                        M[a * nf + b] = A[a * RL_POSE_NQ + b];
                    x[a] = -grad[a];
                }
                eliminate(M, x, nf);
                for (a = 0; a < nf; a++)
                    step = fmax(step, fabs(x[a]));
            }
            worst_step = fmax(worst_step, step);
            if (getenv("PF_DEBUG"))
                printf("c%d nf%d n%d step %.3g\n", c, nf, s.n, step);
            if (step > STEP_LEFT)
                fail_msg("scene %d, %d parameters: the fit stopped %.3g from the misfit's minimum", c, nf, step);
            if (nf == RL_POSE_NQ) {
                double factor = (chi2 + 3.0) / (2 * s.n - nf + 3.0);
                for (a = 0; a < nf; a++)
                    for (b = 0; b < nf; b++) {
                        double e = 0;
                        for (k = 0; k < nf; k++)
                            e += cov[a * nf + k] * A[k * nf + b];
                        e = fabs(e / factor - (a == b));
                        worst_cov = fmax(worst_cov, e);
                        if (e > 1e-4)
                            fail_msg("scene %d: covariance x normal matrix [%d][%d] off the identity by %.3g", c, a,
                                     b, e);
                    }
            }
        }
    printf("  %d fits (%d more stopped before their weights settled): the step left at most %.3g, the covariance's "
           "product with the differences' normal matrix at most %.3g off the identity\n", fits, unsettled, worst_step,
           worst_cov);
    assert_true(fits > CASES && unsettled < fits / 4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_jacobian),
        cmocka_unit_test(test_fit_stops_at_the_minimum),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
