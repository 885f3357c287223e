/* SPDX-License-Identifier: MIT */
/* ARM semihosting for Cortex-M (bkpt 0xAB), plus a small printf. */
#include "port.h"

#include <stdarg.h>

#define SYS_WRITE0 0x04
#define SYS_GET_CMDLINE 0x15
#define SYS_EXIT 0x18
#define SYS_EXIT_EXTENDED 0x20
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUNTIME_ERROR 0x20023u

static int semihost_call(int op, void *arg)
{
    register int r0 __asm__("r0") = op;
    register void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void sh_write0(const char *s)
{
    semihost_call(SYS_WRITE0, (void *)(uintptr_t)s);
}

static char outbuf[96];
static unsigned outlen;

void sh_flush(void)
{
    if (outlen) {
        outbuf[outlen] = 0;
        sh_write0(outbuf);
        outlen = 0;
    }
}

void sh_putc(char c)
{
    outbuf[outlen++] = c;
    if (c == '\n' || outlen == sizeof outbuf - 1)
        sh_flush();
}

static void put_num(unsigned long long v, unsigned base, int upper, int neg, int width, int zero,
                    int left)
{
    char tmp[24];
    int n = 0, len;
    const char *digits = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    do {
        tmp[n++] = digits[v % base];
        v /= base;
    } while (v);
    len = n + neg;
    if (neg && zero)
        sh_putc('-');
    if (!left)
        for (; len < width; len++)
            sh_putc(zero ? '0' : ' ');
    if (neg && !zero)
        sh_putc('-');
    while (n)
        sh_putc(tmp[--n]);
    if (left)
        for (; len < width; len++)
            sh_putc(' ');
}

void sh_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    for (; *fmt; fmt++) {
        int width = 0, zero = 0, left = 0, lng = 0;
        if (*fmt != '%') {
            sh_putc(*fmt);
            continue;
        }
        fmt++;
        for (;; fmt++) {
            if (*fmt == '0')
                zero = 1;
            else if (*fmt == '-')
                left = 1;
            else
                break;
        }
        while (*fmt >= '0' && *fmt <= '9')
            width = width * 10 + (*fmt++ - '0');
        while (*fmt == 'l') {
            lng++;
            fmt++;
        }
        switch (*fmt) {
        case 'd': {
            long long v = lng >= 2 ? va_arg(ap, long long) : lng ? va_arg(ap, long) : va_arg(ap, int);
            put_num(v < 0 ? 0ull - (unsigned long long)v : (unsigned long long)v, 10, 0, v < 0,
                    width, zero, left);
            break;
        }
        case 'u':
        case 'x':
        case 'X': {
            unsigned long long v = lng >= 2 ? va_arg(ap, unsigned long long)
                                   : lng    ? va_arg(ap, unsigned long)
                                            : va_arg(ap, unsigned);
            put_num(v, *fmt == 'u' ? 10u : 16u, *fmt == 'X', 0, width, zero, left);
            break;
        }
        case 's': {
            const char *s = va_arg(ap, const char *);
            int len = 0;
            while (s[len])
                len++;
            if (!left)
                for (; len < width; len++)
                    sh_putc(' ');
            while (*s)
                sh_putc(*s++);
            if (left)
                for (; len < width; len++)
                    sh_putc(' ');
            break;
        }
        case 'c':
            sh_putc((char)va_arg(ap, int));
            break;
        case '%':
            sh_putc('%');
            break;
        case 0:
            fmt--;
            break;
        default:
            sh_putc('%');
            sh_putc(*fmt);
        }
    }
    va_end(ap);
}

int sh_get_cmdline(char *buf, size_t size)
{
    struct {
        char *buf;
        size_t size;
    } blk;
    blk.buf = buf;
    blk.size = size;
    return semihost_call(SYS_GET_CMDLINE, &blk) == 0 ? 0 : -1;
}

void sh_exit(int status)
{
    uint32_t blk[2];
    sh_flush();
    blk[0] = ADP_STOPPED_APPLICATION_EXIT;
    blk[1] = (uint32_t)status;
    /* SYS_EXIT_EXTENDED carries the status (QEMU >= 4.0); fall back to
     * SYS_EXIT, whose reason code only says success or failure. */
    semihost_call(SYS_EXIT_EXTENDED, blk);
    semihost_call(SYS_EXIT, (void *)(uintptr_t)(status == 0 ? ADP_STOPPED_APPLICATION_EXIT
                                                             : ADP_STOPPED_RUNTIME_ERROR));
    for (;;)
        __asm__ volatile("wfi");
}
