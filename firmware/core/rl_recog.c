/* The recognizer: configuration, workspace, and the paper's flowchart
 * (rl_recog_run), each step a call into its own module. */
#include "rl_recog.h"

#include <limits.h>
#include <math.h>
#include <string.h>
#include "rl_clr.h"
#include "rl_filter.h"
#include "rl_global.h"
#include "rl_hist.h"
#include "rl_light.h"
#include "rl_local.h"
#include "rl_recog_state.h"
#include "rl_refine.h"
#include "rl_result.h"
#include "rl_speck.h"
#include "rl_twins.h"
#include "rl_twins_lead.h"
#include "rl_verify.h"

void rl_recog_defaults(rl_recog_config *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->family.bits = 5;
    cfg->ids = NULL;
    cfg->n_ids = 0;
    cfg->min_score = 0.80;
    cfg->min_lead = 1.5;
    cfg->local_min_score = 0.75;
    cfg->local_min_lead = 1.3;
    cfg->min_radius = 0.0;
    cfg->max_radius = 0.0;
    cfg->size_tolerance = 0.35;
    cfg->need = 2;
    cfg->local = RL_LOCAL_ALWAYS;
    cfg->near_light = 1.5;
    cfg->local_min_first = RL_LOCAL_MIN_FIRST;
    cfg->min_contrast = 0.5;
    cfg->gamma = 0.0;
}

void rl_recog_use_map(rl_recog_config *cfg, const rl_map *map, int *ids)
{
    int i, j, n = 0;
    cfg->family = map->family;
    for (i = 0; i < map->count; i++) {
        /* each id once: a large site's map repeats them */
        for (j = 0; j < n && ids[j] != map->lm[i].id; j++)
            ;
        if (j < n)
            continue;
        if (n == RL_MAX_IDS) {
            n++; /* more than any family holds: rl_recog_init says RL_ELIMIT */
            break;
        }
        ids[n++] = map->lm[i].id;
    }
    cfg->ids = ids;
    cfg->n_ids = n;
}

static int cap_runs(int w, int h)
{
    long n = (long)w * h / RL_PIXELS_PER_RUN;
    return n < 1024 ? 1024 : (int)n;
}

static rl_err check_config(const rl_recog_config *cfg, int w, int h)
{
    int i;
    if (w <= 0 || h <= 0 || w > RL_MAX_IMAGE_DIM || h > RL_MAX_IMAGE_DIM)
        return RL_EINVAL;
    if (cfg->family.bits < RL_FAMILY_MIN_BITS || cfg->family.bits > RL_MAX_BITS)
        return RL_ERANGE;
    if (cfg->ids != NULL) {
        if (cfg->n_ids <= 0)
            return RL_EINVAL;
        if (cfg->n_ids > RL_MAX_IDS)
            return RL_ELIMIT;
        for (i = 0; i < cfg->n_ids; i++)
            if (!rl_family_valid(&cfg->family, cfg->ids[i]))
                return RL_ERANGE;
    }
    if (!(cfg->min_radius >= 0) || !(cfg->max_radius >= 0) || !(cfg->min_score > 0) ||
        cfg->min_score > 1 || !(cfg->local_min_score > 0) || cfg->local_min_score > 1 ||
        !(cfg->min_lead >= 1) || !(cfg->local_min_lead >= 1) || !(cfg->min_contrast >= 0) ||
        !(cfg->size_tolerance > 0) || !(cfg->near_light >= 0) || cfg->need < 1 ||
        !(cfg->gamma == 0.0 || (cfg->gamma >= 1.0 && cfg->gamma <= 3.0)))
        return RL_EINVAL;
    return RL_OK;
}

/* The one allocation sequence, shared by sizing (ws counts) and init:
 * the recognizer itself at the start of the block, then its arrays
 * (into *rec, or into a scratch copy when sizing hands out nothing). */
static rl_err layout(rl_ws *ws, const rl_recog_config *cfg, int w, int h, rl_recog **rec,
                     rl_recog *scratch)
{
    rl_recog *r;
    rl_err e;
    int runs = cap_runs(w, h);
    if ((e = rl_ws_alloc(ws, sizeof(rl_recog), RL_WS_ALIGN, (void **)rec)) != RL_OK)
        return e;
    r = *rec ? *rec : scratch;
    if ((e = rl_templates_init(&r->templates, ws, &cfg->family, cfg->ids, cfg->ids ? cfg->n_ids : 0)) != RL_OK ||
        (e = cfg->skip_rivals ? rl_rivals_none(&r->rivals) : rl_rivals_init(&r->rivals, ws, &r->templates)) != RL_OK ||
        (e = rl_label_init(&r->dark, ws, w, h, runs, RL_MAX_REGIONS)) != RL_OK ||
        (e = rl_label_init(&r->light, ws, w, (h + 1) / 2, runs / 4, RL_MAX_LIGHTS * 8)) != RL_OK ||
        (e = rl_illum_init(&r->illum, ws, w, h)) != RL_OK ||
        (e = rl_split_init(&r->split, ws, &r->illum.map)) != RL_OK ||
        (e = rl_ws_alloc(ws, sizeof(rl_polar), RL_WS_ALIGN, (void **)&r->polar)) != RL_OK ||
        (e = rl_match_kept_init(&r->kept, ws, &r->templates)) != RL_OK ||
        (e = rl_ws_alloc(ws, RL_MAX_CANDIDATES * sizeof(rl_recog_placed), RL_WS_ALIGN, (void **)&r->placed)) != RL_OK)
        return e;
    return RL_OK;
}

size_t rl_recog_workspace_size(int w, int h, const rl_recog_config *cfg)
{
    rl_ws ws;
    rl_recog scratch, *rec;
    if (cfg == NULL || check_config(cfg, w, h) != RL_OK)
        return 0;
    rl_ws_init_sizing(&ws);
    if (layout(&ws, cfg, w, h, &rec, &scratch) != RL_OK)
        return 0;
    return ws.peak;
}

/* The configuration as the recognizer keeps it: ids copied, radius limits
 * resolved. */
static void resolve_config(rl_recog *rec, const rl_recog_config *cfg, int w, int h)
{
    rec->cfg = *cfg;
    if (cfg->ids != NULL) {
        memcpy(rec->ids, cfg->ids, (size_t)cfg->n_ids * sizeof(int));
        rec->cfg.ids = rec->ids; /* the caller's array need not outlive init */
    }
    if (rec->cfg.max_radius <= 0)
        rec->cfg.max_radius = (w < h ? w : h) / 2.0;
    if (rec->cfg.min_radius <= 0) {
        /* below this radius code zone 1, the narrowest, is under a pixel
         * wide and the code cannot be read */
        int n = cfg->family.bits;
        rec->cfg.min_radius = 1.0 / (RL_OUTER_RING_INNER * (1.0 - sqrt((double)(n - 1) / n)));
    }
    rl_tones_init(&rec->tones, cfg->gamma);
    rec->tone = rl_tones_current(&rec->tones);
    rec->width = w;
    rec->height = h;
}

rl_err rl_recog_init(rl_recog **out, const rl_recog_config *cfg, int w, int h, void *mem,
                     size_t size)
{
    rl_recog *rec;
    rl_ws ws;
    rl_err e;
    if (out == NULL || cfg == NULL || mem == NULL)
        return RL_EINVAL;
    *out = NULL;
    if ((e = check_config(cfg, w, h)) != RL_OK)
        return e;
    if (size < rl_recog_workspace_size(w, h, cfg))
        return RL_ENOMEM;
    rl_ws_init(&ws, mem, size);
    if ((e = layout(&ws, cfg, w, h, &rec, NULL)) != RL_OK)
        return e;
    /* the arrays are carved; the rest of the recognizer is filled in */
    resolve_config(rec, cfg, w, h);
    rl_verify_init(rec);
    rl_twins_led_init(rec);
    *out = rec;
    return RL_OK;
}

void rl_recog_frame_size(const rl_recog *rec, int *w, int *h)
{
    *w = rec->width;
    *h = rec->height;
}

/* 1. histogram analysis: light sources, foreground and background; 0 when
 * the frame has no dark class (nothing to find). */
static int analyse_histogram(const rl_image *img, const rl_tone *tone, rl_result *res)
{
    rl_hist h;
    /* every fourth row suffices for the levels (76,800 pixels of a 640 x 480
     * frame), every other or every row in small frames */
    rl_hist_compute_rows(img, &h, img->height >= 240 ? 4 : img->height >= 120 ? 2 : 1);
    if (rl_hist_levels(&h, tone, &res->levels) != RL_OK)
        return 0; /* a frame that is all light */
    return 1;
}

/* Read the outer CLRs (a CLR inside another's box of the same batch is an
 * inner ring; rl_split leaves out the code rings of a batch read before)
 * through tone t into res (landmarks and unidentified), each as read into
 * rec->placed (the tone reads'). Returns how many are identified; into
 * *outer when outer is not NULL the count of the outer ones any curve may
 * identify (rl_global_readable: not those the border cuts by more than a
 * sliver). */
static int read_clrs(rl_recog *rec, const rl_image *img, const rl_clr *cand, int n, int t, rl_result *res,
                     int *outer)
{
    int i, found = 0, seen = 0;
    for (i = 0; i < n; i++) {
        rl_detection d;
        rec->placed[i].read = -1;
        if (rl_clr_is_inner(cand, n, i))
            continue;
        rl_global_read(rec, img, &cand[i], &rec->tones.tone[t], res, &d);
        rec->placed[i].u = d.u;
        rec->placed[i].v = d.v;
        if (rl_global_readable(&cand[i], rec->width, rec->height)) {
            rec->placed[i].read = d.id >= 0;
            seen++;
        }
        found += d.id >= 0;
        res->n_candidates++;
        if (d.id >= 0)
            rl_result_add_landmark(res, &d);
        else
            rl_result_add_unidentified(res, &d);
    }
    if (outer != NULL)
        *outer = seen;
    return found;
}

/* The tone reads: the n_outer outer CLRs a curve may identify (rec->placed,
 * as read_clrs read them through the current curve) counted through tone
 * t from the centres the global pass placed them at (not refined again:
 * rl_global_read_placed), the current curve having identified `current`
 * of them; the others (cut by the border, id -1 through every curve) are
 * not read. The reads stop once the rest cannot change the vote
 * (rl_tones_decided), and the count so far is returned. That count decides
 * the vote whatever order the CLRs are read in (a full count is the same
 * in any order, and one cut short is cut short on the vote's side), so
 * those the current curve did not identify are read first: on most frames
 * the other curve misses them too, and once it has missed as many as the
 * current curve did the vote is decided, the rest unread. */
static int count_other(rl_recog *rec, const rl_image *img, const rl_clr *cand, int n, int t, int current,
                       int n_outer, const rl_result *res)
{
    int i, pass, found = 0, left = n_outer;
    for (pass = 0; pass < 2; pass++)
        for (i = 0; i < n && !rl_tones_decided(current, found, left); i++) {
            rl_detection d;
            if (rec->placed[i].read != pass)
                continue;
            left--;
            rl_global_read_placed(rec, img, &cand[i], &rec->tones.tone[t], res, rec->placed[i].u,
                                  rec->placed[i].v, &d);
            found += d.id >= 0;
        }
    return found;
}

/* What read_clrs adds to res, to be taken back (rl_global_read reads
 * only res's lights, which it leaves as they are). */
typedef struct {
    int n_landmarks, n_unidentified, n_candidates, dropped_landmarks, dropped_candidates;
} reads_mark;

static reads_mark mark_reads(const rl_result *res)
{
    reads_mark m = {res->n_landmarks, res->n_unidentified, res->n_candidates, res->dropped.landmarks,
                    res->dropped.candidates};
    return m;
}

static void undo_reads(rl_result *res, const reads_mark *m)
{
    res->n_landmarks = m->n_landmarks;
    res->n_unidentified = m->n_unidentified;
    res->n_candidates = m->n_candidates;
    res->dropped.landmarks = m->dropped_landmarks;
    res->dropped.candidates = m->dropped_candidates;
}

/* 4. identification of the outer CLRs through the camera's tone curve
 * (returned, as an index into rec->tones):
 * the configured one, or, while it is being learned, the one the frame's
 * landmarks read best through (rl_tones.h). The current curve is read
 * into res (the global pass); while the curve is open the other is read
 * too, counting only (the tone reads) and only until the rest of its
 * reads could not change the vote (rl_tones_decided: on most frames once
 * it has missed as many as the current curve), and only when the vote takes the
 * other for this frame (seldom) are the current curve's reads taken back
 * and the other's read into res: two reads of a frame's candidates while
 * the curve is open (three at most), one after. */
static int identify_clrs(rl_recog *rec, const rl_image *img, const rl_clr *cand, int n,
                          rl_result *res)
{
    const rl_stage_hook *hook = &rec->cfg.stage_hook;
    int which[RL_TONES_MAX], found[RL_TONES_MAX], nt = rl_tones_to_try(&rec->tones, which), t, outer;
    reads_mark before = mark_reads(res);
    rl_stage_enter(hook, RL_STAGE_GLOBAL);
    found[0] = read_clrs(rec, img, cand, n, which[0], res, &outer);
    if (nt > 1)
        rl_stage_enter(hook, RL_STAGE_TONES);
    for (t = 1; t < nt; t++)
        found[t] = count_other(rec, img, cand, n, which[t], found[0], outer, res);
    t = rl_tones_vote(&rec->tones, which, nt, found);
    if (t != 0) {
        undo_reads(res, &before);
        read_clrs(rec, img, cand, n, which[t], res, NULL);
    }
    t = which[t];
    rec->tone = &rec->tones.tone[t];
    res->gamma = rec->tones.gamma[t];
    return t;
}

/* 4b. the new CLRs of the second labellings (rl_split), read through the
 * frame's tone curve t into res (cand is reused). */
static void read_second_labellings(rl_recog *rec, const rl_image *img, int speck, int t,
                                   rl_clr *cand, rl_result *res)
{
    int n = rl_split_find(&rec->split, &rec->dark, img, &rec->cfg, speck, res, cand,
                          RL_MAX_CANDIDATES);
    read_clrs(rec, img, cand, n, t, res, NULL);
}

static int local_wanted(const rl_recog_config *cfg, const rl_result *res)
{
    return cfg->local == RL_LOCAL_ALWAYS ||
           (cfg->local == RL_LOCAL_AUTO && res->n_landmarks < cfg->need);
}

/* Each whole landmark the global pass read from a round region gets its
 * radius from both edges of its outer band (rl_recog_config.band_radius). */
static void band_radii(const rl_recog *rec, const rl_image *img, rl_result *res)
{
    int i;
    for (i = 0; i < res->n_landmarks; i++) {
        rl_detection *d = &res->landmarks[i];
        if (d->band_ready)
            rl_refine_radius_band(img, rec->tone, &rec->cfg.family, d->id, d->u, d->v, &d->radius);
    }
}

/* The frame through the stages of rl_stage.h, in their order; each
 * announced to the configuration's hook as it begins. */
static rl_err run_stages(rl_recog *rec, const rl_image *img, rl_result *res)
{
    const rl_stage_hook *hook = &rec->cfg.stage_hook;
    rl_clr cand[RL_MAX_CANDIDATES];
    int ncand, speck, t;
    rl_err e;
    rl_result_clear(res, rec->width, rec->height);
    res->gamma = rl_tones_gamma(&rec->tones);
    speck = rl_speck_area(&rec->cfg);

    /* 1. histogram analysis, and the light sources it finds */
    rl_stage_enter(hook, RL_STAGE_HIST);
    if (!analyse_histogram(img, rec->tone, res))
        return RL_OK;
    if ((e = rl_light_find(&rec->light, img, res->levels.light, speck, res)) != RL_OK)
        return e;
    if (res->levels.threshold <= 0)
        return RL_OK; /* no dark class in the frame */
    /* 2. image clustering into dark ROIs, as connected regions, under the
     *    threshold scaled by the ceiling's light across the frame */
    rl_stage_enter(hook, RL_STAGE_LABEL);
    rl_illum_measure(&rec->illum, img, &res->levels);
    if ((e = rl_label_dark(&rec->dark, img, &rec->illum.map, speck)) != RL_OK)
        return e;
    res->n_regions = rec->dark.n_regions;
    /* regions never examined: past the capacity, or in rows past the
     * run capacity (at least one there) */
    res->dropped.regions = rec->dark.overflow + (rec->dark.rows_left > 0);
    /* 3. CLR extraction; the regions where the frame's thresholds may have
     *    failed a landmark marked for a second labelling */
    rl_stage_enter(hook, RL_STAGE_CLR);
    ncand = rl_clr_find(&rec->dark, &rec->cfg, res, cand, RL_MAX_CANDIDATES);
    rl_split_mark(&rec->split, &rec->dark, cand, ncand, &rec->cfg);
    /* 4. identification: ICLRs and UCLRs (tone reads, then the global
     *    pass); then the new CLRs of the second labellings, through the
     *    same tone curve */
    t = identify_clrs(rec, img, cand, ncand, res);
    rl_stage_enter(hook, RL_STAGE_SECOND);
    read_second_labellings(rec, img, speck, t, cand, res);
    rl_filter_duplicates(res);
    /* 5. local recognition of the DUCLRs (its reads across the motion
     *    announced by rl_local) */
    if (local_wanted(&rec->cfg, res)) {
        rl_stage_enter(hook, RL_STAGE_LOCAL);
        rl_local_pass(rec, img, res);
        rl_filter_duplicates(res);
    }
    /* no landmark whose zone twin reads as well through the other image
     * formation (grey levels mixed, or light), learned curve or not */
    if (res->n_landmarks > 0) {
        rl_stage_enter(hook, RL_STAGE_TWINS);
        rl_twins_check(rec, img, rl_tones_other(&rec->tones, rec->tone), res);
    }
    /* 6. the frame's landmarks: consistent sizes, their band radii when
     *    asked for (after every id is decided: no judgement sees them),
     *    in order */
    rl_filter_size(res, rec->cfg.size_tolerance);
    if (rec->cfg.band_radius)
        band_radii(rec, img, res);
    rl_filter_sort(res);
    return RL_OK;
}

rl_err rl_recog_run(rl_recog *rec, const rl_image *img, rl_result *res)
{
    rl_err e;
    if (rec == NULL || res == NULL || img == NULL || !rl_image_valid(img))
        return RL_EINVAL;
    if (img->width != rec->width || img->height != rec->height || img->stride > INT_MAX / 2)
        return RL_EINVAL;
    e = run_stages(rec, img, res);
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_DONE);
    return e;
}
