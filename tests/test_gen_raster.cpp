// `ringloc gen` output rasterized by independent renderers and measured
// against docs/landmark-spec.md: PNGs read back with OpenCV, PDFs
// rasterized by poppler's pdftoppm at print scale.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
extern "C" {
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>
}

static std::string ringloc, tmpdir;

static int run(const std::string &cmd)
{
    int rc = std::system((cmd + " 2>/dev/null").c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

// Spec radii as fractions of R, written out from the spec's table.
static std::vector<double> spec_radii(int n)
{
    std::vector<double> r{1.0, 0.8};
    for (int k = 1; k <= n; k++)
        r.push_back(0.8 * std::sqrt(double(n - k) / n));
    return r;
}

static double sample(const cv::Mat &g, double x, double y)
{
    int x0 = (int)std::floor(x), y0 = (int)std::floor(y);
    double fx = x - x0, fy = y - y0;
    auto at = [&](int xx, int yy) { return (double)g.at<uchar>(yy, xx); };
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
           fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

// Mean radius of each 50% crossing, from outside in, over many rays.
static std::vector<double> crossings(const cv::Mat &g, double cx, double cy, double rmax,
                                     size_t want)
{
    std::vector<double> sum(want, 0.0);
    const int rays = 360;
    for (int a = 0; a < rays; a++) {
        double th = 2 * M_PI * (a + 0.5) / rays, c = std::cos(th), s = std::sin(th);
        std::vector<double> found;
        double prev = sample(g, cx + rmax * c, cy + rmax * s);
        for (double r = rmax - 0.05; r > 0.5; r -= 0.05) {
            double v = sample(g, cx + r * c, cy + r * s);
            if ((prev - 127.5) * (v - 127.5) < 0) {
                double t = (prev - 127.5) / (prev - v);
                found.push_back(r + 0.05 - t * 0.05);
            }
            prev = v;
        }
        if (found.size() != want)
            fail_msg("ray %d: %zu crossings, want %zu", a, found.size(), want);
        for (size_t i = 0; i < want; i++) {
            sum[i] += found[i];
        }
    }
    for (auto &v : sum)
        v /= rays;
    return sum;
}

static void centre_of_dark(const cv::Mat &g, double &cx, double &cy)
{
    cv::Mat inv = 255 - g;
    cv::Moments m = cv::moments(inv, false);
    cx = m.m10 / m.m00;
    cy = m.m01 / m.m00;
}

static void test_png_zone_radii_every_family(void **)
{
    for (int n = 2; n <= 8; n++) {
        // Alternating code 0101...: every zone boundary is a black/white edge.
        int id = 0;
        for (int k = 0; k < n; k++)
            id = id * 2 + (k % 2);
        std::string out = tmpdir + "/gen_ring" + std::to_string(n) + ".png";
        std::string cmd = ringloc + " gen --family ring" + std::to_string(n) + " --id " +
                          std::to_string(id) + " --png " + out + " --px 2000";
        assert_int_equal(run(cmd), 0);
        cv::Mat g = cv::imread(out, cv::IMREAD_GRAYSCALE);
        assert_false(g.empty());
        double cx, cy;
        centre_of_dark(g, cx, cy);
        assert_true(std::fabs(cx - (g.cols - 1) / 2.0) < 0.5);
        std::vector<double> spec = spec_radii(n);
        std::vector<double> got = crossings(g, cx, cy, 1000 * 1.1, (size_t)n + 1);
        for (int i = 0; i <= n; i++) {
            double want = spec[i] * 1000.0;
            if (std::fabs(got[i] - want) > 0.5)
                fail_msg("ring%d boundary %d: %.3f px, spec %.3f px", n, i, got[i], want);
        }
        // Code zones k = 1..N: equal area within 1%.
        double total = got[1] * got[1];
        for (int k = 1; k <= n; k++) {
            double inner = k < n ? got[k + 1] : 0.0;
            double area = got[k] * got[k] - inner * inner;
            if (std::fabs(area - total / n) > 0.01 * total / n)
                fail_msg("ring%d zone %d area off by %.2f%%", n, k,
                         100 * (area - total / n) / (total / n));
        }
    }
}

static void test_pdf_prints_exact_diameter(void **)
{
    const char *papers[] = {"a4", "letter"};
    for (const char *paper : papers) {
        std::string pdf = tmpdir + "/gen_" + paper + ".pdf", stem = tmpdir + "/gen_" + paper;
        assert_int_equal(run(ringloc + " gen --id 25 --diameter 0.180 --paper " + paper +
                             " --pdf " + pdf),
                         0);
        // 254 dpi: one pixel is 0.1 mm.
        assert_int_equal(run("pdftoppm -r 254 -gray -png -singlefile " + pdf + " " + stem), 0);
        cv::Mat g = cv::imread(stem + ".png", cv::IMREAD_GRAYSCALE);
        assert_false(g.empty());
        double wmm = std::string(paper) == "a4" ? 210.0 : 215.9;
        assert_true(std::fabs(g.cols - wmm * 10) <= 2);
        double cx, cy;
        // the label and crop marks are thin; the landmark dominates the moments
        cv::Mat body = g.clone();
        cv::rectangle(body, cv::Rect(0, g.rows - 300, g.cols, 300), 255, cv::FILLED);
        centre_of_dark(body, cx, cy);
        // 11001: edges at R, 0.8 sqrt(3/5) R (outer ring and zones 1-2 merge), 0.8 sqrt(1/5) R
        std::vector<double> got = crossings(body, cx, cy, 950, 3);
        double R = got[0];
        if (std::fabs(2 * R - 1800.0) > 3.0) // within 0.3 mm
            fail_msg("%s: printed diameter %.2f mm, want 180 mm", paper, 2 * R / 10);
        assert_true(std::fabs(got[1] - 0.8 * std::sqrt(3.0 / 5) * 900) < 3.0);
        assert_true(std::fabs(got[2] - 0.8 * std::sqrt(1.0 / 5) * 900) < 3.0);
    }
}

// Issue 18: at the largest diameter a paper allows, the whole disk and the
// crop marks are on the page, at least 5 mm (50 px at 254 dpi) from every
// edge; one step larger is refused naming that diameter.
static void test_pdf_keeps_the_margin(void **)
{
    const char *papers[] = {"a4", "letter"};
    const double side_mm[] = {210.0, 215.9};
    for (int k = 0; k < 2; k++) {
        const char *paper = papers[k];
        double dmax = std::floor(side_mm[k] - 10.5) / 1000.0; // whole mm, 5 mm margins
        char d[32];
        std::snprintf(d, sizeof d, "%.4f", dmax);
        std::string pdf = tmpdir + "/gen_max_" + paper + ".pdf", stem = tmpdir + "/gen_max_" + paper;
        assert_int_equal(run(ringloc + " gen --id 25 --diameter " + d + " --paper " + paper + " --pdf " + pdf), 0);
        std::snprintf(d, sizeof d, "%.4f", dmax + 0.001);
        assert_int_not_equal(run("(" + ringloc + " gen --id 25 --diameter " + d + " --paper " + paper +
                                 " --pdf " + tmpdir + "/too_big.pdf 2>" + tmpdir + "/too_big.err)"), 0);
        char want[64];
        std::snprintf(want, sizeof want, "the largest that does is %.3f m", dmax);
        assert_int_equal(run("grep -q '" + std::string(want) + "' " + tmpdir + "/too_big.err"), 0);
        assert_int_equal(run("pdftoppm -r 254 -gray -png -singlefile " + pdf + " " + stem), 0);
        cv::Mat g = cv::imread(stem + ".png", cv::IMREAD_GRAYSCALE);
        assert_false(g.empty());
        // every mark on the page, the label's grey type included
        cv::Mat ink = g < 250;
        cv::Rect box = cv::boundingRect(ink);
        if (box.x < 50 || box.y < 50 || g.cols - (box.x + box.width) < 50 || g.rows - (box.y + box.height) < 50)
            fail_msg("%s: ink from (%d, %d) to (%d, %d) on a %dx%d page: within 5 mm of an edge", paper,
                     box.x, box.y, box.x + box.width, box.y + box.height, g.cols, g.rows);
        // the whole disk: its width is the diameter
        cv::Mat body = g.clone();
        cv::rectangle(body, cv::Rect(0, g.rows - 300, g.cols, 300), 255, cv::FILLED);
        double cx, cy;
        centre_of_dark(body, cx, cy);
        std::vector<double> got = crossings(body, cx, cy, dmax * 5000 + 30, 3); // id 25: 3 edges
        if (std::fabs(2 * got[0] - dmax * 10000) > 4.0)
            fail_msg("%s: printed diameter %.2f mm, want %.1f mm", paper, 2 * got[0] / 10, dmax * 1000);
        // a crop mark in each corner of the disk's square, inside it
        double R = dmax * 5000;
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = -1; sy <= 1; sy += 2) {
                cv::Rect corner((int)(cx + sx * R - (sx > 0 ? 42 : 2)), (int)(cy + sy * R - (sy > 0 ? 42 : 2)), 44, 44);
                corner &= cv::Rect(0, 0, g.cols, g.rows);
                if (cv::countNonZero(ink(corner)) < 20)
                    fail_msg("%s: no crop mark at corner (%d, %d) of the square around (%.1f, %.1f), R %.1f: %d px of ink", paper, sx, sy, cx, cy, R, cv::countNonZero(ink(corner)));
            }
    }
}

static void test_pdf_map_pages_and_svg(void **)
{
    std::string map = tmpdir + "/gen_map.yaml", pdf = tmpdir + "/gen_map.pdf";
    FILE *f = std::fopen(map.c_str(), "w");
    assert_non_null(f);
    std::fputs("family: ring4\ndiameter: 0.15\nceiling_height: 2.5\nlandmarks:\n"
               "  - {id: 3, x: 0, y: 0}\n  - {id: 9, x: 0.5, y: 0}\n  - {id: 14, x: 1, y: 0}\n",
               f);
    std::fclose(f);
    assert_int_equal(run(ringloc + " gen --map " + map + " --pdf " + pdf + " --svg " + tmpdir +
                         "/gen_map.svg"),
                     0);
    assert_int_equal(run("pdftoppm -r 20 -png " + pdf + " " + tmpdir + "/gen_map_page"), 0);
    for (int p = 1; p <= 3; p++) {
        cv::Mat g = cv::imread(tmpdir + "/gen_map_page-" + std::to_string(p) + ".png",
                               cv::IMREAD_GRAYSCALE);
        assert_false(g.empty());
    }
    assert_true(cv::imread(tmpdir + "/gen_map_page-4.png").empty());
    for (int id : {3, 9, 14}) {
        FILE *s = std::fopen((tmpdir + "/gen_map-" + std::to_string(id) + ".svg").c_str(), "r");
        assert_non_null(s);
        char head[64] = {0};
        assert_true(std::fread(head, 1, 63, s) > 10);
        std::fclose(s);
        assert_non_null(std::strstr(head, "<?xml"));
    }
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: test_gen_raster RINGLOC TMPDIR\n");
        return 2;
    }
    ringloc = argv[1];
    tmpdir = argv[2];
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_png_zone_radii_every_family),
        cmocka_unit_test(test_pdf_prints_exact_diameter),
        cmocka_unit_test(test_pdf_keeps_the_margin),
        cmocka_unit_test(test_pdf_map_pages_and_svg),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
