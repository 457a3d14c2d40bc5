// Localization against OpenCV: undistortion and projection against
// cv::undistortPoints / cv::projectPoints (0.01 px), the pose against
// cv::solvePnP on the same points, and the pose solver's own contract.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>
#include <opencv2/calib3d.hpp>
#include <fstream>
#include <opencv2/core.hpp>
extern "C" {
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>
#include "rl_calib.h"
#include "rl_pose.h"
}

static rl_calib make_cam(int model)
{
    rl_calib c;
    rl_calib_defaults(&c, 640, 480, 70 * M_PI / 180);
    c.fx = 457.3;
    c.fy = 458.1;
    c.cx = 322.4;
    c.cy = 237.9;
    c.model = (rl_dist_model)model;
    double k5[5] = {-0.12, 0.08, 0.0004, -0.0003, -0.01};
    double k8[8] = {0.35, -0.2, 0.0006, -0.0004, 0.05, 0.47, -0.15, 0.04};
    double k12[12] = {-0.1, 0.05, 0.0005, -0.0002, -0.01, 0.02, 0.01, 0.001, 0.002, -0.001, -0.0015, 0.0008};
    double kf[4] = {0.08, -0.03, 0.01, -0.002};
    for (int i = 0; i < RL_CALIB_MAX_COEFFS; i++)
        c.k[i] = model == RL_DIST_RATIONAL ? (i < 8 ? k8[i] : 0)
                 : model == RL_DIST_RATIONAL + 4 ? k12[i]
                 : model == RL_DIST_PLUMB_BOB && i < 5 ? k5[i]
                 : model == RL_DIST_FISHEYE && i < 4 ? kf[i] : 0;
    if (model == RL_DIST_RATIONAL + 4) // the thin-prism lens: rational, 12 coefficients
        c.model = RL_DIST_RATIONAL;
    return c;
}

static int n_coeffs(const rl_calib &c)
{
    return c.model == RL_DIST_FISHEYE ? 4 : c.model == RL_DIST_PLUMB_BOB ? 5 : c.k[8] != 0 ? 12 : 8;
}

static void cv_mats(const rl_calib &c, cv::Mat &K, cv::Mat &D)
{
    K = (cv::Mat_<double>(3, 3) << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
    int n = n_coeffs(c);
    D = cv::Mat(1, n, CV_64F);
    for (int i = 0; i < n; i++)
        D.at<double>(i) = c.k[i];
}

static void test_project_and_undistort_match_opencv(void **)
{
    for (int model : {(int)RL_DIST_PLUMB_BOB, (int)RL_DIST_RATIONAL, (int)RL_DIST_RATIONAL + 4, (int)RL_DIST_FISHEYE}) {
        rl_calib c = make_cam(model);
        cv::Mat K, D;
        cv_mats(c, K, D);
        std::vector<cv::Point3d> obj;
        for (double y = -0.75; y <= 0.75; y += 0.05)
            for (double x = -0.95; x <= 0.95; x += 0.05)
                obj.push_back({x, y, 1.0});
        std::vector<cv::Point2d> img;
        std::vector<cv::Point2d> und;
        if (c.model == RL_DIST_FISHEYE) {
            cv::fisheye::projectPoints(obj, img, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, D);
            cv::fisheye::undistortPoints(img, und, K, D, cv::noArray(), cv::noArray(),
                                         cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-14));
        } else {
            cv::projectPoints(obj, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, D, img);
            cv::undistortPoints(img, und, K, D, cv::noArray(), cv::noArray(),
                                cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-14));
        }
        double worst_p = 0, worst_u = 0;
        for (size_t i = 0; i < obj.size(); i++) {
            double u, v, xn, yn;
            rl_calib_project(&c, obj[i].x, obj[i].y, &u, &v);
            worst_p = std::max(worst_p, std::hypot(u - img[i].x, v - img[i].y));
            rl_calib_unproject(&c, img[i].x, img[i].y, &xn, &yn);
            // compare in pixels: re-scale the normalized difference by fx
            worst_u = std::max(worst_u, c.fx * std::hypot(xn - und[i].x, yn - und[i].y));
            worst_u = std::max(worst_u, c.fx * std::hypot(xn - obj[i].x, yn - obj[i].y));
        }
        if (worst_p > 0.01 || worst_u > 0.01)
            fail_msg("model %d: projection off %.4f px, undistortion off %.4f px", model, worst_p, worst_u);
    }
}

static rl_map site_map(void)
{
    rl_map m;
    std::memset(&m, 0, sizeof m);
    m.family.bits = 5;
    m.diameter = 0.21;
    m.ceiling_height = 2.75;
    for (int j = 0; j < 5; j++)
        for (int i = 0; i < 6; i++) {
            m.lm[m.count].id = m.count + 1;
            m.lm[m.count].x = 0.305 + 0.61 * i;
            m.lm[m.count].y = 0.305 + 0.61 * j;
            m.count++;
        }
    return m;
}

// Rz(yaw) Ry(pitch) Rx(roll), row-major, written out here independently
// of the solver's own.
static void rot(double yaw, double pitch, double roll, double *R)
{
    double cz = std::cos(yaw), sz = std::sin(yaw), cy = std::cos(pitch), sy = std::sin(pitch),
           cx = std::cos(roll), sx = std::sin(roll);
    cv::Matx33d Rz(cz, -sz, 0, sz, cz, 0, 0, 0, 1), Ry(cy, 0, sy, 0, 1, 0, -sy, 0, cy), Rx(1, 0, 0, 0, cx, -sx, 0, sx, cx);
    cv::Matx33d M = Rz * Ry * Rx;
    for (int k = 0; k < 9; k++)
        R[k] = M.val[k];
}

// The image of the map's landmarks from a robot at (x, y, yaw) tilted by
// (roll, pitch) about its footprint: what an edge fit sees (the mean of the
// outer edge's image through the lens), or the centres' images.
static std::vector<rl_detection> observe_tilted(const rl_calib &c, const rl_map &m, const rl_mount &mt, double x,
                                                double y, double yaw, double roll, double pitch, bool edge,
                                                cv::Matx33d *Rcam = nullptr, cv::Vec3d *Ccam = nullptr)
{
    double Rr[9], Rt[9], Ry[9];
    rot(yaw, pitch, roll, Rr);
    rot(0, mt.pitch, mt.roll, Rt);
    rot(mt.yaw, 0, 0, Ry);
    cv::Matx33d R_robot(Rr), R_cam = R_robot * cv::Matx33d(Rt) * cv::Matx33d(Ry);
    cv::Vec3d C = cv::Vec3d(x, y, 0) + R_robot * cv::Vec3d(mt.x, mt.y, mt.z);
    if (Rcam) *Rcam = R_cam;
    if (Ccam) *Ccam = C;
    std::vector<rl_detection> out;
    for (int i = 0; i < m.count; i++) {
        double u = 0, v = 0;
        for (int a = 0; a < 360; a++) {
            double r = edge ? m.diameter / 2 : 0, t = a * M_PI / 180, ue, ve;
            cv::Vec3d d = R_cam.t() * (cv::Vec3d(m.lm[i].x + r * std::cos(t), m.lm[i].y + r * std::sin(t),
                                                  m.ceiling_height) - C);
            rl_calib_project(&c, d[1] / d[2], -d[0] / d[2], &ue, &ve);
            u += ue / 360;
            v += ve / 360;
        }
        if (u < 20 || v < 20 || u > c.width - 20 || v > c.height - 20)
            continue;
        rl_detection det;
        std::memset(&det, 0, sizeof det);
        det.id = m.lm[i].id;
        det.u = u;
        det.v = v;
        det.radius = 25;
        det.complete = 1;
        out.push_back(det);
    }
    return out;
}

// Image positions of the map's landmarks seen from a level robot, with
// pixel noise.
static std::vector<rl_detection> observe(const rl_calib &c, const rl_map &m, const rl_mount &mt,
                                         double x, double y, double yaw, double noise = 0, bool edge = true)
{
    std::mt19937 rng(5);
    std::normal_distribution<double> n(0, noise > 0 ? noise : 1);
    std::vector<rl_detection> out = observe_tilted(c, m, mt, x, y, yaw, 0, 0, edge);
    for (auto &d : out) {
        d.u += noise > 0 ? n(rng) : 0;
        d.v += noise > 0 ? n(rng) : 0;
    }
    return out;
}

// A tilted robot (and a tilted mount): the solved pose is the true one, the
// camera's tilt the true one, and solvePnP on the centres' images puts the
// camera where ringloc does.
static void test_tilted_pose_against_truth_and_solvepnp(void **)
{
    rl_calib c = make_cam(RL_DIST_PLUMB_BOB);
    cv::Mat K, D;
    cv_mats(c, K, D);
    rl_map m = site_map();
    rl_mount mt = {0.12, -0.04, 0.88, 0.3, 0.01, -0.015, RL_POSE_TILT_PRIOR};
    for (double tilt : {0.03, -0.02}) {
        cv::Matx33d Rc;
        cv::Vec3d Cc;
        std::vector<rl_detection> d = observe_tilted(c, m, mt, 1.7, 1.4, 0.4, tilt, -0.7 * tilt, true, &Rc, &Cc);
        std::vector<rl_detection> dc = observe_tilted(c, m, mt, 1.7, 1.4, 0.4, tilt, -0.7 * tilt, false);
        rl_pose p;
        assert_true(d.size() >= 6);
        assert_int_equal(rl_pose_solve(&c, &m, &mt, d.data(), (int)d.size(), NULL, &p), RL_OK);
        assert_true(p.tilt_solved);
        // exact data; the edge offsets are modelled to second order
        if (std::hypot(p.x - 1.7, p.y - 1.4) > 3e-4 || std::fabs(p.yaw - 0.4) > 1e-4)
            fail_msg("tilt %.2f: pose (%.5f, %.5f, %.5f), truth (1.7, 1.4, 0.4)", tilt, p.x, p.y, p.yaw);
        // the camera's tilt from vertical, from its true rotation
        double roll = std::atan2(Rc(2, 1), Rc(2, 2)), pitch = -std::asin(Rc(2, 0));
        assert_true(std::fabs(p.roll - roll) < 3e-4 && std::fabs(p.pitch - pitch) < 3e-4);
        std::vector<cv::Point3d> w;
        std::vector<cv::Point2d> im;
        for (auto &o : dc) {
            int k = rl_map_find(&m, o.id);
            w.push_back({m.lm[k].x, m.lm[k].y, m.ceiling_height});
            im.push_back({o.u, o.v});
        }
        cv::Mat rvec, tvec, R;
        assert_true(cv::solvePnP(w, im, K, D, rvec, tvec, false, cv::SOLVEPNP_ITERATIVE));
        cv::Rodrigues(rvec, R);
        cv::Mat C = -R.t() * tvec;
        double dcv = std::hypot(C.at<double>(0) - p.cam_x, C.at<double>(1) - p.cam_y);
        if (dcv > 0.001 || std::hypot(C.at<double>(0) - Cc[0], C.at<double>(1) - Cc[1]) > 0.001)
            fail_msg("camera: ringloc (%.4f, %.4f), solvePnP (%.4f, %.4f), truth (%.4f, %.4f)", p.cam_x, p.cam_y,
                     C.at<double>(0), C.at<double>(1), Cc[0], Cc[1]);
    }
}

static void test_pose_exact_and_mount(void **)
{
    rl_calib c = make_cam(RL_DIST_PLUMB_BOB);
    rl_map m = site_map();
    rl_mount mt = {0.12, -0.04, 0.88, 0.3, 0, 0, RL_POSE_TILT_PRIOR};
    for (double yaw : {0.0, 1.0, -2.5, 3.1}) {
        std::vector<rl_detection> d = observe(c, m, mt, 1.7, 1.4, yaw);
        rl_pose p;
        assert_true(d.size() >= 4);
        assert_int_equal(rl_pose_solve(&c, &m, &mt, d.data(), (int)d.size(), NULL, &p), RL_OK);
        assert_true(std::hypot(p.x - 1.7, p.y - 1.4) < 1e-6);
        assert_true(std::fabs(std::remainder(p.yaw - yaw, 2 * M_PI)) < 1e-6);
        assert_int_equal(p.used, (int)d.size());
        assert_true(p.residual < 1e-5); // the edge offset is corrected to second order
        assert_int_equal(p.n_dropped, 0);
    }
}

static void test_pose_drops_a_misplaced_landmark(void **)
{
    rl_calib c = make_cam(RL_DIST_PLUMB_BOB);
    rl_map m = site_map(), wrong = m;
    rl_mount mt = {0, 0, 0.88, 0, 0, 0, RL_POSE_TILT_PRIOR};
    std::vector<rl_detection> d = observe(c, m, mt, 1.8, 1.5, 0.4, 0.1);
    int victim = d[2].id;
    wrong.lm[rl_map_find(&wrong, victim)].x += 0.25; // moved since the map was made
    rl_pose p;
    assert_int_equal(rl_pose_solve(&c, &wrong, &mt, d.data(), (int)d.size(), NULL, &p), RL_OK);
    assert_int_equal(p.n_dropped, 1);
    assert_int_equal(p.dropped[0], victim);
    assert_true(std::hypot(p.x - 1.8, p.y - 1.5) < 0.003);
    // unknown ids are counted, not used
    d[0].id = 99;
    assert_int_equal(rl_pose_solve(&c, &m, &mt, d.data(), (int)d.size(), NULL, &p), RL_OK);
    assert_int_equal(p.n_unknown, 1);
}

static void test_pose_too_few(void **)
{
    rl_calib c = make_cam(RL_DIST_NONE);
    rl_map m = site_map();
    rl_mount mt = {0, 0, 0.88, 0, 0, 0, RL_POSE_TILT_PRIOR};
    std::vector<rl_detection> d = observe(c, m, mt, 1.8, 1.5, 0.0);
    rl_pose p;
    assert_int_equal(rl_pose_solve(&c, &m, &mt, d.data(), 1, NULL, &p), RL_ETOOFEW);
    assert_int_equal(rl_pose_solve(&c, &m, &mt, d.data(), 2, NULL, &p), RL_OK); // the paper's case
    assert_true(std::hypot(p.x - 1.8, p.y - 1.5) < 1e-6);
    rl_map bad = m;
    bad.lm[rl_map_find(&bad, d[1].id)].y += 0.5;
    assert_int_equal(rl_pose_solve(&c, &bad, &mt, d.data(), 2, NULL, &p), RL_ETOOFEW);
    assert_int_equal(p.n_dropped, 2);
    mt.z = 3.0;
    assert_int_equal(rl_pose_solve(&c, &m, &mt, d.data(), 2, NULL, &p), RL_ERANGE);
}

// The same points through cv::solvePnP: the camera pose must agree.
static void test_pose_agrees_with_solvepnp(void **)
{
    rl_calib c = make_cam(RL_DIST_PLUMB_BOB);
    cv::Mat K, D;
    cv_mats(c, K, D);
    rl_map m = site_map();
    rl_mount mt = {0, 0, 0.88, 0, 0, 0, RL_POSE_TILT_PRIOR};
    double Z = m.ceiling_height - mt.z;
    // noise-free points: the two must agree; with 0.2 px noise both must
    // stay near the truth (solvePnP also fits a tilt, which the known
    // upward mounting lets ringloc leave out)
    for (double noise : {0.0, 0.2})
    for (double yaw : {0.3, -1.2}) {
        std::vector<rl_detection> d = observe(c, m, mt, 1.6, 1.3, yaw, noise);
        // solvePnP is given the images of the centres themselves (it has no
        // model of an edge fit's offset), with the same noise
        std::vector<rl_detection> dc = observe(c, m, mt, 1.6, 1.3, yaw, noise, false);
        rl_pose p;
        assert_int_equal(rl_pose_solve(&c, &m, &mt, d.data(), (int)d.size(), NULL, &p), RL_OK);
        // world: map x, y on the ceiling plane at z = Z above the camera's plane
        std::vector<cv::Point3d> w;
        std::vector<cv::Point2d> im;
        for (auto &o : dc) {
            int k = rl_map_find(&m, o.id);
            w.push_back({m.lm[k].x, m.lm[k].y, Z});
            im.push_back({o.u, o.v});
        }
        cv::Mat rvec, tvec, R;
        assert_true(cv::solvePnP(w, im, K, D, rvec, tvec, false, cv::SOLVEPNP_ITERATIVE));
        cv::Rodrigues(rvec, R);
        cv::Mat C = -R.t() * tvec; // camera centre in the world
        // the camera's forward (image top, -y_c) in the world gives the yaw
        cv::Mat fwd = R.t() * (cv::Mat_<double>(3, 1) << 0, -1, 0);
        double cv_yaw = std::atan2(fwd.at<double>(1), fwd.at<double>(0));
        double dpos = std::hypot(C.at<double>(0) - p.cam_x, C.at<double>(1) - p.cam_y);
        double dyaw = std::fabs(std::remainder(cv_yaw - p.cam_yaw, 2 * M_PI));
        double tol = 0.0005;
        if (noise > 0) { // each against the truth: ringloc within 3 mm, and no worse
            double e_cv = std::hypot(C.at<double>(0) - 1.6, C.at<double>(1) - 1.3);
            double e_rl = std::hypot(p.cam_x - 1.6, p.cam_y - 1.3);
            assert_true(e_cv < 0.010);
            assert_true(e_rl < 0.003);
            assert_true(e_rl <= e_cv + 0.0005);
            dpos = 0;
            dyaw = std::max(std::fabs(std::remainder(cv_yaw - yaw, 2 * M_PI)),
                            std::fabs(std::remainder(p.cam_yaw - yaw, 2 * M_PI)));
            tol = 0.002;
        }
        if (dpos > tol || dyaw > tol)
            fail_msg("yaw %.2f: ringloc (%.4f, %.4f, %.4f), solvePnP (%.4f, %.4f, %.4f)", yaw, p.cam_x,
                     p.cam_y, p.cam_yaw, C.at<double>(0), C.at<double>(1), cv_yaw);
        assert_true(std::fabs(C.at<double>(2)) < 0.02); // and the camera sits at height 0
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_project_and_undistort_match_opencv),
        cmocka_unit_test(test_pose_exact_and_mount),
        cmocka_unit_test(test_tilted_pose_against_truth_and_solvepnp),
        cmocka_unit_test(test_pose_drops_a_misplaced_landmark),
        cmocka_unit_test(test_pose_too_few),
        cmocka_unit_test(test_pose_agrees_with_solvepnp),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
