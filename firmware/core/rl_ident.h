/* rl_ident: landmark identification by template matching (Pearson's
 * correlation), the paper's identification step.
 *
 * A candidate region is sampled into an S x S grid (S = RL_TEMPLATE_SIZE)
 * covering its outer ring's bounding square, as darkness (255 - I), and
 * correlated with the pre-rendered template of every id. Pearson's r is
 * invariant to gain and offset, so the grey samples are used directly:
 * that keeps the sub-pixel information of 2-pixel rings that a binary
 * image would lose. Samples that fall outside the image are masked out and
 * the templates are cut the same way (a landmark cut by the border).
 *
 *   rl_ident id;
 *   rl_ident_init(&id, &ws, &fam, NULL, 0);       // every id of the family
 *   uint8_t x[S*S], m[S*S];  int vis;
 *   rl_ident_sample(&img, cx, cy, r, x, m, &vis);
 *   rl_match best;
 *   rl_ident_match(&id, x, vis < S*S ? m : NULL, &best);
 */
#ifndef RL_IDENT_H
#define RL_IDENT_H

#include <stdint.h>
#include "rl_config.h"
#include "rl_error.h"
#include "rl_family.h"
#include "rl_image.h"
#include "rl_workspace.h"

#define RL_TMPL_PIXELS (RL_TEMPLATE_SIZE * RL_TEMPLATE_SIZE)

typedef struct {
    rl_family fam;
    int n;          /* templates */
    int *ids;       /* id of each template */
    uint8_t *pix;   /* n templates of RL_TMPL_PIXELS darkness values */
    int32_t *sum;   /* per template: sum of values */
    int64_t *sum2;  /* per template: sum of squares */
} rl_ident;

typedef struct {
    int id;         /* best template's id, or -1 */
    double score;   /* its Pearson correlation */
    double second;  /* the runner-up's correlation */
} rl_match;

/* Bytes rl_ident_init takes for n templates. */
size_t rl_ident_bytes(int n);

/* Render the templates of `ids` (or every id of the family when ids is
 * NULL) into ws. RL_ERANGE for an id outside the family. */
RL_CHECK rl_err rl_ident_init(rl_ident *id, rl_ws *ws, const rl_family *fam, const int *ids,
                              int n_ids);

/* Sample the square of half-side r centred (cx, cy) into out[S*S] as
 * darkness, each cell the mean of a k x k grid of bilinear samples (k
 * follows the scale, so large landmarks are box-filtered). mask[i] = 1
 * where the cell's centre is inside the image (mask may be NULL);
 * *visible counts those. */
void rl_ident_sample(const rl_image *img, double cx, double cy, double r, uint8_t *out,
                     uint8_t *mask, int *visible);

/* Best and second-best template for samples x; with mask, only cells with
 * mask != 0 count (on both sides). */
void rl_ident_match(const rl_ident *id, const uint8_t *x, const uint8_t *mask, rl_match *m);

/* Pearson's correlation of a and b over the cells where mask != 0 (all
 * when NULL); 0 when either side is constant. */
double rl_pearson(const uint8_t *a, const uint8_t *b, const uint8_t *mask, int n);

#endif
