#include "rl_family.h"

#include <math.h>

rl_err rl_family_init(rl_family *fam, int bits)
{
    if (fam == NULL)
        return RL_EINVAL;
    if (bits < RL_FAMILY_MIN_BITS || bits > RL_MAX_BITS)
        return RL_ERANGE;
    fam->bits = bits;
    return RL_OK;
}

rl_err rl_family_parse(const char *name, rl_family *fam)
{
    int n = 0, digits = 0;
    if (name == NULL || fam == NULL)
        return RL_EINVAL;
    if (name[0] != 'r' || name[1] != 'i' || name[2] != 'n' || name[3] != 'g')
        return RL_EFORMAT;
    name += 4;
    for (; *name >= '0' && *name <= '9' && digits < 3; name++, digits++)
        n = n * 10 + (*name - '0');
    if (digits == 0 || *name != '\0')
        return RL_EFORMAT;
    return rl_family_init(fam, n);
}

int rl_family_count(const rl_family *fam)
{
    return (1 << fam->bits) - 2;
}

int rl_family_valid(const rl_family *fam, int id)
{
    return id >= 1 && id <= rl_family_count(fam);
}

int rl_family_zone_twins(const rl_family *fam, int id, int *out)
{
    int n = 0, z;
    for (z = 0; z < fam->bits; z++)
        if (rl_family_valid(fam, id ^ (1 << z)))
            out[n++] = id ^ (1 << z);
    return n;
}

int rl_family_bit(const rl_family *fam, int id, int k)
{
    return (id >> (fam->bits - k)) & 1;
}

rl_err rl_family_code(const rl_family *fam, int id, char *buf, size_t len)
{
    int k;
    if (fam == NULL || buf == NULL)
        return RL_EINVAL;
    if (!rl_family_valid(fam, id))
        return RL_ERANGE;
    if (len < (size_t)fam->bits + 1)
        return RL_ENOMEM;
    for (k = 1; k <= fam->bits; k++)
        buf[k - 1] = (char)('0' + rl_family_bit(fam, id, k));
    buf[fam->bits] = '\0';
    return RL_OK;
}

rl_err rl_family_id(const rl_family *fam, const char *code, int *id)
{
    int k, v = 0;
    if (fam == NULL || code == NULL || id == NULL)
        return RL_EINVAL;
    for (k = 0; k < fam->bits; k++) {
        if (code[k] != '0' && code[k] != '1')
            return RL_EFORMAT;
        v = (v << 1) | (code[k] - '0');
    }
    if (code[fam->bits] != '\0')
        return RL_EFORMAT;
    if (!rl_family_valid(fam, v))
        return RL_ERANGE;
    *id = v;
    return RL_OK;
}

void rl_family_radii(const rl_family *fam, double *r)
{
    int k, n = fam->bits;
    r[0] = 1.0;
    for (k = 0; k <= n; k++)
        r[1 + k] = RL_OUTER_RING_INNER * sqrt((double)(n - k) / n);
}

int rl_family_dark_at(const rl_family *fam, int id, double rho)
{
    int n = fam->bits, k;
    double f;
    if (rho > 1.0)
        return 0;
    if (rho >= RL_OUTER_RING_INNER)
        return 1;
    /* Equal-area zones: the fraction of the code disk's area inside rho
     * says which zone it is in. */
    f = rho * rho / (RL_OUTER_RING_INNER * RL_OUTER_RING_INNER);
    k = n - (int)(f * n);
    if (k < 1)
        k = 1;
    return rl_family_bit(fam, id, k);
}

double rl_family_band_inner(const rl_family *fam, int id)
{
    double rad[RL_MAX_BITS + 2];
    int k = 1, j;
    if (!rl_family_valid(fam, id))
        return 0;
    rl_family_radii(fam, rad);
    while (k <= fam->bits && rl_family_bit(fam, id, k))
        k++;
    if (k > fam->bits)
        return 0;
    for (j = k; j <= fam->bits && !rl_family_bit(fam, id, j); j++)
        ;
    /* zone k's outer radius is rad[k]; white down to zone j's outer one */
    return rad[k] - (j > fam->bits ? 0.0 : rad[j]) >= RL_FAMILY_BAND_WHITE ? rad[k] : 0.0;
}
