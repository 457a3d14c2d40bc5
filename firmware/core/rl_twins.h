/* rl_twins: no id that hangs on how the image was formed (internal).
 *
 * Blur, scaling and compression mix either light (optics, motion: before
 * the camera's tone curve) or grey levels (an ISP's scaler, binning after
 * the curve, JPEG, sharpening: after it). A blurred edge falls elsewhere
 * under the two, so code zone 1, the narrowest, next to the outer ring,
 * can swell or shrink by a zone's width and a landmark pass for its zone
 * twin (the codes one zone next to the outer ring away) with a high
 * score. The recognizer cannot tell the formation from one frame, so
 * every landmark that is not clear, of either pass and from the first
 * frame of a stream, is scored with its zone twins (every valid code one
 * zone away) through the other formation (rl_tones_other) at its centre
 * and radius (and 3% either side; a small local read's rivals in a frame
 * read through a curve 9%, RL_TWINS_FAR_ZONE_PX): one whose twin leads it there by more
 * than it leads the twin through the frame's curve is reported
 * unidentified, not as either id (a local read, and any read of a small
 * landmark, under RL_TWINS_FAR_ZONE_PX's radius, needs a margin more),
 * unless read through any monotone curve (rl_rank, which no formation
 * moves; a whole local read about its outer edge's centre too, one
 * chosen for no id, where the edge gives one near its circle) it leads
 * every id up to two zones away clearly, its lead through the frame's
 * curve clear too; or, for a landmark that moved during the exposure
 * (rl_motion: its rings sharper across the motion than along it) in a
 * frame read through a curve, unless read along its sharpest axis alone
 * (where only the blur that is the same every way is left) it passes the
 * same rule there, about its centre and, but for a whole global read,
 * about a centre chosen for no id (a whole one's darkness centroid, a cut
 * one's outer edge). A small whole landmark that moved must also pass
 * before any rule keeps it: a global read its twins at 9% either side
 * through the frame's curve, about the whole ring and along its sharpest
 * axis (the two leads over RL_TWINS_LOCAL_MARGIN), a local read the rule
 * along its sharpest axis (small_fits; docs/design.md, rule 6); a small
 * global read the border cuts, in a frame read through a curve, its twins
 * at 9% either side through that curve (cut_fits). A small
 * landmark read from a circle RL_TWINS_CUT_SIZE or more larger than the
 * frame's other landmarks' must lead its twins read at their radius
 * too (size_fits; rule 7). A landmark too small for its twins to be
 * told apart at all (code zone 1 under RL_TWINS_MIN_ZONE_PX) gets no id,
 * nor a cut local read whose circle the search took off its outer edge
 * (RL_TWINS_CUT_BULGE), nor one with most of its code zone 1 out of the
 * frame whose lead through the other formation is thin
 * (RL_TWINS_CUT_ZONE1).
 * What the twins came to is in the landmark's runner_up.
 *
 *   rl_twins_check(rec, &img, rl_tones_other(&rec->tones, rec->tone), &res);
 */
#ifndef RL_TWINS_H
#define RL_TWINS_H

#include "rl_recog_state.h"

/* A global read of a whole landmark (not a small one: under
 * RL_TWINS_FAR_ZONE_PX's radius it is always checked) whose id leads every
 * other id through its curve by this much correlation is clear (no such read the
 * formations turned into a twin led by more than 0.036: composites and
 * moving frames, docs/design.md; a cut one read through the 2.2 curve
 * led by 0.055, so a landmark the border cuts is always checked in a frame
 * read through a curve), and leads its zone twins at 0.97 of its radius
 * on the pixels the read gathered (rl_twins_led_read,
 * rl_detection.twins_led). */
#define RL_TWINS_CLEAR 0.05
/* A local read's (and a small global read's) lead over its twins, both
 * formations summed, at least;
 * and its twin's lead through the other formation, at most. */
#define RL_TWINS_LOCAL_MARGIN 0.01
/* A twin's lead through the other formation past which no lead through
 * the frame's curve keeps the id: the formations disagree (right reads
 * let a twin come within 0.001-0.014 there, wrong ones gave it 0.009 to
 * 0.048; ISP pipelines and composites, docs/design.md). */
#define RL_TWINS_TOLERANCE 0.006
/* The same for a local read (sector by sector, the centre searched), whose
 * own lead says less, in a frame read through a curve: its right reads let
 * a twin come within 0.004 there, a wrong one (a whole 19 of a 16 px
 * grey-mixed sheet read as 27 at 2.2) gave it 0.0059. */
#define RL_TWINS_LOCAL_TOLERANCE 0.005
/* The same for a landmark the border cuts, in a frame read through a
 * curve (a twin leading by more is too much): none. Its reads rest on the
 * part of the ring in the frame, where a twin leading at all through the
 * grey levels is the formations disagreeing (a cut 17 of a 16 px
 * grey-mixed sheet read as 25 by the local pass at gamma 2.2, its twin
 * 0.0013 ahead there); the rank read decides it, as any landmark they
 * disagree on, where its radius is the frame's (RL_TWINS_CUT_SIZE). */
#define RL_TWINS_CUT_TOLERANCE 0.0
/* The same for a small read, local or global (under RL_TWINS_FAR_ZONE_PX's
 * radius), in a frame read as linear light (the other formation the 2.2
 * curve's): none. A global one's twins are met at 0.97 .. 1.03 and at
 * 0.91 .. 1.09 of its radius, the lesser lead: a 2.2 camera sharpening
 * after its curve, read as linear, leaves the global pass's box 7-11%
 * short, and a 24 read as 16 three times and a 25 as 17 let the twin lead
 * by 0.0036-0.0050 (one of them at 9% only; fourteenth session,
 * tests/frames/small_global_twin). Read as linear, a 2.2 camera's frame
 * leaves the local search's circle 7-11% short of the truth, and its twin, read 3-9% further out
 * through the 2.2 curve (every id, whole or cut, at 0.91 .. 1.09 of the
 * radius), leads by a little: a whole 19 read as 3 twice (the 3 reported
 * with its runner-up over its score: the 19 0.0038 and 0.0057 ahead),
 * cut ones as their twins (a 24 as 16, a 25 as 17, a 29 as 25: ahead by
 * 0.0001, 0.011, 0.036 at the wider range). Of the 2,580 right local
 * reads the start kept at gamma 1 on the development small sets (seeds
 * 101-112, 131-132, 141-146, 161-166), 5 let a twin lead there, by 0.0042
 * at most (docs/results.md, fourteenth session). */
#define RL_TWINS_SMALL_LINEAR_TOLERANCE 0.0
/* A small cut local read (under RL_TWINS_FAR_ZONE_PX's radius) in a frame
 * read as linear light whose lead over its rivals through the 2.2 curve is
 * not over RL_TWINS_LOCAL_MARGIN by itself keeps its id (by rule 3's sum or
 * the rank read) only where its lead through the frame's own curve is over
 * this (rl_twins.c, own_lead). Three wrong reads of a fresh hunt (a cut 20
 * read as 8, an 18 as 4, a 24 as 16; 2.2 cameras with an ISP after the
 * curve, read as linear) led through the 2.2 curve by 0.0008, 0.0087 and
 * 0.0007 and through their own by 0.0136, 0.0133 and 0.0095: the sum was
 * the frame's own lead over the margin. On a truly linear camera's 16 px
 * sheets (the development folders at gamma 1) 4 right cut reads of 187
 * had less (0.0095-0.0143), where refusing every such read under the
 * margin cost 47 (docs/results.md, fifteenth session). */
#define RL_TWINS_CUT_LINEAR_OWN 0.015
/* A cut landmark read through a curve whose radius is this far (a share)
 * from the frame's size (rl_twins.c frame_size: the median of its other
 * whole reads, two or more) is not decided by the rank read (rl_twins.c,
 * rank_fits); a cut local read this much over them has its circle judged
 * against its outer edge (rl_twins_cut_on_edge, RL_TWINS_CUT_BULGE); a
 * small read this much over them must lead its twins read at their
 * radius too (size_fits). */
#define RL_TWINS_CUT_SIZE 0.05
/* A landmark the formations disagree on keeps its id when its lead
 * through the frame's curve passes the rule above with no twin through
 * the other formation, and it leads every id up to two zones away by
 * this much read through any monotone curve (rl_rank). On the
 * development sets the right reads the formations disagreed on led by up
 * to 0.012 there, the 68 wrong reads they caught by at most 0.003
 * (docs/results.md). */
#define RL_TWINS_RANK_LEAD 0.006
/* ... and only when its lead over them through the frame's curve is more
 * than this (a global read as a local one, RL_TWINS_LOCAL_MARGIN): where
 * the formations disagree, the rank read chooses between two clear reads,
 * not for a tie. A whole 1 of a 16 px grey-mixed sheet read as 17 on the
 * renderer's ceilings (its twin 0.015 ahead through the grey levels) led
 * by 0.0004 through the curve and by 0.0060 through the rank read; the 90
 * right reads the rank read kept on the development photos' 16 px sheets
 * (seeds 1-10, gamma 2.2 / auto / 1) led through the curve by 0.0147 or
 * more (global) and 0.0109 (local). */
#define RL_TWINS_RANK_OWN RL_TWINS_LOCAL_MARGIN
/* A landmark whose circle, read through the other formation, fits this
 * much worse than its read is not judged there (an ellipse the local pass
 * read in its shape fits a circle at 0.4-0.6; the misreads the rule is for
 * fitted within 0.04), unless a lamp covers it (RL_TWINS_UNFIT_LAMP). */
#define RL_TWINS_UNFIT 0.2
/* ... a landmark so read with this share of its disk (its pixels in the
 * frame) at or above the frame's light level gets no id: a lamp hides
 * that part, and neither the local pass's sectors under it nor the rules'
 * reads of the whole ring say which id the rest is. The only two wrong
 * ids the exemption let through on the fresh sets (fifteenth session: a
 * cut 27 read as 26 at 2.2 and auto, an 11 as 8 at gamma 1, the twin
 * ahead by 0.0185 for the one, 8 no twin of 11 for the other) had 0.59 and
 * 0.67 of their disks lit; every read the exemption kept on the lens sets
 * (whole and cut ellipses at a wide-angle lens's border, no lamp) had
 * none, and no right read of the moving, glare and border sets was exempt
 * (docs/results.md). */
#define RL_TWINS_UNFIT_LAMP 0.25

/* A local read of a landmark the border cuts whose circle passes outside
 * the circle fitted to its outer edge (rl_edge_fit_rays from the read's
 * circle) by more than this share of its radius, along some direction
 * (the centres' distance plus the read's radius less the edge's), gets no
 * id: twice the outer ring's width (0.2 R, docs/landmark-spec.md), so
 * there the read puts its whole outer ring on the quiet zone round the
 * landmark. A circle fitted to what is left of a cut ring fixes centre and
 * radius loosely, and the local search can climb from it to a larger
 * circle sharing the arc in the frame, where another id fits and both
 * formations agree (a cut 19 read as 7 at gamma 1 from 1.19 of its radius,
 * its centre a third of a radius out of the frame: 0.51-0.59 there); the
 * right cut reads from every circle an edge fit could leave measured up to
 * 0.35 (test_search_twins, docs/results.md). Judged only for a read whose
 * radius is RL_TWINS_CUT_SIZE or more over the frame's other whole
 * landmarks' (rl_twins.c, rl_twins_cut_on_edge). */
#define RL_TWINS_CUT_BULGE 0.4

/* A local read of a landmark the border cuts whose circle has less than
 * this share of its code zone 1 in the frame (rl_twins_cut_zone1_shown:
 * the zone whose bit tells its twins 16 apart) keeps its id only where it
 * leads its rivals through the other formation by RL_TWINS_CUT_ZONE1_LEAD:
 * with that zone mostly out of view the part left, at the frame's edge,
 * decides between the twins, and through every curve from 1 to 4 the
 * same id (sixteenth session, second round: a cut 17 46% in view read as
 * 1 at gamma 1, its circle 2 px further out than the truth's, 0.43 of
 * zone 1 in the frame, its 2.2-curve lead 0.015; the right cut reads with
 * under half of zone 1 in view on the development and traced sets led by
 * 0.0256 or more, docs/results.md). */
#define RL_TWINS_CUT_ZONE1 0.5
#define RL_TWINS_CUT_ZONE1_LEAD 0.02

/* Code zone 1, the narrowest (next to the outer ring), narrower than this
 * many pixels: no id, whatever the reads (a landmark of ring5 under 14.2 px).
 * There a blurred edge, the pixel grid and the radius's error move a zone
 * by its width, the twins' templates fit alike, and neither formation nor
 * the rank read tells them apart: letter sheets of 10-17 px on the
 * development photos (site-check --mix grey, seeds 1-10, gamma 2.2 / auto
 * / 1) gave 53 wrong global reads, every one with zone 1 at most 1.14 px
 * (the radius read 13.46 px or less), and none above; 1.2 leaves 5%
 * (docs/results.md). */
#define RL_TWINS_MIN_ZONE_PX 1.2

/* A local read through a curve of a landmark whose code zone 1 is under
 * this many px (1.5 times the size floor's; ring5: a radius under 21.3 px)
 * meets its rivals (as does a local read of a whole landmark in a frame
 * read as linear, rl_twins.c) through the other formation at 0.91 .. 1.09 of its radius,
 * not 0.97 .. 1.03: a grey-mixed sheet read through the 2.2 curve swells its dark
 * zones and its outer edge by about 0.6 of the blur's sigma, and a white
 * zone of 1.4-2.1 px read dark (radius read 14.7-18.6 px) gave the local
 * pass's wrong ids above the floor (docs/results.md); on larger ones the
 * swell is a smaller share of a zone, and at the moving frames' 23-25 px
 * the range let a twin fit 5 of 55 right cut reads. */
#define RL_TWINS_FAR_ZONE_PX 1.8

/* A landmark whose axes' radial gradients (rl_motion) differ by less than
 * this (rl_motion's ratio above it) did not move, for rl_twins: its twins
 * are not read across a motion. Still landmarks of the clean rendered set
 * measured 0.85-1; the moving set's right reads the check refused 0.4-0.87. */
#define RL_TWINS_MOVED 0.8

/* A landmark whose outer edge fits an ellipse of aspect (minor over major)
 * under this is not read across a motion: a still one drawn slanted at
 * 0.85 measures a ratio under RL_TWINS_MOVED at 12-16 px (test_motion),
 * while a straight motion leaves a ring's outer edge round (its half
 * level stays at the radius along the motion). */
#define RL_TWINS_MOVED_ASPECT 0.9

/* The radius (px) under which a landmark of fam gets no id: its code zone
 * 1 under RL_TWINS_MIN_ZONE_PX (ring4 11.2, ring5 14.2, ring6 17.2 px).
 * A landmark over it by its radius read but under it along its minor
 * axis (a slanted one: the ellipse fitted to its outer edge), in a frame
 * read through a curve, keeps its id only while no twin leads it at all
 * through the other formation (RL_TWINS_CUT_TOLERANCE), or by the rank
 * read; only under RL_TWINS_FAR_ZONE_PX's radius (ring5 21.3 px), where no
 * read is clear by RL_TWINS_CLEAR. */
double rl_twins_min_radius(const rl_family *fam);

/* Each landmark of res that is not clear checked against its zone twins
 * through `other` (at every blur): its lead over the best of them there, plus, where that is
 * slight, its lead through the frame's own curve; one that fails the
 * rules above becomes unidentified, the others' runner_up raised to what
 * the twins came to. */
void rl_twins_check(const rl_recog *rec, const rl_image *img, const rl_tone *other, rl_result *res);

/* rl_twins_check, but a landmark i with known[i] nonzero keeps its id
 * unjudged (a window read of a landmark whose id this check kept
 * in the frame before: rl_track), unless too small for an id or a cut
 * local read whose circle lies off its outer edge (RL_TWINS_CUT_BULGE,
 * rl_twins.c's rl_twins_cut_on_edge); known NULL:
 * none. kept (NULL: not wanted), one entry per landmark of res as it came
 * in: 1 when it keeps its id. */
void rl_twins_check_known(const rl_recog *rec, const rl_image *img, const rl_tone *other, rl_result *res,
                          const unsigned char *known, unsigned char *kept);

#endif
