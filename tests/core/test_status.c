/* SPDX-License-Identifier: MIT */
/*
 * test_status: the status codes and their texts. The oracle is the header
 * itself: the test reads include/zspan/zspan.h, takes the zs_status
 * enumerators in order with the comment after each, and checks that
 *
 *  - the enumerators are the ones this program was compiled with, in order,
 *    ending with ZS_STATUS_COUNT (so a code added to the header without a
 *    row below fails here);
 *  - every code has a non-NULL, non-empty text, distinct from all others, and
 *    out-of-range values get a text too;
 *  - each text says what the header's comment says: every word of the
 *    comment that carries meaning is one of the code's concepts below, and
 *    the text contains one of that concept's wordings. A comment that gains a
 *    word, or a text that loses one, fails.
 */
#include "zt_test.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#ifndef ZT_TOP_DIR
#define ZT_TOP_DIR "."
#endif
#define HEADER ZT_TOP_DIR "/include/zspan/zspan.h"

/* One idea of a header comment: the word it uses there (hdr) and the
 * wordings (any one of them) that the text must contain. */
typedef struct concept {
    const char *hdr;
    const char *txt[4];
} concept;

typedef struct code_spec {
    zs_status code;
    const char *name;
    concept c[9];
} code_spec;

static const code_spec k_specs[] = {
    {ZS_OK, "ZS_OK", {{NULL, {"ok", "success"}}}},
    {ZS_ERR_NULL,
     "ZS_ERR_NULL",
     {{"required", {"required"}},
      {"pointer", {"pointer"}},
      {"argument", {"argument"}},
      {"NULL", {"NULL"}}}},
    {ZS_ERR_SIZE,
     "ZS_ERR_SIZE",
     {{"width", {"width"}},
      {"height", {"height"}},
      {"zero", {"zero", "0"}},
      {"above", {"above", "greater than", "more than"}},
      {"ZS_MAX_DIM", {"ZS_MAX_DIM"}}}},
    {ZS_ERR_CAPACITY,
     "ZS_ERR_CAPACITY",
     {{"capacity", {"capacity"}},
      {"zero", {"zero", "0"}},
      {"above", {"above", "greater than", "more than"}},
      {"limit", {"limit", "maximum"}}}},
    {ZS_ERR_ARENA_SMALL,
     "ZS_ERR_ARENA_SMALL",
     {{"arena", {"arena"}},
      {"smaller", {"smaller", "too small"}},
      {"zs_arena_bytes", {"zs_arena_bytes"}}}},
    {ZS_ERR_CAMERA,
     "ZS_ERR_CAMERA",
     {{"eye", {"eye"}},
      {"target", {"target"}},
      {"up", {"up"}},
      {"parallel", {"parallel", "along"}},
      {"view", {"view"}},
      {"bad", {"bad", "invalid"}},
      {"projection", {"projection"}}}},
    {ZS_ERR_FOV,
     "ZS_ERR_FOV",
     {{"field", {"field of view", "fov"}},
      {"view", {"field of view", "fov"}},
      {"not", {"not in", "outside"}},
      {"0", {"(0, 180)"}},
      {"180", {"(0, 180)"}},
      {"degrees", {"degrees"}}}},
    {ZS_ERR_DEPTH_RANGE,
     "ZS_ERR_DEPTH_RANGE",
     {{"near", {"near"}}, {"0", {"0 < near", "near <= 0", "near > 0"}}, {"far", {"far"}}}},
    {ZS_ERR_MESH,
     "ZS_ERR_MESH",
     {{"mesh", {"mesh"}},
      {"no", {"no", "without", "NULL"}},
      {"positions", {"positions"}},
      {"indices", {"indices"}},
      {"zero", {"zero", "0"}},
      {"scale", {"scale"}}}},
    {ZS_ERR_INDEX,
     "ZS_ERR_INDEX",
     {{"triangle", {"triangle"}},
      {"index", {"index"}},
      {"vertex_count", {"vertex_count"}},
      {"draw", {"draw"}},
      {"rejected", {"rejected", "refused"}},
      {"whole", {"whole", "entire"}}}},
    {ZS_ERR_STATE,
     "ZS_ERR_STATE",
     {{"call", {"call"}},
      {"out", {"out of order"}},
      {"order", {"out of order"}},
      {"draw", {"draw", "zs_draw"}},
      {"before", {"before"}},
      {"frame_begin", {"frame_begin", "zs_frame_begin"}}}},
    {ZS_ERR_ROW,
     "ZS_ERR_ROW",
     {{"row", {"row"}},
      {"range", {"range"}},
      {"outside", {"outside"}},
      {"screen", {"screen"}},
      {"before", {"before"}},
      {"next", {"next"}}}},
    {ZS_ERR_BUFFER,
     "ZS_ERR_BUFFER",
     {{"buffer", {"buffer"}},
      {"stride", {"stride"}},
      {"too", {"too small"}},
      {"small", {"too small"}},
      {"width", {"width"}},
      {"format", {"format"}}}},
    {ZS_ERR_FORMAT, "ZS_ERR_FORMAT", {{"unknown", {"unknown"}}, {"pixel", {"pixel"}},
                                      {"format", {"format"}}}},
    {ZS_ERR_MODE,
     "ZS_ERR_MODE",
     {{"unknown", {"unknown"}},
      {"visibility", {"visibility"}},
      {"shading", {"shading"}},
      {"mode", {"mode"}},
      {"config", {"config"}},
      {"flags", {"flags"}},
      {"left", {"left out", "leaves out", "not built in"}},
      {"out", {"left out", "leaves out", "not built in"}}}},
    {ZS_ERR_ARGUMENT,
     "ZS_ERR_ARGUMENT",
     {{"other", {"other", "another"}},
      {"argument", {"argument"}},
      {"out", {"out of", "outside"}},
      {"documented", {"documented"}},
      {"range", {"range"}}}},
    {ZS_ERR_LEVEL,
     "ZS_ERR_LEVEL",
     {{"malformed", {"malformed"}},
      {"level", {"level"}},
      {"PVS", {"PVS"}},
      {"data", {"data"}},
      {"zspan", {"zspan/portal.h"}},
      {"portal", {"zspan/portal.h"}},
      {"h", {"zspan/portal.h"}}}},
    {ZS_ERR_TEXTURE,
     "ZS_ERR_TEXTURE",
     {{"bad", {"bad"}},
      {"texture", {"texture"}},
      {"see", {"see zs_texture_check"}},
      {"zs_texture_check", {"zs_texture_check"}}}},
};

/* Words of a header comment that carry no meaning of their own. */
static const char *const k_stop[] = {"a", "an", "the", "or", "and", "of", "to", "is", "its",
                                     "in", "for", "with", "any", "one", "than", "e", "g", "s", NULL};

#define NSPECS ((int)(sizeof k_specs / sizeof k_specs[0]))

/* ---------------- the header's enumerators ---------------- */

typedef struct hdr_code {
    char name[48];
    char comment[256];
} hdr_code;

static hdr_code g_hdr[64];
static int g_nhdr;

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, n = 0;
    char *s = malloc(cap);
    size_t got;
    while (s && (got = fread(s + n, 1, cap - 1 - n, f)) > 0) {
        n += got;
        if (n + 1 == cap)
            s = realloc(s, cap *= 2);
    }
    fclose(f);
    if (s)
        s[n] = 0;
    return s;
}

/* Appends the comment text of [p, end) to dst, whitespace collapsed. */
static void append_words(char *dst, size_t cap, const char *p, const char *end)
{
    size_t n = strlen(dst);
    for (; p < end && n + 2 < cap; p++) {
        if (isspace((unsigned char)*p)) {
            if (n && dst[n - 1] != ' ')
                dst[n++] = ' ';
        } else {
            dst[n++] = *p;
        }
    }
    dst[n] = 0;
}

/* Parses "typedef enum zs_status { ... } zs_status;": each enumerator and
 * the comment that follows it (up to the next enumerator). */
static int parse_header(void **state)
{
    (void)state;
    char *text = read_file(HEADER);
    if (!text) {
        fprintf(stderr, "test_status: cannot read %s\n", HEADER);
        return -1;
    }
    const char *p = strstr(text, "typedef enum zs_status {");
    const char *end = p ? strstr(p, "} zs_status;") : NULL;
    if (!p || !end) {
        fprintf(stderr, "test_status: no zs_status enum in %s\n", HEADER);
        free(text);
        return -1;
    }
    p = strchr(p, '{') + 1;
    int in_comment = 0;
    while (p < end) {
        if (in_comment) {
            const char *close = strstr(p, "*/");
            if (!close || close > end)
                close = end;
            if (g_nhdr > 0)
                append_words(g_hdr[g_nhdr - 1].comment, sizeof g_hdr[0].comment, p, close);
            p = close + 2;
            in_comment = 0;
        } else if (p[0] == '/' && p[1] == '*') {
            p += 2;
            in_comment = 1;
        } else if (isalpha((unsigned char)*p) || *p == '_') {
            const char *q = p;
            while (isalnum((unsigned char)*q) || *q == '_')
                q++;
            if (g_nhdr < (int)(sizeof g_hdr / sizeof g_hdr[0]) &&
                (size_t)(q - p) < sizeof g_hdr[0].name) {
                memcpy(g_hdr[g_nhdr].name, p, (size_t)(q - p));
                g_hdr[g_nhdr].name[q - p] = 0;
                g_hdr[g_nhdr].comment[0] = 0;
                g_nhdr++;
            }
            /* skip "= value" and the comma */
            while (q < end && *q != ',' && *q != '\n' && !(q[0] == '/' && q[1] == '*'))
                q++;
            p = q;
        } else {
            p++;
        }
    }
    free(text);
    return g_nhdr > 0 ? 0 : -1;
}

/* ---------------- word matching ---------------- */

static int word_char(char c) { return isalnum((unsigned char)c) || c == '_'; }

/* 1 if needle occurs in hay (case-insensitive) with no word character
 * glued to either end of it. */
static int has_phrase(const char *hay, const char *needle)
{
    size_t n = strlen(needle);
    for (const char *p = hay; *p; p++) {
        size_t i = 0;
        while (i < n && p[i] && tolower((unsigned char)p[i]) == tolower((unsigned char)needle[i]))
            i++;
        if (i < n)
            continue;
        int left_ok = p == hay || !word_char(p[-1]) || !word_char(needle[0]);
        int right_ok = !word_char(p[n]) || !word_char(needle[n - 1]);
        if (left_ok && right_ok)
            return 1;
    }
    return 0;
}

static int is_stop(const char *w)
{
    for (int i = 0; k_stop[i]; i++)
        if (!strcmp(w, k_stop[i]))
            return 1;
    return 0;
}

/* ---------------- tests ---------------- */

static void test_enum_matches_header(void **state)
{
    (void)state;
    ZT_CHECK(NSPECS == (int)ZS_STATUS_COUNT, "%d rows for %d status codes", NSPECS,
             (int)ZS_STATUS_COUNT);
    ZT_CHECK(g_nhdr == NSPECS + 1, "%s has %d enumerators, expected %d and ZS_STATUS_COUNT",
             HEADER, g_nhdr, NSPECS);
    for (int i = 0; i < NSPECS; i++) {
        ZT_CHECK((int)k_specs[i].code == i, "row %d is code %d", i, (int)k_specs[i].code);
        ZT_CHECK(!strcmp(g_hdr[i].name, k_specs[i].name),
                 "enumerator %d of the header is %s, this program knows it as %s", i,
                 g_hdr[i].name, k_specs[i].name);
        ZT_CHECK((g_hdr[i].comment[0] != 0) == (k_specs[i].c[0].hdr != NULL),
                 "%s: the header %s a comment", k_specs[i].name,
                 g_hdr[i].comment[0] ? "has" : "lacks");
    }
    ZT_CHECK(!strcmp(g_hdr[NSPECS].name, "ZS_STATUS_COUNT"), "last enumerator %s",
             g_hdr[NSPECS].name);
}

static void test_strerror_distinct(void **state)
{
    (void)state;
    const char *s[ZS_STATUS_COUNT];
    for (int i = 0; i < ZS_STATUS_COUNT; i++) {
        s[i] = zs_strerror((zs_status)i);
        ZT_CHECK(s[i] != NULL, "zs_strerror(%d) is NULL", i);
        ZT_CHECK(s[i][0] != '\0', "zs_strerror(%d) is empty", i);
        for (int j = 0; j < i; j++)
            ZT_CHECK(strcmp(s[i], s[j]) != 0, "zs_strerror(%d) == zs_strerror(%d): \"%s\"", i, j,
                     s[i]);
    }
    static const int out_of_range[] = {ZS_STATUS_COUNT, -1, 12345, INT32_MIN};
    for (size_t k = 0; k < sizeof out_of_range / sizeof out_of_range[0]; k++) {
        const char *t = zs_strerror((zs_status)out_of_range[k]);
        ZT_CHECK(t != NULL && t[0] != '\0', "zs_strerror(%d) is NULL or empty", out_of_range[k]);
        for (int j = 0; j < ZS_STATUS_COUNT; j++)
            ZT_CHECK(strcmp(t, s[j]) != 0, "zs_strerror(%d) is the text of code %d: \"%s\"",
                     out_of_range[k], j, t);
    }
}

static void test_strerror_says_what_the_header_says(void **state)
{
    (void)state;
    int bad = 0;
    for (int i = 0; i < NSPECS && i < g_nhdr; i++) {
        const code_spec *cs = &k_specs[i];
        const char *comment = g_hdr[i].comment, *text = zs_strerror(cs->code);
        /* every concept is in the header's comment and in the text */
        for (int k = 0; k < (int)(sizeof cs->c / sizeof cs->c[0]); k++) {
            const concept *c = &cs->c[k];
            if (!c->txt[0])
                break;
            if (c->hdr && !has_phrase(comment, c->hdr)) {
                print_error("%s: the header's comment \"%s\" no longer says \"%s\"\n", cs->name,
                            comment, c->hdr);
                bad++;
            }
            int found = 0;
            for (int a = 0; a < 4 && c->txt[a] && !found; a++)
                found = has_phrase(text, c->txt[a]);
            if (!found) {
                print_error("%s: zs_strerror gives \"%s\", which does not say \"%s\" (the header: "
                            "\"%s\")\n",
                            cs->name, text, c->txt[0], comment);
                bad++;
            }
        }
        /* every meaningful word of the comment is one of the concepts */
        for (const char *p = comment; *p;) {
            if (!word_char(*p)) {
                p++;
                continue;
            }
            char w[64];
            size_t n = 0;
            while (word_char(*p)) {
                if (n + 1 < sizeof w)
                    w[n++] = (char)tolower((unsigned char)*p);
                p++;
            }
            w[n] = 0;
            if (is_stop(w))
                continue;
            int known = 0;
            for (int k = 0; k < (int)(sizeof cs->c / sizeof cs->c[0]) && cs->c[k].txt[0]; k++)
                if (cs->c[k].hdr) {
                    char h[64];
                    size_t m = 0;
                    for (; cs->c[k].hdr[m] && m + 1 < sizeof h; m++)
                        h[m] = (char)tolower((unsigned char)cs->c[k].hdr[m]);
                    h[m] = 0;
                    known |= !strcmp(h, w);
                }
            if (!known) {
                print_error("%s: the header's comment \"%s\" says \"%s\", which this test does not "
                            "check in the text (add a concept)\n",
                            cs->name, comment, w);
                bad++;
            }
        }
    }
    ZT_CHECK(bad == 0, "%d mismatches between zs_strerror and the header's comments", bad);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_enum_matches_header),
        cmocka_unit_test(test_strerror_distinct),
        cmocka_unit_test(test_strerror_says_what_the_header_says),
    };
    int rc = cmocka_run_group_tests(tests, parse_header, NULL);
    for (int i = 0; i < ZS_STATUS_COUNT; i++)
        printf("  %-20s \"%s\"\n", k_specs[i].name, zs_strerror((zs_status)i));
    printf("test_status: %d status codes read from %s; %d failed\n", g_nhdr - 1, HEADER, rc);
    fflush(stdout);
    return rc;
}
