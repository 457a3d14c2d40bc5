#include "rl_twins.h"

#include <math.h>

#include "rl_clip.h"
#include "rl_edge.h"
#include "rl_ellipse.h"
#include "rl_median.h"
#include "rl_motion.h"
#include "rl_refine.h"
#include "rl_result.h"
#include "rl_twins_cut.h"
#include "rl_twins_lead.h"
#include "rl_twins_rank.h"
#include "rl_twins_steep.h"

/* How far a twin may lead d through the other formation: read as linear
 * light, RL_TWINS_TOLERANCE; read through a curve (the other formation
 * then the grey levels as the camera gave them, mixed after its curve, the
 * formation the near wrong reads came from), RL_TWINS_LOCAL_TOLERANCE for a
 * local read and RL_TWINS_CUT_TOLERANCE for a landmark the border cuts.
 * Read as linear, right reads let the 2.2 curve's twin lead by up to 0.006
 * (the 16 px sheets of the development folders at gamma 1, cut ones among
 * them), wrong ones gave it 0.009 or more; but a small read (small: under
 * the far radius), local or global, none (RL_TWINS_SMALL_LINEAR_TOLERANCE). */
static double tolerance(const rl_detection *d, int curved, int small)
{
    if (!curved)
        return small ? RL_TWINS_SMALL_LINEAR_TOLERANCE : RL_TWINS_TOLERANCE;
    if (!d->complete)
        return RL_TWINS_CUT_TOLERANCE;
    return d->pass == RL_PASS_LOCAL ? RL_TWINS_LOCAL_TOLERANCE : RL_TWINS_TOLERANCE;
}

/* d's minor semi-axis: the ellipse fitted to its outer edge (radius of
 * its area times the root of its aspect); its radius where none fits or
 * the border cuts it; its aspect (minor over major, 1 there) into
 * *aspect. Code zone 1 is narrowest along a slanted
 * landmark's minor axis: a whole 1 of a 15 px grey-mixed sheet at aspect
 * 0.88, its radius read 14.30 px over the size floor, its minor
 * semi-axis 12.8 px (zone 1 1.08 px there, where every wrong read under
 * the floor had 1.14 px or less), was read as its twin 17, the twin
 * 0.0048 ahead through the grey levels (docs/results.md). */
static double minor_radius(const rl_recog *rec, const rl_image *img, int light, const rl_detection *d,
                           double *aspect)
{
    double ex[RL_EDGE_RAYS], ey[RL_EDGE_RAYS];
    rl_ellipse e;
    int n;
    *aspect = 1.0;
    if (!d->complete)
        return d->radius;
    n = rl_edge_points(img, rec->tone, light, d->u, d->v, d->radius, ex, ey);
    if (!rl_ellipse_fit(ex, ey, n, d->u, d->v, d->radius, &e))
        return d->radius;
    *aspect = rl_ellipse_aspect(&e.shape);
    return e.r * sqrt(*aspect);
}

/* Whether d keeps its id, from its lead over its best rival through
 * the other formation (other) and through the frame's curve (own): while
 * the twin leads by less than tol through the other (none at all: tol 0),
 * and the sum is over margin (0 for a global read: the whole ring at the
 * frame's levels; margin()). */
static int keeps(double tol, double margin, double other, double own)
{
    int within = tol > 0 ? other > -tol : other >= 0;
    return within && other + own > margin;
}

/* The sum keeps wants: RL_TWINS_LOCAL_MARGIN for a local read (read
 * sector by sector, its own lead says less) and for a global one under
 * the far radius, whatever the curve (small: a whole 4 of a 16 px
 * moving frame read as its twin 20 led it by 0.0039 through the other
 * formation and 0.0026 through its own, the right 23 of the same frame
 * by 0.0096 and 0.048; another 4 read as 20 in a frame read as linear by
 * 0.0008 and 0.0026: docs/results.md, twelfth session), else 0. */
static double margin(const rl_detection *d, int small)
{
    return d->pass == RL_PASS_LOCAL || small ? RL_TWINS_LOCAL_MARGIN : 0.0;
}

/* Whether the rank read may decide d: not for a cut landmark read
 * through a curve, nor for a cut local read in a frame read as linear,
 * whose radius is RL_TWINS_CUT_SIZE or more off the frame's size
 * (frame_size; 0: none known, not decided), where the rank read,
 * which leans on the radius, can take its twin: a cut 17 read as 25 at
 * 2.2 with its radius 9% short led 17 by more than RL_TWINS_RANK_LEAD
 * there too (the cut ones it kept right on the development sets were
 * within 4.2%); read as linear, a cut 17 of a moving frame nobody had
 * tuned on (0.58 in view, next to a lamp), its local read's circle 1.3 px
 * off and 9.8% short, read as its twin 1 and led 17 so, the 2.2 curve's
 * 17 0.009 ahead of it (docs/results.md, eleventh session). A global
 * read's radius comes from its whole box, not a fit to an arc. */
static int rank_fits(const rl_detection *d, int curved, double size)
{
    if (d->complete || (!curved && d->pass != RL_PASS_LOCAL))
        return 1;
    return size > 0 && fabs(d->radius - size) < RL_TWINS_CUT_SIZE * size;
}

/* The frame's size, that the rules judge a read's circle against
 * (rank_fits, the cut-circle rule, size_fits): the median of the radii r
 * but the i-th, of whole reads (whole[j]) of min_radius or more, where
 * two or more are left (a cut read's short circle, a read too small to
 * judge or one other read alone is no frame's size); 0 otherwise (not
 * known). */
static double frame_size(const double *r, const unsigned char *whole, int n, int i, double min_radius)
{
    double v[RL_MAX_LANDMARKS];
    int j, m = 0;
    for (j = 0; j < n; j++)
        if (j != i && whole[j] && r[j] >= min_radius)
            v[m++] = r[j];
    return m >= 2 ? rl_median(v, m) : 0.0;
}

/* What the rules ask of one landmark more than once, each worked out
 * once, when first wanted: its outer edge's ellipse (the size floor
 * along its minor axis, and rules 5 and 6's guard on slanted landmarks),
 * its motion, and its leads over its twins along the motion's sharpest
 * axis through both formations (small_fits and moved_keeps). */
typedef struct {
    int fitted;           /* minor_radius done: */
    double minor, aspect; /* its minor semi-axis, px, and aspect */
    int measured, moved;  /* rl_motion_measure done; it measured, ratio not over RL_TWINS_MOVED */
    rl_motion mo;
    int read;             /* the leads read: */
    double other, own;    /* through the other formation, through the frame's curve */
} landmark_reads;

/* d's minor semi-axis (minor_radius), fitted into m the first time (its
 * aspect then in m->aspect). */
static double minor_radius_once(const rl_recog *rec, const rl_image *img, int light, const rl_detection *d,
                                landmark_reads *m)
{
    if (!m->fitted) {
        m->fitted = 1;
        m->minor = minor_radius(rec, img, light, d, &m->aspect);
    }
    return m->minor;
}

/* Whether d moved (rl_motion_measure, its ratio not over
 * RL_TWINS_MOVED), measured into m the first time. */
static int measure_motion_once(const rl_image *img, const rl_detection *d, landmark_reads *m)
{
    if (!m->measured) {
        m->measured = 1;
        m->moved = rl_motion_measure(img, d->u, d->v, d->radius, &m->mo) && !(m->mo.ratio > RL_TWINS_MOVED);
    }
    return m->moved;
}

/* d's leads over its twins rv along m's sharpest axis at 0.97 .. 1.03
 * (rl_twins_lead), through the other formation and the frame's curve, read
 * into m the first time (m measured and moved). */
static void read_axis_leads_once(const rl_recog *rec, const rl_image *img, const rl_detection *d, const int *rv,
                                 int n, landmark_reads *m)
{
    double fit;
    if (m->read)
        return;
    m->read = 1;
    m->other = rl_twins_lead(rec, img, rl_tones_other(&rec->tones, rec->tone), d, rv, n, 0, m->mo.axis, &fit);
    m->own = rl_twins_lead(rec, img, rec->tone, d, rv, n, 0, m->mo.axis, &fit);
}

/* Whether d, a landmark that moved (rl_motion_measure) refused by the
 * reads of its whole ring, passes keeps (tol) read along its sharpest axis
 * alone, through both formations: across a motion only the blur that is
 * the same every way is left (docs/design.md, rule 5). An axis cannot see
 * a centre off across it, and a local read's centre is where the id fit
 * best (a whole 12 read as 30 from 2.6 px off led there), so but for a
 * whole global read (its centre a darkness centroid) the id must pass
 * about a centre chosen for no id too: a whole one's darkness centroid
 * (twice; a straight motion smears a ring alike on both sides), a cut
 * one's outer edge (rl_edge_fit_rays from its circle, near it; the arc's,
 * rl_twins_rank.c's edge_centre, came on 1 of 12 moved refusals: motion breaks arcs).
 * Its twins at 0.97 .. 1.03 only, not the main read's far range for a
 * small local read: far here cost 50 right reads of the reviewer's 14
 * stress sets and refused no wrong one (twelfth session). Not for a
 * landmark whose edge is an ellipse flatter than RL_TWINS_MOVED_ASPECT.
 * m: d's edge, motion and axis leads, as rl_twins_check and small_fits
 * left them (read here where they did not). *least: the least lead through the other formation
 * it read. */
static int moved_keeps(const rl_recog *rec, const rl_image *img, const rl_levels *lv, const rl_detection *d,
                       const int *rv, int n, double tol, double mg, landmark_reads *m, double *least)
{
    const rl_tone *other = rl_tones_other(&rec->tones, rec->tone);
    rl_detection c = *d;
    double fit, lead;
    if (!measure_motion_once(img, d, m))
        return 0;
    /* a still landmark seen slanted measures as moved (test_motion;
     * test_twins_slanted holds this guard) */
    minor_radius_once(rec, img, lv->light, d, m);
    if (m->aspect < RL_TWINS_MOVED_ASPECT)
        return 0;
    read_axis_leads_once(rec, img, d, rv, n, m);
    *least = m->other;
    if (!keeps(tol, mg, m->other, m->own))
        return 0;
    if (d->pass != RL_PASS_LOCAL && d->complete)
        return 1;
    if (d->complete) {
        rl_refine_centre(img, lv, &c.u, &c.v, c.radius);
        rl_refine_centre(img, lv, &c.u, &c.v, c.radius);
    } else {
        double r = d->radius;
        if (!rl_edge_fit_rays(img, rec->tone, lv->light, &c.u, &c.v, &r) ||
            !(fabs(r - d->radius) <= RL_TWINS_EDGE_RADIUS * d->radius) ||
            !(hypot(c.u - d->u, c.v - d->v) <= RL_TWINS_EDGE_REACH * d->radius))
            return 0;
    }
    lead = rl_twins_lead(rec, img, other, &c, rv, n, 0, m->mo.axis, &fit);
    *least = lead < *least ? lead : *least;
    return keeps(tol, mg, lead, rl_twins_lead(rec, img, rec->tone, &c, rv, n, 0, m->mo.axis, &fit));
}

/* Whether a small whole landmark that moved (rl_motion; every wrong read
 * below had, and on still frames through a wide-angle lens, where the
 * rings are ellipses, the global rule cost 3 right reads of 263) may keep
 * its id before the rules that keep one (keeps, the rank read,
 * moved_keeps): a global read where its twins at 0.91 .. 1.09 of its radius through
 * the frame's own curve do not lead it (three wrong reads of the
 * reviewer's stress sets, a 2 as 18 and a 4 as 20, the twin 0.0002 to
 * 0.001 ahead there, one of them kept by moved_keeps; every right one of
 * 2,246 led by 0.0016 or more), nor along its sharpest axis, and the
 * two leads together over mg, as keeps sums a read's two (thirteenth
 * session: on twelve stress sets of 15-18 px, an 18 as 26 twice, a 4 as
 * 20 and a 16 as 24, smeared to motion ratios 0.27-0.63, led about the
 * whole ring by 0.004 to 0.008 and along the axis by -0.017 to 0.0025;
 * it cost 5 whole landmarks of 3,061 at 2.2, 18 of 2,206 at gamma 1); a
 * local one where it passes keeps along its sharpest axis too (two
 * wrong, a 4 as 20 and
 * an 18 as 26, led their twins through both formations about the whole
 * ring but not along the axis; 11 of 1,100 right ones failed it). m:
 * d's edge, motion and axis leads, read here where wanted (the edge
 * where rl_twins_check did not) and kept for moved_keeps. */
static int small_fits(const rl_recog *rec, const rl_image *img, int light, const rl_detection *d, const int *rv,
                      int n, double tol, double mg, landmark_reads *m)
{
    double fit, ring, axis;
    if (!d->complete || !measure_motion_once(img, d, m))
        return 1;
    if (d->pass != RL_PASS_LOCAL) {
        if ((ring = rl_twins_lead(rec, img, rec->tone, d, rv, n, 1, -1, &fit)) <= 0)
            return 0;
        axis = rl_twins_lead(rec, img, rec->tone, d, rv, n, 1, m->mo.axis, &fit);
        if (axis > 0 && ring + axis > mg)
            return 1;
        /* not along an axis where the edge is an ellipse: a slanted
         * landmark measures as moved (fixtures_lens: 22 right reads);
         * the edge fit only where the axis refuses, the same decisions */
        minor_radius_once(rec, img, light, d, m);
        return m->aspect < RL_TWINS_MOVED_ASPECT;
    }
    read_axis_leads_once(rec, img, d, rv, n, m);
    return keeps(tol, mg, m->other, m->own);
}

/* Whether d, a small landmark (under the far radius), keeps its id read
 * at the frame's size too (size: frame_size, 0 none known), where its
 * read's circle is larger than the frame's by
 * RL_TWINS_CUT_SIZE or more: there its lead over its rivals (rl_twins_rivals())
 * through the other formation plus its lead through the frame's curve,
 * each at 0.97 .. 1.03 of size, must be positive (rule 3's sum, without
 * the margin). The landmarks of one ceiling are one size, and the frame's
 * others measure it through the same blur from pixels this read did not
 * use; a zone twin differs next to the outer ring, where the radius puts
 * the zones, and a circle larger than the frame's reached past the
 * landmark's edge (a lamp's halo: a whole 18 read as 26 from 1.097 of
 * the frame's size). A circle short of the frame's says little (right
 * reads were, and a lens makes the border's landmarks smaller); one
 * lower than the rest (a map's z) is judged at the others' size and may
 * be refused (docs/design.md rule 7, docs/results.md). */
static int size_fits(const rl_recog *rec, const rl_image *img, const rl_tone *other, const rl_detection *d,
                     const int *rv, int n, double size)
{
    rl_detection s = *d;
    double fit, lead;
    if (!(size > 0) || d->radius < (1.0 + RL_TWINS_CUT_SIZE) * size)
        return 1;
    s.radius = size;
    lead = rl_twins_lead(rec, img, other, &s, rv, n, 0, -1, &fit);
    return lead + rl_twins_lead(rec, img, rec->tone, &s, rv, n, 0, -1, &fit) > 0;
}

/* d's lead over its rivals rv through the other formation (rl_twins_lead;
 * far as rl_twins_check_known chose it), its fit into *fit (and where its
 * rivals were read at 0.91 .. 1.09, through rl_tones_other, the fit there
 * into *far_fit, else NAN); with wide (a
 * small global read as linear) at 0.91 .. 1.09 too, the lesser lead: a
 * sharpening after the 2.2 curve leaves its box's radius 7-11% short, and
 * the wider range alone, from coarser bins, let a 24 read as 16 lead by
 * -0.0003 where 3% had it -0.0097 (docs/results.md, fourteenth session). */
static double other_lead(const rl_recog *rec, const rl_image *img, const rl_tone *other, const rl_detection *d,
                         const int *rv, int n, int far, int wide, double *fit, double *far_fit)
{
    double wide_fit = NAN, lead = rl_twins_lead(rec, img, other, d, rv, n, far, -1, fit);
    if (wide)
        lead = fmin(lead, rl_twins_lead(rec, img, other, d, rv, n, 1, -1, &wide_fit));
    /* the id's fit at 0.91 .. 1.09 through the other formation, where read:
     * rl_twins_steep's evidence wants it of every kept read */
    *far_fit = other != rl_tones_other(&rec->tones, rec->tone) ? NAN : far ? *fit : wide_fit;
    return lead;
}

/* d's lead over its rivals rv through the frame's own curve (its fit into
 * *fit), asked where its lead through the other formation does not keep
 * it alone; for a small cut local read in a frame read as linear
 * (cut_linear), 0 where it is not over RL_TWINS_CUT_LINEAR_OWN: there the
 * frame's own lead, a little over the margin, made up a sum the 2.2
 * curve's did not (fifteenth session: a cut 20 read as 8, an 18 as 4, a
 * 24 as 16), and 0 lets neither the sum nor the rank read keep it. */
static double own_lead(const rl_recog *rec, const rl_image *img, const rl_detection *d, const int *rv, int n,
                       int cut_linear, double *fit)
{
    double own = rl_twins_lead(rec, img, rec->tone, d, rv, n, 0, -1, fit);
    return cut_linear && !(own > RL_TWINS_CUT_LINEAR_OWN) ? 0.0 : own;
}

/* Whether d gets no id before its leads are weighed: a small read by
 * rules 6, 7 and 8 (its rivals rv at its own and the frame's size, in
 * clipped light: rl_clip) and a cut global one by rl_twins_cut_global_fits, a cut local
 * read with most of its code zone 1 out of the frame whose lead through
 * the other formation (lead) is under RL_TWINS_CUT_ZONE1_LEAD, and a read
 * whose circle fits far worse than its read (`fit`: an ellipse the local
 * pass read at a lens's border, not judged by its twins) where a lamp
 * covers it (RL_TWINS_UNFIT_LAMP).
 * size: the frame's landmark size (frame_size), asked only of a small one. */
static int refused(const rl_recog *rec, const rl_image *img, const rl_tone *other, int light,
                   const rl_detection *d, const int *rv, int n, double tol, double mg, landmark_reads *reads,
                   int small, double size, double fit, double lead)
{
    if (small && (rl_clip_refuses(rec, img, light, d) || !small_fits(rec, img, light, d, rv, n, tol, mg, reads) ||
                     !size_fits(rec, img, other, d, rv, n, size) ||
                     !rl_twins_cut_global_fits(rec, img, d, rv, n, rec->tones.gamma[rec->tone - rec->tones.tone] > 1.0)))
        return 1;
    if (!d->complete && d->pass == RL_PASS_LOCAL && lead < RL_TWINS_CUT_ZONE1_LEAD &&
        rl_twins_cut_zone1_shown(img, &rec->templates.fam, d) < RL_TWINS_CUT_ZONE1)
        return 1;
    /* no light level (over 255): no lamp in the frame */
    return fit < d->score - RL_TWINS_UNFIT && light <= 255 &&
           rl_clip_disk_share(img, d->u, d->v, d->radius, light, 2) >= RL_TWINS_UNFIT_LAMP;
}

/* d kept as res's next landmark (*n of them so far; from[*n] its index i
 * before); kept[i] 1 when wanted. */
static void keep(rl_result *res, int *n, const rl_detection *d, unsigned char *kept, int i, int *from)
{
    from[*n] = i;
    res->landmarks[(*n)++] = *d;
    if (kept != NULL)
        kept[i] = 1;
}

double rl_twins_min_radius(const rl_family *fam)
{
    /* code zone 1's width, a share of R (the narrowest: the zones inside
     * the outer ring have equal areas) */
    double r[RL_MAX_BITS + 2];
    rl_family_radii(fam, r);
    return RL_TWINS_MIN_ZONE_PX / (r[1] - r[2]);
}

void rl_twins_check(const rl_recog *rec, const rl_image *img, const rl_tone *other, rl_result *res)
{
    rl_twins_check_known(rec, img, other, res, NULL, NULL);
}

/* res's reads before any is judged: each one's radius and whether it is
 * whole (frame_size's), and its far fit not read yet (NAN: other_lead). */
static void frame_reads(const rl_result *res, double *radii, unsigned char *whole, double *far_fit)
{
    int i;
    for (i = 0; i < res->n_landmarks; i++) {
        radii[i] = res->landmarks[i].radius;
        whole[i] = (unsigned char)(res->landmarks[i].complete != 0);
        far_fit[i] = NAN;
    }
}

void rl_twins_check_known(const rl_recog *rec, const rl_image *img, const rl_tone *other, rl_result *res,
                          const unsigned char *known, unsigned char *kept)
{
    double radii[RL_MAX_LANDMARKS], far_fit[RL_MAX_LANDMARKS], min_radius = rl_twins_min_radius(&rec->templates.fam);
    double far_radius = RL_TWINS_FAR_ZONE_PX / RL_TWINS_MIN_ZONE_PX * min_radius; /* 1.5 floors */
    int curved = rec->tones.gamma[rec->tone - rec->tones.tone] > 1.0; /* through a curve, not as linear */
    int i, kept_n = 0, rv[RL_MAX_IDS], n, all = res->n_landmarks, from[RL_MAX_LANDMARKS];
    unsigned char whole[RL_MAX_LANDMARKS], ask[RL_MAX_LANDMARKS] = {0};
    frame_reads(res, radii, whole, far_fit);
    for (i = 0; i < all; i++) {
        rl_detection d = res->landmarks[i];
        landmark_reads reads = {0};
        /* a small landmark (under the far radius), whatever the curve */
        int far, small = d.radius < far_radius;
        double lead, own = 0, fit, tol = tolerance(&d, curved, small), mg;
        if (kept != NULL)
            kept[i] = 0;
        /* too small to tell its twins apart (RL_TWINS_MIN_ZONE_PX); a cut
         * local read off its outer edge (RL_TWINS_CUT_BULGE) */
        if (d.radius < min_radius ||
            (d.pass == RL_PASS_LOCAL && !d.complete &&
             !rl_twins_cut_on_edge(img, rec->tone, res->levels.light, &d,
                                   frame_size(radii, whole, all, i, min_radius)))) {
            rl_result_add_unidentified(res, &d);
            continue;
        }
        /* a global read of a whole landmark clear of every other id through its curve, and of its twins at
         * 0.97 of its radius on the pixels it was read from (twins_led: a whole 2 behind a 2x scaler read
         * as 18 led every id by 0.060, its twin 0.0055 ahead of it there), is clear of its twins; a local
         * read's runner-up (sector-normalized) does not say so, nor a cut one's read through a curve (a
         * circle partly out of the frame: a cut 2 of a 16 px grey-mixed sheet read as its twin 18 at 2.2
         * led every id by 0.055; read as linear, cut ones clear of every id were right on every set), nor a
         * small one's read through a curve (a whole 2 of a 16.8 px moving frame blurred after the curve,
         * read as its twin 18, led every id by 0.051) */
        if ((d.pass == RL_PASS_GLOBAL && (d.complete || !curved) && !small &&
             d.score - d.runner_up >= RL_TWINS_CLEAR && d.twins_led) ||
            (known != NULL && known[i]) || (n = rl_twins_rivals(rec, &d, rv)) == 0) {
            keep(res, &kept_n, &d, kept, i, from);
            continue;
        }
        mg = margin(&d, small);
        /* over the floor by its radius, under it along its minor axis, in
         * a frame read through a curve: zone 1 is too narrow there for
         * the formations to disagree at all (as on a cut landmark,
         * RL_TWINS_CUT_TOLERANCE; read as linear, right reads let the 2.2
         * curve's twin lead by up to 0.006: tolerance 0 there cost 15-25
         * right reads a line at 15-16 px, docs/results.md; a small read
         * as linear, local or global, has none,
         * RL_TWINS_SMALL_LINEAR_TOLERANCE) */
        if (curved && d.radius < far_radius &&
            minor_radius_once(rec, img, res->levels.light, &d, &reads) < min_radius)
            tol = RL_TWINS_CUT_TOLERANCE;
        /* a local read of a small landmark, or of a whole one read as
         * linear: its rivals through the other formation at the radius
         * they fit (rl_twins_lead's far) */
        far = d.pass == RL_PASS_LOCAL && (small || (!curved && d.complete));
        lead = other_lead(rec, img, other, &d, rv, n, far, !curved && small && d.pass != RL_PASS_LOCAL, &fit,
                          &far_fit[i]);
        if (refused(rec, img, other, res->levels.light, &d, rv, n, tol, mg, &reads, small,
                    small ? frame_size(radii, whole, all, i, min_radius) : 0.0, fit, lead)) {
            rl_result_add_unidentified(res, &d);
            continue;
        }
        if (fit < d.score - RL_TWINS_UNFIT) {
            keep(res, &kept_n, &d, kept, i, from);
            continue;
        }
        if (d.score - lead > d.runner_up)
            d.runner_up = d.score - lead;
        /* through the frame's own curve only where the other's lead
         * alone does not keep it (own: 0, the id's lead where it was read) */
        if (!keeps(tol, mg, lead, 0.0))
            own = own_lead(rec, img, &d, rv, n, !curved && small && d.pass == RL_PASS_LOCAL && !d.complete,
                           &fit);
        /* the formations disagree: the read through any monotone curve
         * decides, where the frame's curve reads the id clearly too
         * (RL_TWINS_RANK_OWN); read as linear, doubted where the
         * steepest curve reads a rival (rl_twins_steep, after the loop) */
        if (keeps(tol, mg, lead, own) ||
            (rank_fits(&d, curved, frame_size(radii, whole, all, i, min_radius)) && own > RL_TWINS_RANK_OWN &&
             rl_twins_rank_keeps(rec, img, rec->tone, res->levels.light, &d))) {
            ask[kept_n] = (unsigned char)(!curved && rl_twins_steep_asks(lead));
            keep(res, &kept_n, &d, kept, i, from);
        }
        else if (curved && moved_keeps(rec, img, &res->levels, &d, rv, n, tol, mg, &reads, &lead)) {
            /* its runner-up from the reads across the motion it passed */
            d.runner_up = res->landmarks[i].runner_up;
            if (d.score - lead > d.runner_up)
                d.runner_up = d.score - lead;
            keep(res, &kept_n, &d, kept, i, from);
        }
        else
            rl_result_add_unidentified(res, &d);
    }
    res->n_landmarks = kept_n;
    rl_twins_steep_settle(rec, img, res, ask, from, far_fit, kept);
}
