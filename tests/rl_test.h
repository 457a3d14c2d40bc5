/* Shared includes for the CMocka tests. */
#ifndef RL_TEST_H
#define RL_TEST_H
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A path in the test's scratch folder (RL_TEST_TMP, set by CTest). */
static inline const char *rl_test_path(char *buf, size_t len, const char *name)
{
    const char *dir = getenv("RL_TEST_TMP");
    snprintf(buf, len, "%s/%s", dir ? dir : "/tmp", name); /* never the source tree */
    return buf;
}
#endif
