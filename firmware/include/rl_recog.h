/* rl_recog: landmark recognition, the paper's bilayer method.
 *
 * Global pass over the whole frame: histogram analysis (light sources,
 * background and foreground levels), K-means clustering into dark regions
 * of interest (ROIs), connected regions, candidate landmark regions (CLRs:
 * outer rings found by shape and bounding-box containment), identification
 * by Pearson correlation (ICLR identified, UCLR not). Local pass (when too
 * few were identified, or always): UCLRs near a light or on the image
 * border (DUCLRs) are re-clustered in an enlarged window of the input
 * frame and identified again, border-cut ones against cut templates.
 *
 * Allocation-free: the recognizer and every buffer it uses live in the
 * block given to rl_recog_init, whose size rl_recog_workspace_size()
 * tells. Nothing is cut silently: whatever a compile-time limit
 * (rl_config.h) drops is counted in rl_result.dropped.
 *
 *   static unsigned char mem[4 << 20];
 *   static rl_result res;                     // large: not on a small stack
 *   rl_recog_config cfg;
 *   rl_recog *rec;
 *   rl_recog_defaults(&cfg);                  // ring5, every id
 *   if (rl_recog_workspace_size(640, 480, &cfg) <= sizeof mem &&
 *       rl_recog_init(&rec, &cfg, 640, 480, mem, sizeof mem) == RL_OK &&
 *       rl_recog_run(rec, &frame, &res) == RL_OK)
 *       use(res.n_landmarks, res.landmarks);
 */
#ifndef RL_RECOG_H
#define RL_RECOG_H

#include "rl_config.h"
#include "rl_error.h"
#include "rl_family.h"
#include "rl_image.h"
#include "rl_map.h"
#include "rl_stage.h"
#include "rl_workspace.h"

typedef enum {
    RL_LOCAL_AUTO = 0,   /* as the paper: only when fewer than `need` were identified */
    RL_LOCAL_ALWAYS = 1, /* retry every DUCLR (more landmarks, better pose) */
    RL_LOCAL_NEVER = 2   /* global pass only */
} rl_local_policy;

typedef enum { RL_PASS_GLOBAL = 0, RL_PASS_LOCAL = 1 } rl_pass;

/* Histogram analysis and clustering of a frame. */
typedef struct {
    int light;         /* light-source threshold: pixels >= light are light; 256 = none */
    int threshold;     /* ROI threshold: pixels < threshold are dark (foreground) */
    double fg, bg;     /* mean foreground and background levels */
    double centre[3];  /* K-means centres, ascending */
    int k;             /* clusters used */
} rl_levels;

typedef struct {
    rl_family family;     /* landmark family (default ring5) */
    const int *ids;       /* ids to recognize (a map's); NULL = every id */
    int n_ids;
    /* Acceptance of an id, one rule for both passes (rl_accept.h): */
    double min_score;     /* global pass: Pearson correlation to accept an id (0.80) */
    double min_lead;      /* global pass: runner-up's residual (1 - r^2) over the best's (1.5) */
    double local_min_score; /* local pass: the same (0.75): a DUCLR is re-extracted and */
    double local_min_lead;  /* centred on its own edge, so a little less is needed (1.3) */
    double min_contrast;  /* fitted ink/paper contrast, fraction of the grey span
                             (global: the frame's background - foreground; local: the
                             sector-normalized span, and at least RL_ACCEPT_LOCAL_SHARE
                             0.3 of the frame's span in the plain profile) (default 0.5) */
    double min_radius;    /* smallest landmark radius considered, px; 0 (default) = where
                             code zone 1 is 1 px wide (11.8 px for ring5) */
    double max_radius;    /* largest, px; 0 = half the shorter image side */
    double size_tolerance;/* identified radii within this fraction of the frame's median (0.35) */
    int need;             /* landmarks a pose needs (default 2) */
    rl_local_policy local;/* when the local pass runs (default RL_LOCAL_ALWAYS: on real
                             ceilings half the landmarks next to lights and most cut ones
                             are found only there, at a fraction of the frame's time) */
    double near_light;    /* DUCLR: gap to a light of at most this many radii (default 1.5) */
    double local_min_first; /* local pass: a whole DUCLR whose first match and the search's
                               step out both score under this is read no further, nor a cut
                               one's read at its box once no other read took it (default
                               0.5, RL_LOCAL_MIN_FIRST; -INFINITY: every one read on) */
    int band_radius;      /* 1: an identified whole landmark's radius from both edges of its
                             outer black band, which no blur or tone curve biases (a
                             survey's scale; some 2-8% more time), refined after every id
                             is decided, so the ids are the default's; 0 (default): from
                             its outer edge (the pose does not use it) */
    double gamma;         /* the camera's tone curve, grey = 255 (light / white)^(1 / gamma):
                             2.2 for the sRGB-like output of most cameras (V4L2,
                             libcamera, webcams), 1 for one that outputs linear light
                             (machine-vision cameras with gamma off); 1 .. 3, or 0
                             (default): learned from the landmarks, between 2.2 and 1.
                             Blur and motion mix light, so identification reads light
                             (the curve undone); an id whose zone twin reads as well
                             with grey levels mixed after the curve (scaling, JPEG,
                             sharpening) is not reported, whatever the curve */
    rl_stage_hook stage_hook; /* called as each stage of a frame begins (rl_stage.h);
                                 none by default */
    int skip_rivals;      /* 1: a tracked window's rivals (rl_rivals) are not worked out at
                             init (some 14 ms for ring5, n^2 in the ids; rl_recog_run never
                             uses them, and a known window then matches every id): for a
                             recognizer built often, as a fuzzer's; 0 (default): worked out */
} rl_recog_config;

typedef struct {
    int x0, y0, x1, y1; /* inclusive bounding box, px */
} rl_box;

typedef struct {
    int id;             /* landmark id, -1 for an unidentified candidate */
    double u, v;        /* centre in the image, px */
    double radius;      /* outer radius, px */
    double score;       /* Pearson correlation of the best id */
    double runner_up;   /* how close the nearest other reading came: score less the
                           least lead the id held, over any other id through the frame's
                           curve and over its zone twins through the other image
                           formation (rl_recog_config.gamma); below score for every
                           reported id but one whose zone twin reads within the
                           tolerance rl_twins grants (at most 0.006 over) */
    rl_pass pass;       /* which pass identified it */
    int complete;       /* 0 if the image border cuts it */
    rl_box box;         /* outer ring's bounding box */
    double visible;     /* fraction of the disk inside the image */
    int best_id;        /* the id that read best, taken or not (-1: none read); an
                           unidentified candidate's says what it nearly was */
    int band_ready;     /* internal: 1 for a whole global read from a round region
                           when rl_recog_config.band_radius is set, whose radius
                           rl_recog_run takes from the band once every id is decided
                           (tracking's reads take none) */
    int twins_led;      /* internal: 1 when the read that took the id found it ahead of
                           its zone twins beside its own radius, from the pixels it read:
                           a global read clear of every id (rl_twins.h, RL_TWINS_CLEAR)
                           at 0.97 of its radius (rl_twins_led_read); 1 for every
                           window read rl_verify takes (it met the twins at 0.95 .. 1.05
                           where the id led its runner-up, every id or a known one's
                           rivals, by under 0.1); rl_twins judges a clear global read
                           without it as any other */
} rl_detection;

/* What a compile-time limit (rl_config.h) left out of one frame's result. */
typedef struct {
    int regions;       /* dark regions past RL_MAX_REGIONS, plus one when rows past the
                          run capacity were left out (never examined) */
    int lights;        /* light regions past RL_MAX_LIGHTS, plus one when rows past the
                          run capacity were left out */
    int candidates;    /* CLRs past RL_MAX_CANDIDATES, unidentified ones included, and
                          arcs of broken rings past the 48 kept for pairing */
    int landmarks;     /* identified landmarks past RL_MAX_LANDMARKS */
} rl_dropped;

typedef struct {
    int width, height;
    rl_levels levels;   /* histogram analysis and clustering */
    int n_landmarks;    /* identified (ICLR), in order of u then v */
    rl_detection landmarks[RL_MAX_LANDMARKS];
    int n_unidentified; /* UCLR left after both passes */
    rl_detection unidentified[RL_MAX_CANDIDATES];
    int n_candidates;   /* CLRs the global pass found */
    int n_regions;      /* dark regions after speck removal */
    int n_lights;
    rl_box lights[RL_MAX_LIGHTS];
    int local_tried;    /* DUCLRs the local pass retried */
    int local_found;    /* of those, identified */
    int local_floored;  /* of those, whole ones read no further (local_min_first) */
    int local_box_floored; /* of those, cut ones whose read at their box, after no other read took
                              them, went no further (local_min_first) */
    double gamma;       /* the tone curve the frame was read through (rl_recog_config.gamma:
                           the configured one, or the one learned) */
    rl_dropped dropped; /* what the limits left out (all 0 on ordinary frames) */
} rl_result;

/* The recognizer: opaque, it lives at the start of the caller's block. */
typedef struct rl_recog rl_recog;

/* Fill every field with its default (ring5, every id). */
void rl_recog_defaults(rl_recog_config *cfg);

/* Recognize the landmarks of a map only: family and ids from it, each id
 * once (a map may repeat them). `ids` (RL_MAX_IDS) holds the ids until
 * rl_recog_init copies them. */
void rl_recog_use_map(rl_recog_config *cfg, const rl_map *map, int *ids);

/* Workspace bytes for frames of w x h with this configuration; 0 if the
 * configuration is invalid. */
size_t rl_recog_workspace_size(int w, int h, const rl_recog_config *cfg);

/* Prepare for frames of w x h in mem[0..size): *rec points into mem and
 * stays valid while mem does. RL_ENOMEM if size is less
 * than rl_recog_workspace_size(), RL_EINVAL / RL_ERANGE for a bad
 * configuration (ids outside the family, sizes), RL_ELIMIT for more ids
 * than RL_MAX_IDS. */
RL_CHECK rl_err rl_recog_init(rl_recog **rec, const rl_recog_config *cfg, int w, int h,
                              void *mem, size_t size);

/* The frame size a recognizer was made for. */
void rl_recog_frame_size(const rl_recog *rec, int *w, int *h);

/* Recognize the landmarks of one frame (same size as at init; any
 * stride). RL_EINVAL for a NULL argument or a wrong size; RL_ELIMIT when
 * the frame holds more dark runs than the workspace (a frame of noise). */
RL_CHECK rl_err rl_recog_run(rl_recog *rec, const rl_image *img, rl_result *res);

#endif
