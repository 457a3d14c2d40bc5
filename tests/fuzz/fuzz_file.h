/* The fuzz targets' one helper: the input as a file, for readers that
 * take a path (libpng, libyaml). One file per process, rewritten each run. */
#ifndef FUZZ_FILE_H
#define FUZZ_FILE_H
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static const char *fuzz_file(const uint8_t *data, size_t size, const char *ext)
{
    static char path[256];
    FILE *f;
    const char *dir = getenv("TMPDIR");
    snprintf(path, sizeof path, "%s/ringloc-fuzz-%ld%s", dir ? dir : "/tmp", (long)getpid(), ext);
    f = fopen(path, "wb");
    if (f == NULL)
        abort();
    if (size > 0 && fwrite(data, 1, size, f) != size)
        abort();
    fclose(f);
    return path;
}
#endif
