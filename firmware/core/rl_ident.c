#include "rl_ident.h"

#include <math.h>
#include "rl_template.h"

#define S RL_TEMPLATE_SIZE

size_t rl_ident_bytes(int n)
{
    return (size_t)n * (RL_TMPL_PIXELS + sizeof(int) + sizeof(int32_t) + sizeof(int64_t)) +
           4 * RL_WS_ALIGN;
}

rl_err rl_ident_init(rl_ident *id, rl_ws *ws, const rl_family *fam, const int *ids, int n_ids)
{
    int i, j, n = ids ? n_ids : rl_family_count(fam);
    rl_err e;
    if (n <= 0)
        return RL_EINVAL;
    id->fam = *fam;
    id->n = n;
    if ((e = rl_ws_alloc(ws, (size_t)n * sizeof(int), RL_WS_ALIGN, (void **)&id->ids)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)n * RL_TMPL_PIXELS, RL_WS_ALIGN, (void **)&id->pix)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)n * sizeof(int32_t), RL_WS_ALIGN, (void **)&id->sum)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)n * sizeof(int64_t), RL_WS_ALIGN, (void **)&id->sum2)) != RL_OK)
        return e;
    if (rl_ws_is_sizing(ws))
        return RL_OK;
    for (i = 0; i < n; i++) {
        rl_image t = rl_image_view(S, S, S, id->pix + (size_t)i * RL_TMPL_PIXELS);
        int32_t s = 0;
        int64_t s2 = 0;
        id->ids[i] = ids ? ids[i] : i + 1;
        if ((e = rl_tmpl_square(fam, id->ids[i], NULL, &t, NULL)) != RL_OK)
            return e;
        for (j = 0; j < RL_TMPL_PIXELS; j++) {
            s += t.data[j];
            s2 += (int64_t)t.data[j] * t.data[j];
        }
        id->sum[i] = s;
        id->sum2[i] = s2;
    }
    return RL_OK;
}

static double bilinear(const rl_image *img, double x, double y)
{
    int x0, y0;
    double fx, fy;
    const uint8_t *p;
    if (x < 0) x = 0;
    if (y < 0) y = 0;
    if (x > img->width - 1) x = img->width - 1;
    if (y > img->height - 1) y = img->height - 1;
    x0 = (int)x;
    y0 = (int)y;
    if (x0 > img->width - 2) x0 = img->width - 2 < 0 ? 0 : img->width - 2;
    if (y0 > img->height - 2) y0 = img->height - 2 < 0 ? 0 : img->height - 2;
    fx = x - x0;
    fy = y - y0;
    p = img->data + (size_t)y0 * (size_t)img->stride + x0;
    if (img->width < 2 || img->height < 2)
        return p[0];
    return (1 - fy) * ((1 - fx) * p[0] + fx * p[1]) +
           fy * ((1 - fx) * p[img->stride] + fx * p[img->stride + 1]);
}

void rl_ident_sample(const rl_image *img, double cx, double cy, double r, uint8_t *out,
                     uint8_t *mask, int *visible)
{
    double step = 2.0 * r / S;
    int k = (int)ceil(step), i, j, a, b, vis = 0;
    if (k < 1)
        k = 1;
    if (k > 4)
        k = 4; /* beyond 4x4 the extra samples change little */
    for (j = 0; j < S; j++) {
        double y = cy - r + (j + 0.5) * step;
        for (i = 0; i < S; i++) {
            double x = cx - r + (i + 0.5) * step, acc = 0;
            int in = x >= -0.5 && y >= -0.5 && x <= img->width - 0.5 && y <= img->height - 0.5;
            for (b = 0; b < k; b++)
                for (a = 0; a < k; a++)
                    acc += bilinear(img, x + ((a + 0.5) / k - 0.5) * step,
                                    y + ((b + 0.5) / k - 0.5) * step);
            out[j * S + i] = (uint8_t)(255.0 - acc / (k * k) + 0.5);
            if (mask)
                mask[j * S + i] = (uint8_t)in;
            vis += in;
        }
    }
    if (visible)
        *visible = vis;
}

static double corr(double n, double sx, double sy, double sxx, double syy, double sxy)
{
    double vx = n * sxx - sx * sx, vy = n * syy - sy * sy;
    if (vx <= 0 || vy <= 0)
        return 0.0;
    return (n * sxy - sx * sy) / sqrt(vx * vy);
}

double rl_pearson(const uint8_t *a, const uint8_t *b, const uint8_t *mask, int n)
{
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, c = 0;
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
    return corr(c, sa, sb, saa, sbb, sab);
}

void rl_ident_match(const rl_ident *id, const uint8_t *x, const uint8_t *mask, rl_match *m)
{
    int32_t sx = 0, cnt = 0;
    int64_t sxx = 0;
    int i, t;
    m->id = -1;
    m->score = m->second = -1.0;
    for (i = 0; i < RL_TMPL_PIXELS; i++) {
        if (mask && !mask[i])
            continue;
        sx += x[i];
        sxx += (int32_t)x[i] * x[i];
        cnt++;
    }
    for (t = 0; t < id->n; t++) {
        const uint8_t *p = id->pix + (size_t)t * RL_TMPL_PIXELS;
        int32_t sxy = 0, st = id->sum[t];
        int64_t stt = id->sum2[t];
        double r;
        if (mask) {
            st = 0;
            stt = 0;
            for (i = 0; i < RL_TMPL_PIXELS; i++)
                if (mask[i]) {
                    sxy += (int32_t)x[i] * p[i];
                    st += p[i];
                    stt += (int32_t)p[i] * p[i];
                }
        } else {
            for (i = 0; i < RL_TMPL_PIXELS; i++)
                sxy += (int32_t)x[i] * p[i];
        }
        r = corr(cnt, sx, st, (double)sxx, (double)stt, sxy);
        if (r > m->score) {
            m->second = m->score;
            m->score = r;
            m->id = id->ids[t];
        } else if (r > m->second) {
            m->second = r;
        }
    }
}
