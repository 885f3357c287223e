/* SPDX-License-Identifier: MIT */
/* Stand-in for a port test whose libraries were not installed at build time
 * (SKIP_WHAT names the suite, SKIP_WHY the reason): every test is skipped
 * with the reason. `make deps` installs what the real suite needs. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#include <cmocka.h>

static void test_skipped(void **state)
{
    (void)state;
    printf("SKIPPED: %s: %s\n", SKIP_WHAT, SKIP_WHY);
    skip();
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_skipped)};
    return cmocka_run_group_tests_name(SKIP_WHAT, tests, NULL, NULL);
}
