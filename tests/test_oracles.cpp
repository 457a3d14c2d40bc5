// Each recognition stage against an independent oracle:
// - histogram K-means against OpenCV's cv::kmeans on the same intensities;
// - run-length labelling against cv::connectedComponentsWithStats (bands
//   anywhere in the grey range, per-tile thresholds);
// - radial Pearson identification against the direct formula over pixels.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
extern "C" {
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>
#include "rl_hist.h"
#include "rl_match.h"
#include "rl_polar.h"
#include "rl_label.h"
#include "rl_raster.h"
}

// Total within-cluster squared error of a 1-D partition by nearest centre.
static double sse(const std::vector<float> &v, const std::vector<double> &c)
{
    double s = 0;
    for (float x : v) {
        double best = 1e18;
        for (double m : c)
            best = std::min(best, (x - m) * (x - m));
        s += best;
    }
    return s;
}

static void test_kmeans_matches_opencv(void **)
{
    int optimum_matches = 0;
    std::mt19937 rng(42);
    for (int trial = 0; trial < 20; trial++) {
        // a ceiling-like mixture: few dark pixels, a grey class, a bright background
        std::vector<float> v;
        std::normal_distribution<double> dark(25 + trial, 6), grey(120, 12), bg(200 - trial, 9);
        int nd = 2000 + 300 * trial, ng = 3000, nb = 40000;
        rl_hist h;
        std::memset(&h, 0, sizeof h);
        auto add = [&](double x) {
            int q = std::max(0, std::min(255, (int)std::lround(x)));
            v.push_back((float)q);
            h.bin[q]++;
            h.total++;
        };
        for (int i = 0; i < nd; i++) add(dark(rng));
        for (int i = 0; i < ng; i++) add(grey(rng));
        for (int i = 0; i < nb; i++) add(bg(rng));
        for (int k = 2; k <= 3; k++) {
            double c[3];
            assert_int_equal(rl_hist_kmeans(&h, 0, 256, k, c, NULL), RL_OK);
            cv::Mat data((int)v.size(), 1, CV_32F, v.data()), labels, centres;
            cv::kmeans(data, k, labels,
                       cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-4),
                       8, cv::KMEANS_PP_CENTERS, centres);
            std::vector<double> cv_c, rl_c(c, c + k);
            for (int i = 0; i < k; i++)
                cv_c.push_back(centres.at<float>(i));
            std::sort(cv_c.begin(), cv_c.end());
            double e_rl = sse(v, rl_c), e_cv = sse(v, cv_c);
            // exact optimum: never worse than OpenCV's best of 8 attempts ...
            if (e_rl > e_cv * (1 + 1e-9) + 1e-6)
                fail_msg("trial %d k=%d: ringloc error %.1f > OpenCV %.1f", trial, k, e_rl, e_cv);
            // ... the same centres when OpenCV found the optimum too ...
            if (e_cv <= e_rl * (1 + 1e-6))
                for (int i = 0; i < k; i++)
                    if (std::fabs(cv_c[i] - rl_c[i]) > 0.05)
                        fail_msg("trial %d k=%d centre %d: ringloc %.3f, OpenCV %.3f", trial, k,
                                 i, rl_c[i], cv_c[i]);
            // ... and a fixed point of Lloyd's iteration: each centre is the
            // mean of the intensities nearest to it
            std::vector<double> sum(k, 0), cnt(k, 0);
            for (float x : v) {
                int best = 0;
                for (int i = 1; i < k; i++)
                    if (std::fabs(x - rl_c[i]) < std::fabs(x - rl_c[best]))
                        best = i;
                sum[best] += x;
                cnt[best] += 1;
            }
            for (int i = 0; i < k; i++)
                assert_true(std::fabs(sum[i] / cnt[i] - rl_c[i]) < 1e-6);
            optimum_matches += e_cv <= e_rl * (1 + 1e-6);
        }
    }
    assert_true(optimum_matches >= 30); // OpenCV usually finds the optimum as well
}

static void test_kmeans_edge_cases(void **)
{
    rl_hist h;
    double c[3];
    int start[3];
    std::memset(&h, 0, sizeof h);
    h.bin[10] = 5;
    h.bin[200] = 7;
    h.total = 12;
    assert_int_equal(rl_hist_kmeans(&h, 0, 256, 3, c, NULL), RL_ERANGE);
    assert_int_equal(rl_hist_kmeans(&h, 0, 256, 2, c, start), RL_OK);
    assert_true(c[0] == 10.0 && c[1] == 200.0);
    assert_true(start[1] > 10 && start[1] <= 200);
    assert_int_equal(rl_hist_kmeans(&h, 0, 256, 4, c, NULL), RL_EINVAL);
    assert_int_equal(rl_hist_kmeans(&h, 100, 50, 2, c, NULL), RL_EINVAL);
}

// The labelling's regions and runs against OpenCV's 8-connected
// components of bin (255 where a pixel is in the band).
static void expect_opencv_regions(const rl_label &lb, const cv::Mat &bin, int min_area, int trial)
{
    cv::Mat labels, stats, cents;
    int n = cv::connectedComponentsWithStats(bin, labels, stats, cents, 8, CV_32S);
    struct box { int area, x0, y0, x1, y1; double cx, cy; };
    std::vector<box> want, got;
    for (int i = 1; i < n; i++) {
        int a = stats.at<int>(i, cv::CC_STAT_AREA);
        if (a < min_area)
            continue;
        int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
        want.push_back({a, x, y, x + stats.at<int>(i, cv::CC_STAT_WIDTH) - 1,
                        y + stats.at<int>(i, cv::CC_STAT_HEIGHT) - 1, cents.at<double>(i, 0),
                        cents.at<double>(i, 1)});
    }
    for (int i = 0; i < lb.n_regions; i++) {
        const rl_region &g = lb.reg[i];
        got.push_back({g.area, g.x0, g.y0, g.x1, g.y1, g.sx / g.area, g.sy / g.area});
    }
    auto key = [](const box &a, const box &b) {
        return std::tie(a.y0, a.x0, a.area) < std::tie(b.y0, b.x0, b.area);
    };
    std::sort(want.begin(), want.end(), key);
    std::sort(got.begin(), got.end(), key);
    if (want.size() != got.size())
        fail_msg("trial %d: %zu regions, OpenCV %zu", trial, got.size(), want.size());
    for (size_t i = 0; i < want.size(); i++) {
        assert_int_equal(got[i].area, want[i].area);
        assert_int_equal(got[i].x0, want[i].x0);
        assert_int_equal(got[i].y1, want[i].y1);
        assert_int_equal(got[i].x1, want[i].x1);
        assert_true(std::fabs(got[i].cx - want[i].cx) < 1e-9);
        assert_true(std::fabs(got[i].cy - want[i].cy) < 1e-9);
    }
    // every run's region is the one OpenCV gives its pixels, and the runs
    // cover every pixel in the band
    int covered = 0;
    for (int y = 0; y < bin.rows; y++)
        for (int r = lb.row[y]; r < lb.row[y + 1]; r++) {
            int reg = rl_label_region_of(&lb, r);
            int cvl = labels.at<int>(y, lb.x0[r]);
            for (int x = lb.x0[r]; x <= lb.x1[r]; x++)
                assert_int_equal(labels.at<int>(y, x), cvl);
            assert_int_not_equal(cvl, 0);
            covered += lb.x1[r] - lb.x0[r] + 1;
            if (reg >= 0)
                assert_int_equal(stats.at<int>(cvl, cv::CC_STAT_AREA), lb.reg[reg].area);
        }
    assert_int_equal(covered, cv::countNonZero(bin));
}

static void test_labelling_matches_opencv(void **)
{
    std::mt19937 rng(7);
    for (int trial = 0; trial < 30; trial++) {
        int W = 97 + trial * 3, H = 61 + trial;
        cv::Mat img(H, W + 5, CV_8U, cv::Scalar(220)); // stride > width
        cv::Mat view = img(cv::Rect(0, 0, W, H));
        std::uniform_int_distribution<int> X(0, W - 1), Y(0, H - 1), R(1, 9);
        for (int i = 0; i < 25; i++)
            cv::circle(view, {X(rng), Y(rng)}, R(rng), cv::Scalar(20), trial % 2 ? cv::FILLED : 1);
        for (int i = 0; i < 200; i++) // specks and diagonal touches
            view.at<uchar>(Y(rng), X(rng)) = 10;
        rl_image ri = rl_image_view(W, H, (int)img.step, img.data);
        std::vector<unsigned char> mem(rl_label_bytes(W, H, W * H, 4096) + 64);
        rl_ws ws;
        rl_ws_init(&ws, mem.data(), mem.size());
        rl_label lb;
        assert_int_equal(rl_label_init(&lb, &ws, W, H, W * H, 4096), RL_OK);
        int min_area = 1 + trial % 4;
        assert_int_equal(rl_label_band(&lb, &ri, 0, 128, min_area), RL_OK);
        expect_opencv_regions(lb, view < 128, min_area, trial);
    }
}

// Bands anywhere in the grey range and per-tile thresholds, on images of
// every grey level whose widths are no multiple of the labeller's chunk:
// the band as defined (lo <= I < hi, hi per tile) against OpenCV.
static void test_bands_and_tiles_match_opencv(void **)
{
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> grey(0, 255);
    for (int trial = 0; trial < 40; trial++) {
        int W = 50 + trial * 17, H = 40 + trial % 7 * 9, tile = trial % 3 == 0 ? 8 : trial % 3 == 1 ? 16 : 32;
        cv::Mat img(H, W + 3, CV_8U), bin(H, W, CV_8U);
        for (int y = 0; y < H; y++) // blobs of one grey level over noise
            for (int x = 0; x < W + 3; x++)
                img.at<uchar>(y, x) = (uchar)grey(rng);
        cv::Mat view = img(cv::Rect(0, 0, W, H));
        std::uniform_int_distribution<int> X(0, W - 1), Y(0, H - 1), R(2, 12);
        for (int i = 0; i < 30; i++)
            cv::circle(view, {X(rng), Y(rng)}, R(rng), cv::Scalar(grey(rng)), cv::FILLED);
        rl_image ri = rl_image_view(W, H, (int)img.step, img.data);
        std::vector<unsigned char> mem(rl_label_bytes(W, H, W * H, 1 << 16) + 64);
        rl_ws ws;
        rl_ws_init(&ws, mem.data(), mem.size());
        rl_label lb;
        assert_int_equal(rl_label_init(&lb, &ws, W, H, W * H, 1 << 16), RL_OK);
        if (trial % 2 == 0) {
            // a band: dark, light (to 256), the middle, all, or empty
            static const int bands[][2] = {{0, 90}, {128, 256}, {60, 200}, {0, 256}, {200, 256},
                                           {0, 1}, {77, 77}, {255, 256}, {1, 256}, {0, 200}};
            int lo = bands[trial / 2 % 10][0], hi = bands[trial / 2 % 10][1];
            assert_int_equal(rl_label_band(&lb, &ri, lo, hi, 1), RL_OK);
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    int v = view.at<uchar>(y, x);
                    bin.at<uchar>(y, x) = lo <= v && v < hi ? 255 : 0;
                }
        } else {
            int nx = (W + tile - 1) / tile, ny = (H + tile - 1) / tile;
            std::vector<uint8_t> his(nx * ny);
            for (auto &h : his)
                h = (uint8_t)grey(rng);
            if (trial % 4 == 3) // as rl_split's maps: whole tile rows and single tiles empty
                for (int t = 0; t < nx * ny; t++)
                    if ((t / nx) % 3 != 1 || t % 5 == 0)
                        his[t] = 0;
            rl_label_map map = {his.data(), tile, nx, ny};
            assert_int_equal(rl_label_dark(&lb, &ri, &map, 1), RL_OK);
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++)
                    bin.at<uchar>(y, x) = view.at<uchar>(y, x) < his[(y / tile) * nx + x / tile] ? 255 : 0;
        }
        expect_opencv_regions(lb, bin, 1, trial);
    }
}

// Windows of a larger frame, as the local pass labels them: a row's last,
// short chunk is read from the chunk that ends with it (or copied out when
// the row is shorter than a chunk); the frame's pixels around the window,
// all in the band, must stay out, against OpenCV on the window alone.
static void test_window_chunks_match_opencv(void **)
{
    std::mt19937 rng(13);
    std::uniform_int_distribution<int> grey(0, 255);
    const int FW = 400, FH = 60;
    cv::Mat frame(FH, FW, CV_8U, cv::Scalar(0)); // dark: in the band everywhere outside
    for (int trial = 0; trial < 40; trial++) {
        int W = 20 + trial * 5, H = 30, x0 = 1 + trial * 3 % 37, y0 = 5;
        cv::Mat view = frame(cv::Rect(x0, y0, W, H));
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                view.at<uchar>(y, x) = (uchar)grey(rng);
        rl_image full = rl_image_view(FW, FH, (int)frame.step, frame.data), win;
        assert_int_equal(rl_image_sub(&full, x0, y0, W, H, &win), RL_OK);
        std::vector<unsigned char> mem(rl_label_bytes(FW, FH, FW * FH, 1 << 16) + 64);
        rl_ws ws;
        rl_ws_init(&ws, mem.data(), mem.size());
        rl_label lb;
        assert_int_equal(rl_label_init(&lb, &ws, FW, FH, FW * FH, 1 << 16), RL_OK);
        assert_int_equal(rl_label_band(&lb, &win, 0, 100, 1), RL_OK);
        cv::Mat bin = view < 100;
        expect_opencv_regions(lb, bin, 1, trial);
        view.setTo(cv::Scalar(0));
    }
}

static void test_labelling_limits(void **)
{
    // a checkerboard has one run per dark pixel (20 a row): a budget of 100
    // labels the first 5 rows and counts the 35 left, never overruns
    cv::Mat img(40, 40, CV_8U);
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 40; x++)
            img.at<uchar>(y, x) = (x + y) % 2 ? 0 : 255;
    rl_image ri = rl_image_view(40, 40, 40, img.data);
    std::vector<unsigned char> mem(rl_label_bytes(40, 40, 100, 10) + 64);
    rl_ws ws;
    rl_ws_init(&ws, mem.data(), mem.size());
    rl_label lb;
    assert_int_equal(rl_label_init(&lb, &ws, 40, 40, 100, 10), RL_OK);
    assert_int_equal(rl_label_band(&lb, &ri, 0, 128, 1), RL_OK);
    assert_int_equal(lb.n_runs, 100);
    assert_int_equal(lb.rows_left, 35);
    assert_int_equal(lb.row[5], 100);
    assert_int_equal(lb.row[40], 100);
    // few regions allowed: the rest are counted, not written
    cv::Mat dots(40, 40, CV_8U, cv::Scalar(255));
    for (int i = 0; i < 16; i++)
        dots.at<uchar>(2 + (i / 4) * 9, 2 + (i % 4) * 9) = 0;
    ri = rl_image_view(40, 40, 40, dots.data);
    assert_int_equal(rl_label_band(&lb, &ri, 0, 128, 1), RL_OK);
    assert_int_equal(lb.n_regions, 10);
    assert_int_equal(lb.overflow, 6);
    // a window of the image labels with the same buffers; a taller image
    // than the row index holds is refused
    rl_image window = rl_image_view(20, 20, 40, dots.data);
    assert_int_equal(rl_label_band(&lb, &window, 0, 128, 1), RL_OK);
    assert_int_equal(lb.n_regions, 4);
    assert_int_equal(lb.width, 20);
    rl_image taller = rl_image_view(40, 41, 40, dots.data);
    assert_int_equal(rl_label_band(&lb, &taller, 0, 128, 1), RL_EINVAL);
    // and a wider one (a row's band widths are held for the width at init)
    cv::Mat wide(40, 41, CV_8U, cv::Scalar(255));
    rl_image wider = rl_image_view(41, 40, 41, wide.data);
    assert_int_equal(rl_label_band(&lb, &wider, 0, 128, 1), RL_EINVAL);
}

// Direct Pearson over pixels within 1.2 R against a template evaluated per
// pixel, and the radial-bin algebra of rl_match_all, must agree.
static void test_ident_matches_direct_pearson(void **)
{
    rl_family fam;
    assert_int_equal(rl_family_init(&fam, 5), RL_OK);
    std::vector<unsigned char> mem(rl_templates_bytes(30) + 64);
    rl_ws ws;
    rl_ws_init(&ws, mem.data(), mem.size());
    rl_templates id;
    assert_int_equal(rl_templates_init(&id, &ws, &fam, NULL, 0), RL_OK);
    std::mt19937 rng(3);
    for (int trial = 0; trial < 12; trial++) {
        int true_id = 1 + trial * 2;
        double R = 20 + trial, cx = 50.3 + trial * 0.37, cy = 47.8 - trial * 0.21;
        cv::Mat t(100, 100, CV_8U);
        rl_image tv = rl_image_view(100, 100, (int)t.step, t.data);
        assert_int_equal(rl_raster_draw(&fam, true_id, cx, cy, R, NULL, &tv, NULL), RL_OK);
        cv::Mat img(100, 100, CV_8U);
        std::normal_distribution<double> noise(0, 4);
        for (int y = 0; y < 100; y++)
            for (int x = 0; x < 100; x++)
                img.at<uchar>(y, x) = cv::saturate_cast<uchar>(210 - 0.7 * t.at<uchar>(y, x) + noise(rng));
        rl_image iv = rl_image_view(100, 100, (int)img.step, img.data);
        rl_profile p;
        rl_tone linear; // the drawing is linear in grey: a linear camera
        rl_tone_init(&linear, 1.0);
        rl_profile_gather(&iv, &linear, cx, cy, R, &p);
        rl_match m;
        rl_match_all(&id, &p, &m);
        assert_int_equal(m.id, true_id);
        // direct formula: Pearson over the pixels with the template value of
        // the best id at blur 0 .. 3, evaluated per pixel by its bin
        double best_direct = -1;
        for (int b = 0; b < RL_BLUR_LEVELS; b++) {
            std::vector<uint8_t> a, c;
            for (int y = 0; y < 100; y++)
                for (int x = 0; x < 100; x++) {
                    double d = std::hypot(x - cx, y - cy);
                    if (d >= RL_PROFILE_EXTENT * R)
                        continue;
                    int k = (int)(d * RL_PROFILE_BINS / (RL_PROFILE_EXTENT * R));
                    float tv2 = rl_templates_bin(&id, true_id - 1, b, k);
                    a.push_back((uint8_t)(255 - img.at<uchar>(y, x)));
                    c.push_back((uint8_t)std::lround(tv2 * 255));
                }
            best_direct = std::max(best_direct, rl_match_pearson(a.data(), c.data(), NULL, (int)a.size()));
        }
        if (std::fabs(best_direct - m.score) > 0.003) // template quantized to 8 bits here
            fail_msg("trial %d: binned %.4f, direct %.4f", trial, m.score, best_direct);
        // and close to the 2-D rasterized template itself
        std::vector<uint8_t> a, c;
        for (int y = 0; y < 100; y++)
            for (int x = 0; x < 100; x++)
                if (std::hypot(x - cx, y - cy) < RL_PROFILE_EXTENT * R) {
                    a.push_back((uint8_t)(255 - img.at<uchar>(y, x)));
                    c.push_back(t.at<uchar>(y, x));
                }
        double r2d = rl_match_pearson(a.data(), c.data(), NULL, (int)a.size());
        if (std::fabs(r2d - m.score) > 0.03)
            fail_msg("trial %d: 2-D template %.4f, radial %.4f", trial, r2d, m.score);
        // the gain: the template's black is 0.7 of the white point darker
        // than its white (light in RL_TONE_MAX steps)
        assert_true(std::fabs(m.contrast - 0.7 * RL_TONE_MAX) < 15 * RL_TONE_MAX / 255.0);
    }
}

static void test_pearson_formula(void **)
{
    uint8_t a[5] = {1, 2, 3, 4, 5}, b[5] = {2, 4, 6, 8, 10}, c[5] = {5, 4, 3, 2, 1}, k[5] = {7, 7, 7, 7, 7};
    uint8_t mask[5] = {1, 1, 0, 1, 1};
    assert_true(std::fabs(rl_match_pearson(a, b, NULL, 5) - 1.0) < 1e-12);
    assert_true(std::fabs(rl_match_pearson(a, c, NULL, 5) + 1.0) < 1e-12);
    assert_true(rl_match_pearson(a, k, NULL, 5) == 0.0);
    assert_true(std::fabs(rl_match_pearson(a, b, mask, 5) - 1.0) < 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kmeans_matches_opencv),
        cmocka_unit_test(test_kmeans_edge_cases),
        cmocka_unit_test(test_labelling_matches_opencv),
        cmocka_unit_test(test_bands_and_tiles_match_opencv),
        cmocka_unit_test(test_window_chunks_match_opencv),
        cmocka_unit_test(test_labelling_limits),
        cmocka_unit_test(test_ident_matches_direct_pearson),
        cmocka_unit_test(test_pearson_formula),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
