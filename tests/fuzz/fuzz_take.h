/* The fuzz targets' raw numbers: the next 8 bytes of the input as a
 * double (any bit pattern: NaN, infinities, huge), 0 when it runs out. */
#ifndef FUZZ_TAKE_H
#define FUZZ_TAKE_H
#include <stddef.h>
#include <stdint.h>
#include <string.h>

static double fuzz_take(const uint8_t **p, size_t *n)
{
    double v = 0;
    if (*n >= sizeof v) {
        memcpy(&v, *p, sizeof v);
        *p += sizeof v;
        *n -= sizeof v;
    }
    return v;
}
#endif
