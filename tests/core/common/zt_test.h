/* cmocka glue for the zspan core suites. */
#ifndef ZT_TEST_H
#define ZT_TEST_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "zt.h"

/* Fail the current test with a printf-style message. */
#define ZT_FAIL(...)                                                            \
    do {                                                                        \
        print_error("%s:%d: ", __FILE__, __LINE__);                             \
        print_error(__VA_ARGS__);                                               \
        print_error("\n");                                                      \
        fail();                                                                 \
    } while (0)

/* Check a condition; on failure print the message and fail. */
#define ZT_CHECK(cond, ...)                                                     \
    do {                                                                        \
        if (!(cond)) {                                                          \
            print_error("%s:%d: check failed: %s\n  ", __FILE__, __LINE__, #cond); \
            print_error(__VA_ARGS__);                                           \
            print_error("\n");                                                  \
            fail();                                                             \
        }                                                                       \
    } while (0)

/* Check a status code. */
#define ZT_ST(expr, want)                                                       \
    do {                                                                        \
        zs_status zt_st_ = (expr);                                              \
        if (zt_st_ != (want)) {                                                 \
            print_error("%s:%d: %s returned %d (%s), expected %d (%s)\n",       \
                        __FILE__, __LINE__, #expr, (int)zt_st_,                 \
                        zs_strerror(zt_st_), (int)(want), zs_strerror(want));   \
            fail();                                                             \
        }                                                                       \
    } while (0)

#endif
