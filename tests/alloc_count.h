/* alloc_count: heap allocations counted, for tests that show a path
 * calls no heap function. The test links with
 * -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc (rl_alloc_counted in
 * tests/CMakeLists.txt).
 *
 *   long before = alloc_count();
 *   step();
 *   assert_int_equal(alloc_count() - before, 0);
 */
#ifndef ALLOC_COUNT_H
#define ALLOC_COUNT_H

/* Calls of malloc, calloc and realloc so far. */
long alloc_count(void);

#endif
