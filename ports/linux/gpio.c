/* SPDX-License-Identifier: MIT */
/*
 * GPIO output lines through libgpiod: the v1 API (Debian 12 ships 1.6) or
 * the v2 API, chosen at build time (mk/ports.mk defines ZS_GPIOD_V2 when
 * pkg-config reports libgpiod >= 2).
 */
#define _GNU_SOURCE
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gpiod.h>

#include "zs_linux.h"

#define CONSUMER "zspan"

static void chip_error(const char *chip, int e, char *err, size_t n)
{
    if (e == ENOENT || e == ENODEV)
        snprintf(err, n, "GPIO chip '%s': no such device (list the chips with gpiodetect)",
                 chip);
    else if (e == EACCES || e == EPERM)
        snprintf(err, n,
                 "GPIO chip '%s': permission denied (run as root or add the user to the group "
                 "owning /dev/gpiochip*, e.g. 'gpio')",
                 chip);
    else if (e == ENOTTY)
        snprintf(err, n, "GPIO chip '%s': not a GPIO character device", chip);
    else
        snprintf(err, n, "GPIO chip '%s': %s", chip, strerror(e));
}

static void busy_error(unsigned offset, const char *consumer, char *err, size_t n)
{
    snprintf(err, n,
             "GPIO line %u is busy: already requested by '%s' (another program, a kernel driver "
             "or a device-tree overlay holds it; free it or pick another line)",
             offset, consumer != NULL && consumer[0] != '\0' ? consumer : "an unnamed consumer");
}

#ifndef ZS_GPIOD_V2
/* ------------------------------------------------------------------ v1 -- */

static void *v1_chip_open(const char *chip, char *err, size_t n)
{
    struct gpiod_chip *c;
    errno = 0;
    c = gpiod_chip_open_lookup(chip);
    if (c == NULL)
        chip_error(chip, errno ? errno : ENOENT, err, n);
    return c;
}

static void v1_chip_close(void *chip)
{
    if (chip != NULL)
        gpiod_chip_close(chip);
}

static void *v1_line_request(void *chip, unsigned offset, int value, char *err, size_t n)
{
    struct gpiod_line *line;
    if (offset >= gpiod_chip_num_lines(chip)) {
        snprintf(err, n, "GPIO line %u does not exist: %s has %u lines", offset,
                 gpiod_chip_name(chip), gpiod_chip_num_lines(chip));
        errno = EINVAL;
        return NULL;
    }
    line = gpiod_chip_get_line(chip, offset);
    if (line == NULL) {
        snprintf(err, n, "GPIO line %u: %s", offset, strerror(errno));
        return NULL;
    }
    if (gpiod_line_request_output(line, CONSUMER, value ? 1 : 0) != 0) {
        int e = errno;
        if (e == EBUSY) {
            gpiod_line_update(line);
            busy_error(offset, gpiod_line_consumer(line), err, n);
        } else if (e == EACCES || e == EPERM) {
            snprintf(err, n, "GPIO line %u: permission denied", offset);
        } else {
            snprintf(err, n, "GPIO line %u: %s", offset, strerror(e));
        }
        errno = e;
        return NULL;
    }
    return line;
}

static int v1_line_set(void *line, int value)
{
    return gpiod_line_set_value(line, value ? 1 : 0);
}

static void v1_line_release(void *line)
{
    if (line != NULL)
        gpiod_line_release(line);
}

static const zs_gpio_ops v1_ops = {v1_chip_open,    v1_chip_close,   v1_line_request,
                                   v1_line_set,     v1_line_release, "libgpiod v1 API"};

const zs_gpio_ops *zs_gpio_libgpiod(void)
{
    return &v1_ops;
}

#else
/* ------------------------------------------------------------------ v2 -- */

typedef struct v2_line {
    struct gpiod_line_request *req;
    unsigned offset;
} v2_line;

static void *v2_chip_open(const char *chip, char *err, size_t n)
{
    char path[256];
    struct gpiod_chip *c;
    const char *p = chip;
    if (strchr(chip, '/') == NULL) {
        /* "gpiochip0" or "0", like the v1 lookup. */
        char *end;
        long num = strtol(chip, &end, 10);
        if (*chip != '\0' && *end == '\0' && num >= 0)
            snprintf(path, sizeof path, "/dev/gpiochip%ld", num);
        else
            snprintf(path, sizeof path, "/dev/%s", chip);
        p = path;
    }
    errno = 0;
    c = gpiod_chip_open(p);
    if (c == NULL)
        chip_error(chip, errno ? errno : ENOENT, err, n);
    return c;
}

static void v2_chip_close(void *chip)
{
    if (chip != NULL)
        gpiod_chip_close(chip);
}

static void *v2_line_request(void *chip, unsigned offset, int value, char *err, size_t n)
{
    struct gpiod_chip_info *ci = gpiod_chip_get_info(chip);
    struct gpiod_line_settings *ls = NULL;
    struct gpiod_line_config *lc = NULL;
    struct gpiod_request_config *rc = NULL;
    struct gpiod_line_request *req = NULL;
    v2_line *l = NULL;
    int e = 0;

    if (ci != NULL) {
        size_t lines = gpiod_chip_info_get_num_lines(ci);
        if (offset >= lines) {
            snprintf(err, n, "GPIO line %u does not exist: %s has %zu lines", offset,
                     gpiod_chip_info_get_name(ci), lines);
            gpiod_chip_info_free(ci);
            errno = EINVAL;
            return NULL;
        }
        gpiod_chip_info_free(ci);
    }
    ls = gpiod_line_settings_new();
    lc = gpiod_line_config_new();
    rc = gpiod_request_config_new();
    l = calloc(1, sizeof *l);
    if (ls == NULL || lc == NULL || rc == NULL || l == NULL) {
        e = ENOMEM;
        snprintf(err, n, "GPIO line %u: out of memory", offset);
        goto out;
    }
    gpiod_line_settings_set_direction(ls, GPIOD_LINE_DIRECTION_OUTPUT);
    gpiod_line_settings_set_output_value(ls, value ? GPIOD_LINE_VALUE_ACTIVE
                                                   : GPIOD_LINE_VALUE_INACTIVE);
    if (gpiod_line_config_add_line_settings(lc, &offset, 1, ls) != 0) {
        e = errno;
        snprintf(err, n, "GPIO line %u: %s", offset, strerror(e));
        goto out;
    }
    gpiod_request_config_set_consumer(rc, CONSUMER);
    req = gpiod_chip_request_lines(chip, rc, lc);
    if (req == NULL) {
        e = errno;
        if (e == EBUSY) {
            struct gpiod_line_info *li = gpiod_chip_get_line_info(chip, offset);
            busy_error(offset, li != NULL ? gpiod_line_info_get_consumer(li) : NULL, err, n);
            if (li != NULL)
                gpiod_line_info_free(li);
        } else if (e == EACCES || e == EPERM) {
            snprintf(err, n, "GPIO line %u: permission denied", offset);
        } else {
            snprintf(err, n, "GPIO line %u: %s", offset, strerror(e));
        }
        goto out;
    }
    l->req = req;
    l->offset = offset;
out:
    if (ls != NULL)
        gpiod_line_settings_free(ls);
    if (lc != NULL)
        gpiod_line_config_free(lc);
    if (rc != NULL)
        gpiod_request_config_free(rc);
    if (req == NULL) {
        free(l);
        errno = e;
        return NULL;
    }
    return l;
}

static int v2_line_set(void *line, int value)
{
    v2_line *l = line;
    return gpiod_line_request_set_value(l->req, l->offset,
                                        value ? GPIOD_LINE_VALUE_ACTIVE : GPIOD_LINE_VALUE_INACTIVE);
}

static void v2_line_release(void *line)
{
    v2_line *l = line;
    if (l == NULL)
        return;
    gpiod_line_request_release(l->req);
    free(l);
}

static const zs_gpio_ops v2_ops = {v2_chip_open,    v2_chip_close,   v2_line_request,
                                   v2_line_set,     v2_line_release, "libgpiod v2 API"};

const zs_gpio_ops *zs_gpio_libgpiod(void)
{
    return &v2_ops;
}
#endif
