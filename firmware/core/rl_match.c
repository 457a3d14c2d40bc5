#include "rl_match.h"

#include <math.h>
#include <string.h>
#include "rl_match_kernel.h"

/* What every column's correlation shares: the profile's pixels, their
 * sum and 1 / sqrt of their variance term, and its bins in single
 * precision for the kernel. */
typedef struct {
    double n, sx, ivx;
    float fn[RL_PROFILE_BINS], fs[RL_PROFILE_BINS];
} profile_terms;
/* Pearson's r of one column from its sums, kept as best or runner-up (of
 * any other id). A column that cannot beat the runner-up is dropped
 * before its square root. */
static void keep_column(rl_match *m, const profile_terms *z, int id, int blur, double st,
                        double stt, double sxt)
{
    double vt = z->n * stt - st * st, num, r;
    if (vt <= 0)
        return;
    num = z->n * sxt - z->sx * st;
    if (m->second >= 0 &&
        (num <= 0 || num * num * z->ivx * z->ivx <= m->second * m->second * vt))
        return;
    r = num * z->ivx / sqrt(vt);
    if (r > m->score) {
        if (id != m->id)
            m->second = m->score;
        m->score = r;
        m->id = id;
        m->contrast = num / vt; /* the fitted gain */
        m->blur = blur;
    } else if (r > m->second && id != m->id) {
        m->second = r;
    }
}

/* The match before any column is scored; 0 when the profile cannot
 * correlate with anything (too few pixels, flat), else its terms in *z. */
static int match_start(const rl_profile *p, profile_terms *z, rl_match *m)
{
    double n = p->total, sx, vx;
    int k;
    m->id = -1;
    m->score = m->second = -1.0;
    m->contrast = 0.0;
    m->blur = 0;
    if (n < 16)
        return 0;
    {
        /* two partial sums: half the chain of dependent adds */
        double s0 = 0, s1 = 0;
        for (k = 0; k < RL_PROFILE_BINS; k += 2) {
            s0 += p->sx[k];
            s1 += p->sx[k + 1];
        }
        sx = s0 + s1;
    }
    vx = n * (p->sxx - p->plane) - sx * sx;
    if (!(vx > 0))
        return 0; /* a flat candidate correlates with nothing */
    z->n = n;
    z->sx = sx;
    z->ivx = 1.0 / sqrt(vx);
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        z->fn[k] = (float)p->n[k];
        z->fs[k] = (float)p->sx[k];
    }
    /* a bin with no pixel has no darkness: the 8-lane kernel adds it
     * (rl_match_kernel.h); a loop of its own, in vectors */
    for (k = 0; k < RL_PROFILE_BINS; k++)
        z->fs[k] = z->fn[k] == 0 ? 0.0f : z->fs[k];
    return 1;
}

/* Score the block of columns at t (bin stride `stride`) and keep the
 * first nc, column c being id ids[c] at blur blurs[c]. */
static void score_block(const float *t, size_t stride, int nc, const int *ids, const int *blurs,
                        const profile_terms *z, rl_match *m)
{
    float st[RL_MATCH_BLOCK], stt[RL_MATCH_BLOCK], sxt[RL_MATCH_BLOCK];
    int c;
    rl_match_kernel(t, stride, z->fn, z->fs, st, stt, sxt);
    for (c = 0; c < nc; c++)
        keep_column(m, z, ids[c], blurs[c], st[c], stt[c], sxt[c]);
}

/* Columns the wide kernel scores at a time. */
#define WIDE_COLUMNS (RL_MATCH_WIDE * RL_MATCH_BLOCK)

/* Every column of the table scored against the profile's terms z, in
 * table order, as wide a block at a time as the table holds (each
 * column's sums the same bits either way); id's columns kept in *own and
 * the rest in *m, or all in *m when own is NULL. Where keep is not NULL
 * the sums are copied into it (column c at c) rather than thrown away.
 * 0 as soon as a block leaves m's score over stop (the rest not scored;
 * +INFINITY: never), else 1. */
static inline int score_table(const rl_templates *tt, const profile_terms *z, int id, rl_match *own, rl_match *m,
                              rl_match_kept *keep, double stop)
{
    int ncol = tt->n * RL_BLUR_LEVELS, c0, c, i = 0, b = 0;
    for (c0 = 0; c0 < ncol;) {
        float st[WIDE_COLUMNS], stt[WIDE_COLUMNS], sxt[WIDE_COLUMNS];
        int nc, nk; /* columns kept, and the kernel's (whole blocks) */
        if (c0 + WIDE_COLUMNS <= tt->stride && ncol - c0 > WIDE_COLUMNS - RL_MATCH_BLOCK) {
            const float *blocks[RL_MATCH_WIDE];
            nc = ncol - c0 < WIDE_COLUMNS ? ncol - c0 : WIDE_COLUMNS;
            for (c = 0; c < RL_MATCH_WIDE; c++)
                blocks[c] = tt->table + c0 + c * RL_MATCH_BLOCK;
            rl_match_kernel_wide(blocks, RL_MATCH_WIDE, (size_t)tt->stride, z->fn, z->fs, st, stt, sxt);
            nk = WIDE_COLUMNS;
        } else {
            nc = ncol - c0 < RL_MATCH_BLOCK ? ncol - c0 : RL_MATCH_BLOCK;
            rl_match_kernel(tt->table + c0, (size_t)tt->stride, z->fn, z->fs, st, stt, sxt);
            nk = RL_MATCH_BLOCK;
        }
        if (keep) {
            /* the kernel's whole blocks copied (within the stride: c0 + nk
             * <= stride); scored from the stack as without (the compiler
             * moves three pointers a column over the kept arrays, 2 more
             * instructions a column) */
            if (nk == WIDE_COLUMNS) {
                memcpy(keep->st + c0, st, sizeof st);
                memcpy(keep->stt + c0, stt, sizeof stt);
                memcpy(keep->sxt + c0, sxt, sizeof sxt);
            } else {
                memcpy(keep->st + c0, st, RL_MATCH_BLOCK * sizeof *st);
                memcpy(keep->stt + c0, stt, RL_MATCH_BLOCK * sizeof *stt);
                memcpy(keep->sxt + c0, sxt, RL_MATCH_BLOCK * sizeof *sxt);
            }
        }
        for (c = 0; c < nc; c++) {
            keep_column(own != NULL && tt->ids[i] == id ? own : m, z, tt->ids[i], b, st[c], stt[c], sxt[c]);
            if (++b == RL_BLUR_LEVELS) {
                b = 0;
                i++;
            }
        }
        if (m->score > stop)
            return 0;
        c0 += nc;
    }
    return 1;
}

void rl_match_all(const rl_templates *tt, const rl_profile *p, rl_match *m)
{
    profile_terms z;
    if (match_start(p, &z, m))
        (void)score_table(tt, &z, -1, NULL, m, NULL, INFINITY);
}

size_t rl_match_kept_bytes(int columns)
{
    /* as rl_match_kept_init carves them, each with its worst padding */
    return sizeof(rl_match_kept) + RL_WS_ALIGN - 1 + (size_t)columns * 3 * sizeof(float) + RL_WS_ALIGN - 1;
}

rl_err rl_match_kept_init(rl_match_kept **out, rl_ws *ws, const rl_templates *tt)
{
    rl_match_kept *k;
    float *sums;
    size_t cols = (size_t)tt->stride;
    rl_err e;
    if ((e = rl_ws_alloc(ws, sizeof *k, RL_WS_ALIGN, (void **)&k)) != RL_OK ||
        (e = rl_ws_alloc(ws, cols * 3 * sizeof *sums, RL_WS_ALIGN, (void **)&sums)) != RL_OK)
        return e;
    *out = k;
    if (k == NULL)
        return RL_OK; /* sizing: nothing handed out */
    k->state = RL_MATCH_KEPT_NONE; /* none kept yet: a profile is read */
    k->columns = tt->stride;
    k->n = k->sx = k->ivx = 0;
    k->st = sums;
    k->stt = sums + cols;
    k->sxt = sums + 2 * cols;
    return RL_OK;
}

void rl_match_all_kept(const rl_templates *tt, const rl_profile *p, rl_match *m, rl_match_kept *keep)
{
    profile_terms z;
    keep->state = RL_MATCH_KEPT_FLAT;
    if (!match_start(p, &z, m))
        return;
    if (tt->stride > keep->columns) {
        keep->state = RL_MATCH_KEPT_NONE; /* past the room: rl_match_kept_ids reads the profile again */
        (void)score_table(tt, &z, -1, NULL, m, NULL, INFINITY);
        return;
    }
    keep->state = RL_MATCH_KEPT_SUMS;
    keep->n = z.n;
    keep->sx = z.sx;
    keep->ivx = z.ivx;
    (void)score_table(tt, &z, -1, NULL, m, keep, INFINITY);
}

/* How far a column must score over id's best to end rl_match_all_kept_as's
 * walk: none at all, but for sums that were not the same bits. */
#define AS_MARGIN 1e-9

int rl_match_all_kept_as(const rl_templates *tt, const rl_profile *p, int id, int max_blur, rl_match *m,
                         rl_match_kept *keep)
{
    profile_terms z;
    rl_match own, blurrier;
    float st[RL_MATCH_BLOCK], stt[RL_MATCH_BLOCK], sxt[RL_MATCH_BLOCK];
    int i = rl_templates_find(tt, id), b;
    if (i < 0 || i * RL_BLUR_LEVELS + RL_MATCH_BLOCK > tt->stride || tt->stride > keep->columns) {
        rl_match_all_kept(tt, p, m, keep);
        return 1;
    }
    keep->state = RL_MATCH_KEPT_FLAT;
    if (!match_start(p, &z, m))
        return 1;
    /* id's best score up to max_blur, and blurrier, from its own block (a
     * column's sums the same bits as in the table's walk): once any column
     * scores over the first, the walk's winner is none of them (its score
     * only rises, and a column it passes over scores under its runner-up) */
    own = blurrier = *m;
    rl_match_kernel(tt->table + (size_t)i * RL_BLUR_LEVELS, (size_t)tt->stride, z.fn, z.fs, st, stt, sxt);
    for (b = 0; b < RL_BLUR_LEVELS; b++)
        keep_column(b <= max_blur ? &own : &blurrier, &z, id, b, st[b], stt[b], sxt[b]);
    keep->state = RL_MATCH_KEPT_SUMS;
    keep->n = z.n;
    keep->sx = z.sx;
    keep->ivx = z.ivx;
    if (own.id < 0 || (blurrier.id >= 0 && blurrier.score > own.score + AS_MARGIN) ||
        !score_table(tt, &z, -1, NULL, m, keep, own.score + AS_MARGIN)) {
        keep->state = RL_MATCH_KEPT_NONE; /* the sums only in part */
        return 0;
    }
    return 1;
}

void rl_match_id_and_rest(const rl_templates *tt, const rl_profile *p, int id, rl_match *own, rl_match *rest)
{
    profile_terms z;
    int ok = match_start(p, &z, rest);
    *own = *rest; /* both start as nothing matched */
    if (ok)
        (void)score_table(tt, &z, id, own, rest, NULL, INFINITY);
}

/* Add column (id index i, blur b) of the table to a list (the table's
 * layout as rl_match_all reads it: bin k of column c at k * stride + c). */
static void list_add(const rl_templates *tt, int i, int b, rl_match_list *ls)
{
    const float *col = tt->table + (size_t)i * RL_BLUR_LEVELS + (size_t)b;
    size_t stride = (size_t)tt->stride;
    int k;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        ls->table[k * RL_MATCH_BLOCK + ls->n] = col[(size_t)k * stride];
    ls->id[ls->n] = tt->ids[i];
    ls->blur[ls->n] = b;
    ls->n++;
}

void rl_match_list_make(const rl_templates *tt, const int *ids, int n, int blur,
                        rl_match_list *ls)
{
    int j;
    int b;
    memset(ls, 0, sizeof *ls);
    for (j = 0; j < n; j++) {
        int i = rl_templates_find(tt, ids[j]);
        for (b = blur < 0 ? 0 : blur; i >= 0 && b < (blur < 0 ? RL_BLUR_LEVELS : blur + 1) &&
                                      ls->n < RL_MATCH_BLOCK; b++)
            list_add(tt, i, b, ls);
    }
}

static void list_score(const rl_match_list *ls, const profile_terms *z, rl_match *m)
{
    score_block(ls->table, RL_MATCH_BLOCK, ls->n, ls->id, ls->blur, z, m);
}

void rl_match_list_score(const rl_match_list *ls, const rl_profile *p, rl_match *m)
{
    profile_terms z;
    if (match_start(p, &z, m))
        list_score(ls, &z, m);
}

/* 1 when every id of the table among ids has a whole block of columns
 * from its first in the table (the kernel reads RL_MATCH_BLOCK of them). */
static int ids_in_place(const rl_templates *tt, const int *ids, int n)
{
    int j;
    for (j = 0; j < n; j++) {
        int i = rl_templates_find(tt, ids[j]);
        if (i >= 0 && i * RL_BLUR_LEVELS + RL_MATCH_BLOCK > tt->stride)
            return 0;
    }
    return 1;
}

/* Up to RL_MATCH_WIDE ids of the table in place (ids_in_place), from
 * ids[*from] on (those not in the table passed over), each at every blur:
 * the j-th one's sums at st + j * RL_MATCH_BLOCK .., its place in ids
 * into at[j]. Two or three ids take one walk over the bins
 * (rl_match_kernel_wide: a verification's rivals and zone twins are lists
 * of a few ids, a block each, and one block's walk waits on its adds), one
 * a block; each column's sums the same bits either way. *from moves past
 * the ids taken; their count. */
static int sum_in_place(const rl_templates *tt, const profile_terms *z, const int *ids, int n, int *from,
                        int *at, float *st, float *stt, float *sxt)
{
    const float *blocks[RL_MATCH_WIDE];
    int c = 0;
    for (; *from < n && c < RL_MATCH_WIDE; (*from)++) {
        int i = rl_templates_find(tt, ids[*from]);
        if (i < 0)
            continue;
        blocks[c] = tt->table + (size_t)i * RL_BLUR_LEVELS;
        at[c++] = *from;
    }
    if (c >= 2)
        rl_match_kernel_wide(blocks, c, (size_t)tt->stride, z->fn, z->fs, st, stt, sxt);
    else if (c == 1)
        rl_match_kernel(blocks[0], (size_t)tt->stride, z->fn, z->fs, st, stt, sxt);
    return c;
}

/* Id's columns (every blur) from its sums at st.. kept into m. */
static void keep_id(rl_match *m, const profile_terms *z, int id, const float *st, const float *stt,
                    const float *sxt)
{
    int b;
    for (b = 0; b < RL_BLUR_LEVELS; b++)
        keep_column(m, z, id, b, st[b], stt[b], sxt[b]);
}

/* Every id of ids (each in place in the table) at every blur, a walk
 * over the bins for RL_MATCH_WIDE of them (sum_in_place): kept into m; or,
 * where best is given, each into its own copy of m (m unchanged), its
 * score, where it matched, into best[its index]. */
static void keep_in_place(const rl_templates *tt, const profile_terms *z, const int *ids, int n, rl_match *m,
                          double *best)
{
    float st[RL_MATCH_WIDE * RL_MATCH_BLOCK], stt[RL_MATCH_WIDE * RL_MATCH_BLOCK],
        sxt[RL_MATCH_WIDE * RL_MATCH_BLOCK];
    int at[RL_MATCH_WIDE], from = 0, c, j;
    while (from < n) {
        c = sum_in_place(tt, z, ids, n, &from, at, st, stt, sxt);
        for (j = 0; j < c; j++) {
            const float *bt = st + j * RL_MATCH_BLOCK, *btt = stt + j * RL_MATCH_BLOCK,
                        *bxt = sxt + j * RL_MATCH_BLOCK;
            rl_match each;
            if (best == NULL) {
                keep_id(m, z, ids[at[j]], bt, btt, bxt);
                continue;
            }
            each = *m;
            keep_id(&each, z, ids[at[j]], bt, btt, bxt);
            if (each.id >= 0)
                best[at[j]] = each.score;
        }
    }
}

/* The columns of ids (at one blur, or every blur when blur < 0) scored
 * against the profile's terms z into m. */
static void score_ids(const rl_templates *tt, const profile_terms *z, const int *ids, int n, int blur,
                      rl_match *m)
{
    int b0 = blur < 0 ? 0 : blur, b1 = blur < 0 ? RL_BLUR_LEVELS : blur + 1, j, b;
    rl_match_list ls;
    if (blur < 0 && ids_in_place(tt, ids, n)) {
        /* each id at every blur: its columns are side by side in the
         * table, scored there (the columns, and their order, as a list's) */
        keep_in_place(tt, z, ids, n, m, NULL);
        return;
    }
    ls.n = 0;
    for (j = 0; j < n; j++) {
        int i = rl_templates_find(tt, ids[j]);
        for (b = b0; b < b1 && i >= 0; b++) {
            if (ls.n == 0)
                memset(ls.table, 0, sizeof ls.table);
            list_add(tt, i, b, &ls);
            if (ls.n == RL_MATCH_BLOCK) {
                list_score(&ls, z, m);
                ls.n = 0;
            }
        }
    }
    if (ls.n > 0)
        list_score(&ls, z, m);
}

void rl_match_ids(const rl_templates *tt, const rl_profile *p, const int *ids, int n, int blur,
                  rl_match *m)
{
    profile_terms z;
    if (match_start(p, &z, m))
        score_ids(tt, &z, ids, n, blur, m);
}

void rl_match_kept_ids(const rl_templates *tt, const rl_profile *p, const rl_match_kept *keep, const int *ids,
                       int n, rl_match *m)
{
    profile_terms z;
    int j;
    if (keep->state == RL_MATCH_KEPT_NONE) {
        rl_match_ids(tt, p, ids, n, -1, m);
        return;
    }
    /* the match before any column, as match_start leaves it */
    m->id = -1;
    m->score = m->second = -1.0;
    m->contrast = 0.0;
    m->blur = 0;
    if (keep->state != RL_MATCH_KEPT_SUMS)
        return;
    /* keep_column reads these three terms only */
    z.n = keep->n;
    z.sx = keep->sx;
    z.ivx = keep->ivx;
    /* each id of the table at every blur, in the order of ids: the order
     * in which score_ids keeps them, in place or from a list */
    for (j = 0; j < n; j++) {
        int c = rl_templates_find(tt, ids[j]) * RL_BLUR_LEVELS;
        if (c >= 0)
            keep_id(m, &z, ids[j], keep->st + c, keep->stt + c, keep->sxt + c);
    }
}

void rl_match_id_and_ids(const rl_templates *tt, const rl_profile *p, int id, const int *ids, int n,
                         int blur, rl_match *own, rl_match *m)
{
    profile_terms z;
    int ok = match_start(p, &z, m);
    *own = *m; /* both start as nothing matched */
    if (!ok)
        return;
    score_ids(tt, &z, &id, 1, blur, own);
    score_ids(tt, &z, ids, n, blur, m);
}

void rl_match_ids_each(const rl_templates *tt, const rl_profile *p, const int *ids, int n,
                       double *best)
{
    profile_terms z;
    rl_match m0;
    int j, ok = match_start(p, &z, &m0);
    for (j = 0; j < n; j++)
        best[j] = -2;
    if (ok && ids_in_place(tt, ids, n)) {
        /* three ids a walk over the bins, each kept apart */
        keep_in_place(tt, &z, ids, n, &m0, best);
        return;
    }
    for (j = 0; j < n && ok; j++) {
        rl_match m = m0;
        score_ids(tt, &z, &ids[j], 1, -1, &m);
        if (m.id >= 0)
            best[j] = m.score;
    }
}

int rl_match_twins(const rl_templates *tt, int id, int *twins)
{
    int n = 0, z;
    for (z = 1; z <= 2; z++) {
        int t = id ^ (1 << (tt->fam.bits - z));
        if (rl_family_valid(&tt->fam, t))
            twins[n++] = t;
    }
    return n;
}

double rl_match_pearson(const uint8_t *a, const uint8_t *b, const uint8_t *mask, int n)
{
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, c = 0, va, vb;
    int i;
    for (i = 0; i < n; i++) {
        if (mask && !mask[i])
            continue;
        sa += a[i];
        sb += b[i];
        saa += (double)a[i] * a[i];
        sbb += (double)b[i] * b[i];
        sab += (double)a[i] * b[i];
        c += 1;
    }
    va = c * saa - sa * sa;
    vb = c * sbb - sb * sb;
    if (va <= 0 || vb <= 0)
        return 0.0;
    return (c * sab - sa * sb) / sqrt(va * vb);
}
