// rl_survey_adjust: every landmark, the ceiling and every frame's pose and
// tilt by robust least squares (Ceres Solver), then the landmarks'
// covariances. The image model is the pose solver's own
// (rl_pose_fit_predict: the tilted view's edge-centre offset included);
// each centre weighs by its noise, each radius gives the depth (the
// scale), each frame's tilt has a prior (the robot's rocking). Frames are
// eliminated first (Schur), the landmarks and the ceiling solved sparse.
#include <ceres/ceres.h>
#include <ceres/manifold.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

extern "C" {
#include "rl_module.h"
#include "rl_pose_fit.h"
#include "rl_survey.h"
#include "rl_survey_ceres.h"
}

namespace {

// A frame's view of one landmark: its centre (and radius) from the
// robot's pose q (x, y, yaw, roll, pitch), the landmark's (x, y), the
// ceiling's height h and the landmark's own height off it dz (held at 0
// for a landmark on the ceiling's plane).
struct View {
    const rl_survey_config *cfg;
    const rl_pose_model *model; // the mount and the landmarks' radius, made once
    const rl_survey_obs *obs;
    bool radius;

    bool operator()(const double *q, const double *lm, const double *h, const double *dz, double *r) const
    {
        rl_pose_model md = *model;
        double Rc[9], C[3], xn, yn, R = md.radius, Z = h[0] + dz[0];
        md.height = h[0];
        rl_pose_fit_camera(&md, q, Rc, C);
        if (!rl_pose_fit_predict(&md, Rc, C, lm[0], lm[1], Z, &xn, &yn))
            return false;
        double s = cfg->pixel_scale / (cfg->pixel_sigma * obs->noise);
        r[0] = (xn - obs->xn) * s;
        r[1] = (yn - obs->yn) * s;
        if (radius) {
            double depth = Rc[2] * (lm[0] - C[0]) + Rc[5] * (lm[1] - C[1]) + Rc[8] * (Z - C[2]);
            if (!(depth > 1e-6))
                return false;
            r[2] = (R / depth - obs->rn) * cfg->pixel_scale / cfg->radius_sigma;
        }
        return true;
    }
};

struct TiltPrior {
    double sigma;
    template <typename T> bool operator()(const T *q, T *r) const
    {
        r[0] = q[3] / sigma;
        r[1] = q[4] / sigma;
        return true;
    }
};

struct Params {
    std::vector<double> q; // 5 per frame
    std::vector<double> lm; // 2 per landmark
    std::vector<double> dz; // 1 per landmark: its height off the ceiling's plane
    std::vector<char> zfree; // 1: dz estimated (a landmark off the plane), 0: held at 0
    double h;
    rl_pose_model model;   // the mount's rotation, the radius (the height is h)
};

bool use_radius(const rl_survey_config *c)
{
    return c->ceiling_height <= 0 && c->axis_distance <= 0;
}

// The centre residual (px) of observation i at the current parameters;
// false if it could not be evaluated.
bool centre_px(const rl_survey *sv, const Params &p, int f, int i, double *px)
{
    View v{&sv->cfg, &p.model, &sv->obs[i], false};
    double r[2];
    int k = sv->obs_lm[i];
    if (!v(&p.q[5 * f], &p.lm[2 * k], &p.h, &p.dz[k], r))
        return false;
    double s = sv->cfg.pixel_sigma * sv->obs[i].noise;
    *px = std::hypot(r[0] * s, r[1] * s);
    return true;
}

int solve(rl_survey *sv, Params &p, ceres::Problem &problem)
{
    ceres::Solver::Options opt;
    opt.linear_solver_type = ceres::SPARSE_SCHUR;
    opt.num_threads = 1;
    opt.max_num_iterations = 100;
    opt.function_tolerance = 1e-12;
    opt.gradient_tolerance = 1e-14;
    opt.parameter_tolerance = 1e-12;
    opt.logging_type = ceres::SILENT;
    // frames first (each sees only landmarks and the ceiling)
    auto *order = new ceres::ParameterBlockOrdering;
    for (int f = 0; f < sv->n_fr; f++)
        if (problem.HasParameterBlock(&p.q[5 * f]))
            order->AddElementToGroup(&p.q[5 * f], 0);
    for (int k = 0; k < sv->n_lm; k++)
        if (problem.HasParameterBlock(&p.lm[2 * k])) {
            order->AddElementToGroup(&p.lm[2 * k], 1);
            order->AddElementToGroup(&p.dz[k], 1);
        }
    order->AddElementToGroup(&p.h, 1);
    opt.linear_solver_ordering.reset(order);
    ceres::Solver::Summary sum;
    ceres::Solve(opt, &problem, &sum);
    if (!sum.IsSolutionUsable()) {
        std::snprintf(sv->err, sizeof sv->err, "the solver failed: %s", sum.message.c_str());
        return 0;
    }
    return 1;
}

// One problem over the frames in use; gauge: the origin fixed, the axis
// on y = 0 (fixed too when its distance is known), the ceiling fixed
// when known.
void build_problem(rl_survey *sv, Params &p, ceres::Problem &problem, ceres::LossFunction *loss)
{
    const rl_survey_config *c = &sv->cfg;
    bool rad = use_radius(c);
    for (int f = 0; f < sv->n_fr; f++) {
        const rl_survey_frame *fr = &sv->fr[f];
        if (fr->status != RL_SURVEY_USED)
            continue;
        for (int j = 0; j < fr->n; j++) {
            int i = fr->first + j, k = sv->obs_lm[i];
            if (k < 0)
                continue;
            bool r = rad && sv->obs[i].rn > 0;
            ceres::CostFunction *cost;
            if (r)
                cost = new ceres::NumericDiffCostFunction<View, ceres::CENTRAL, 3, 5, 2, 1, 1>(
                    new View{c, &p.model, &sv->obs[i], true});
            else
                cost = new ceres::NumericDiffCostFunction<View, ceres::CENTRAL, 2, 5, 2, 1, 1>(
                    new View{c, &p.model, &sv->obs[i], false});
            problem.AddResidualBlock(cost, loss, &p.q[5 * f], &p.lm[2 * k], &p.h, &p.dz[k]);
        }
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<TiltPrior, 2, 5>(new TiltPrior{c->tilt_sigma}),
                                 nullptr, &p.q[5 * f]);
    }
    for (int k = 0; k < sv->n_lm; k++) {
        if (problem.HasParameterBlock(&p.dz[k]) && !p.zfree[k])
            problem.SetParameterBlockConstant(&p.dz[k]);
        if (sv->lm[k].status != RL_SURVEY_PLACED || !problem.HasParameterBlock(&p.lm[2 * k]))
            continue;
        if (sv->lm[k].id == c->origin_id)
            problem.SetParameterBlockConstant(&p.lm[2 * k]);
        else if (sv->lm[k].id == c->axis_id) {
            if (c->axis_distance > 0)
                problem.SetParameterBlockConstant(&p.lm[2 * k]);
            else
                problem.SetManifold(&p.lm[2 * k], new ceres::SubsetManifold(2, {1}));
        }
    }
    if (!rad && c->ceiling_height > 0)
        problem.SetParameterBlockConstant(&p.h);
}

// Frames whose centres miss the map by far more than the others do.
int drop_outlier_frames(rl_survey *sv, const Params &p)
{
    std::vector<double> all;
    std::vector<double> frame_rms(sv->n_fr, 0.0);
    for (int f = 0; f < sv->n_fr; f++) {
        const rl_survey_frame *fr = &sv->fr[f];
        double ss = 0;
        int n = 0;
        if (fr->status != RL_SURVEY_USED)
            continue;
        for (int j = 0; j < fr->n; j++) {
            int i = fr->first + j;
            double px;
            if (sv->obs_lm[i] < 0)
                continue;
            if (!centre_px(sv, p, f, i, &px))
                px = 1e3;
            all.push_back(px);
            ss += px * px;
            n++;
        }
        frame_rms[f] = n ? std::sqrt(ss / n) : 0;
    }
    if (all.empty())
        return 0;
    std::nth_element(all.begin(), all.begin() + all.size() / 2, all.end());
    // the median of a 2-D normal's norm is 1.177 sigma
    double sigma = std::max(all[all.size() / 2] / 1.177, 0.02);
    int dropped = 0;
    for (int f = 0; f < sv->n_fr; f++)
        if (sv->fr[f].status == RL_SURVEY_USED && frame_rms[f] > 8 * sigma) {
            sv->fr[f].status = RL_SURVEY_OUTLIER;
            dropped++;
        }
    return dropped;
}

// Residual statistics; the variance factor of the
// centres and radii (the noise as it came out over as assumed, outliers
// clipped as the loss clips them), never below 1: residuals smaller than
// the assumed noise do not make a landmark surer (its own centre bias
// does not show in them).
double summarize(rl_survey *sv, const Params &p)
{
    const rl_survey_config *c = &sv->cfg;
    bool rad = use_radius(c);
    double ss_px = 0, ss_w = 0;
    long n_px = 0, n_res = 0;
    long placed = 0;
    sv->frames_used = sv->obs_used = 0;
    for (int k = 0; k < sv->n_lm; k++)
        placed += sv->lm[k].status == RL_SURVEY_PLACED;
    for (int f = 0; f < sv->n_fr; f++) {
        const rl_survey_frame *fr = &sv->fr[f];
        if (fr->status != RL_SURVEY_USED)
            continue;
        sv->frames_used++;
        for (int j = 0; j < fr->n; j++) {
            int i = fr->first + j, k = sv->obs_lm[i];
            bool r = rad && sv->obs[i].rn > 0;
            double res[3];
            if (k < 0)
                continue;
            View v{c, &p.model, &sv->obs[i], r};
            if (!v(&p.q[5 * f], &p.lm[2 * k], &p.h, &p.dz[k], res))
                continue;
            double s = c->pixel_sigma * sv->obs[i].noise;
            double px2 = res[0] * res[0] * s * s + res[1] * res[1] * s * s;
            if (sv->obs[i].noise <= 1.0) {
                ss_px += px2;
                n_px++;
            }
            for (int t = 0; t < (r ? 3 : 2); t++)
                ss_w += std::min(res[t] * res[t], 9.0);
            n_res += r ? 3 : 2;
            sv->obs_used++;
        }
    }
    sv->rms_px = n_px ? std::sqrt(ss_px / n_px) : 0;
    long dof = n_res - 3L * sv->frames_used - 2L * placed - std::count(p.zfree.begin(), p.zfree.end(), 1);
    return dof > 0 ? std::max(ss_w / dof, 1.0) : 1.0;
}

// How the covariances are computed (sparse QR, the loss applied).
ceres::Covariance::Options covariance_options()
{
    ceres::Covariance::Options o;
    o.algorithm_type = ceres::SPARSE_QR;
    o.num_threads = 1;
    o.apply_loss_function = true;
    return o;
}

// Covariances of the landmarks and the ceiling, scaled by the variance
// factor.
int covariances(rl_survey *sv, Params &p, ceres::Problem &problem, double factor)
{
    ceres::Covariance cov(covariance_options());
    std::vector<std::pair<const double *, const double *>> blocks;
    for (int k = 0; k < sv->n_lm; k++)
        if (sv->lm[k].status == RL_SURVEY_PLACED && problem.HasParameterBlock(&p.lm[2 * k]) &&
            !problem.IsParameterBlockConstant(&p.lm[2 * k]))
            blocks.emplace_back(&p.lm[2 * k], &p.lm[2 * k]);
    for (int k = 0; k < sv->n_lm; k++)
        if (p.zfree[k] && problem.HasParameterBlock(&p.dz[k]) && !problem.IsParameterBlockConstant(&p.dz[k]))
            blocks.emplace_back(&p.dz[k], &p.dz[k]);
    bool h_free = !problem.IsParameterBlockConstant(&p.h);
    if (h_free)
        blocks.emplace_back(&p.h, &p.h);
    if (!cov.Compute(blocks, &problem)) {
        std::snprintf(sv->err, sizeof sv->err, "the landmarks' covariance could not be computed (the drive does "
                      "not fix every landmark)");
        return 0;
    }
    for (int k = 0; k < sv->n_lm; k++) {
        double m[4] = {0, 0, 0, 0};
        rl_survey_landmark *lm = &sv->lm[k];
        if (lm->status == RL_SURVEY_PLACED && problem.HasParameterBlock(&p.lm[2 * k]) &&
            !problem.IsParameterBlockConstant(&p.lm[2 * k]))
            cov.GetCovarianceBlock(&p.lm[2 * k], &p.lm[2 * k], m);
        lm->cov[0] = m[0] * factor;
        lm->cov[1] = m[1] * factor;
        lm->cov[2] = m[3] * factor;
        lm->sigma_z = 0;
        if (p.zfree[k] && problem.HasParameterBlock(&p.dz[k]) && !problem.IsParameterBlockConstant(&p.dz[k])) {
            double zz;
            cov.GetCovarianceBlock(&p.dz[k], &p.dz[k], &zz);
            lm->sigma_z = std::sqrt(std::max(0.0, zz * factor));
        }
    }
    sv->sigma_height = 0;
    if (h_free) {
        double hh;
        cov.GetCovarianceBlock(&p.h, &p.h, &hh);
        sv->sigma_height = std::sqrt(std::max(0.0, hh * factor));
    }
    return 1;
}

// A landmark is off the ceiling's plane when its own height, estimated
// with every landmark's free and the plane held, is this far off it and
// this many of its sigmas.
const double OFF_PLANE_M = 0.03;
const double OFF_PLANE_SIGMAS = 5.0;

// The landmarks off the ceiling's plane: every landmark's own height
// estimated from the one-plane fit p (the plane held: every height free
// would leave it undetermined; the origin's held too where no radius
// fixes the scale); those off it get zfree and their estimate in p.
// How many; -1 when the check could not be made.
int off_plane(rl_survey *sv, Params &p, ceres::LossFunction *loss)
{
    Params t = p;
    ceres::Problem::Options po;
    po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(po);
    for (int k = 0; k < sv->n_lm; k++)
        t.zfree[k] = sv->lm[k].status == RL_SURVEY_PLACED &&
                     (use_radius(&sv->cfg) || sv->lm[k].id != sv->cfg.origin_id);
    build_problem(sv, t, problem, loss);
    problem.SetParameterBlockConstant(&t.h);
    if (problem.NumResidualBlocks() == 0 || !solve(sv, t, problem))
        return -1;
    ceres::Covariance cov(covariance_options());
    std::vector<std::pair<const double *, const double *>> blocks;
    for (int k = 0; k < sv->n_lm; k++)
        if (t.zfree[k] && problem.HasParameterBlock(&t.dz[k]))
            blocks.emplace_back(&t.dz[k], &t.dz[k]);
    if (blocks.empty() || !cov.Compute(blocks, &problem))
        return -1;
    int n = 0;
    for (int k = 0; k < sv->n_lm; k++) {
        double zz;
        if (!t.zfree[k] || !problem.HasParameterBlock(&t.dz[k]))
            continue;
        cov.GetCovarianceBlock(&t.dz[k], &t.dz[k], &zz);
        if (std::fabs(t.dz[k]) > std::max(OFF_PLANE_M, OFF_PLANE_SIGMAS * std::sqrt(std::max(0.0, zz)))) {
            p.zfree[k] = 1;
            p.dz[k] = t.dz[k];
            n++;
        }
    }
    return n;
}

} // namespace

extern "C" RL_MODULE_EXPORT unsigned long rl_module_abi(void)
{
    return RL_SURVEY_CERES_ABI;
}

extern "C" RL_MODULE_EXPORT rl_err rl_survey_adjust_ceres(rl_survey *sv)
{
    Params p;
    p.q.assign(5 * (size_t)sv->n_fr, 0.0);
    p.lm.assign(2 * (size_t)sv->n_lm, 0.0);
    p.dz.assign((size_t)sv->n_lm, 0.0);
    p.zfree.assign((size_t)sv->n_lm, 0);
    p.h = sv->height;
    rl_pose_fit_model(&p.model, &sv->cfg.mount, sv->height, 0.5 * sv->cfg.diameter);
    for (int f = 0; f < sv->n_fr; f++) {
        const rl_survey_frame *fr = &sv->fr[f];
        double q[5] = {fr->x, fr->y, fr->yaw, fr->roll, fr->pitch};
        std::copy(q, q + 5, &p.q[5 * f]);
    }
    for (int k = 0; k < sv->n_lm; k++) {
        p.lm[2 * k] = sv->lm[k].x;
        p.lm[2 * k + 1] = sv->lm[k].y;
    }
    ceres::HuberLoss loss(3.0);
    double factor = 1;
    bool checked = false;
    for (int round = 0; round < 4; round++) {
        ceres::Problem::Options po;
        po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
        ceres::Problem problem(po);
        build_problem(sv, p, problem, &loss);
        if (problem.NumResidualBlocks() == 0) {
            std::snprintf(sv->err, sizeof sv->err, "no frame with two or more placed landmarks");
            return RL_ETOOFEW;
        }
        if (!solve(sv, p, problem))
            return RL_ERANGE;
        // once, before frames are judged by a fit of one plane: the
        // landmarks off it, then the fit again with their own heights
        if (!checked) {
            checked = true;
            if (off_plane(sv, p, &loss) > 0)
                continue;
        }
        if (round < 3 && drop_outlier_frames(sv, p) > 0)
            continue;
        factor = summarize(sv, p);
        if (!covariances(sv, p, problem, factor))
            return RL_ERANGE;
        break;
    }
    if (!std::isfinite(p.h)) {
        std::snprintf(sv->err, sizeof sv->err, "the solution is not finite");
        return RL_ERANGE;
    }
    sv->height = p.h;
    for (int f = 0; f < sv->n_fr; f++) {
        rl_survey_frame *fr = &sv->fr[f];
        const double *q = &p.q[5 * f];
        fr->x = q[0];
        fr->y = q[1];
        fr->yaw = std::atan2(std::sin(q[2]), std::cos(q[2]));
        fr->roll = q[3];
        fr->pitch = q[4];
    }
    for (int k = 0; k < sv->n_lm; k++) {
        sv->lm[k].x = p.lm[2 * k];
        sv->lm[k].y = p.lm[2 * k + 1];
        sv->lm[k].z = p.zfree[k] ? p.h + p.dz[k] : 0.0;
    }
    return RL_OK;
}
