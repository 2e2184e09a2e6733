/* The progress line of a batch (and of design's searches) on stderr,
 * rewritten in place: cases done, failures, time left. Only on a terminal: a log file or a CI console gets
 * nothing, since carriage returns make a mess there. The wall time stays
 * here too, never in the summary files, which must not depend on it. */
#include <stdio.h>
#include <time.h>
#include <unistd.h>
#include "cli_batch.h"
#include "rockbolt/textsafe.h"

#define RB_PROGRESS_INTERVAL_S 0.2

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void rb_cli_progress_start(rb_cli_progress *p, int quiet)
{
    p->enabled = !quiet && isatty(STDERR_FILENO);
    p->start_s = p->last_s = now_s();
    p->shown = 0;
}

static void fmt_time(char *buf, size_t n, double s)
{
    long t = (long)(s + 0.5);
    if (t >= 3600)
        snprintf(buf, n, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
    else
        snprintf(buf, n, "%ld:%02ld", t / 60, t % 60);
}

/* Called by the library, one call at a time. */
void rb_cli_progress_update(void *ctx, const rb_batch_progress *bp)
{
    rb_cli_progress *p = ctx;
    double t = now_s();
    if (!p->enabled || (t - p->last_s < RB_PROGRESS_INTERVAL_S
                        && bp->cases_done < bp->cases_total))
        return;
    p->last_s = t;
    char left[32] = "estimating";
    if (bp->cases_done > 0) {
        double per = (t - p->start_s) / (double)bp->cases_done;
        fmt_time(left, sizeof left, per * (double)(bp->cases_total - bp->cases_done));
    }
    fprintf(stderr, "\r%zu/%zu cases, %zu failed, %zu unreadable, %s left\033[K",
            bp->cases_done, bp->cases_total, bp->failed, bp->unreadable, left);
    fflush(stderr);
    p->shown = 1;
}

void rb_cli_progress_end(rb_cli_progress *p, size_t cases)
{
    char took[32];
    if (!p->enabled)
        return;
    fmt_time(took, sizeof took, now_s() - p->start_s);
    fprintf(stderr, "%s%zu case%s in %s (%.1f s)\n", p->shown ? "\r\033[K" : "", cases,
            cases == 1 ? "" : "s", took, now_s() - p->start_s);
}

/* design: one line per search as it starts (searches are few and each can
 * take seconds, so every start is shown); what it is, of the case's text,
 * escaped like every name on a terminal. */
void rb_cli_progress_design(void *ctx, size_t done, size_t total, const char *what)
{
    rb_cli_progress *p = ctx;
    char el[32], w[160];
    if (!p->enabled || !what)
        return;
    fmt_time(el, sizeof el, now_s() - p->start_s);
    fprintf(stderr, "\rdesign: search %zu/%zu, %s, %s elapsed\033[K", done + 1, total,
            rb_text_escape_buf(what, w, sizeof w), el);
    fflush(stderr);
    p->shown = 1;
}

void rb_cli_progress_design_end(rb_cli_progress *p, size_t searches)
{
    char took[32];
    if (!p->enabled)
        return;
    fmt_time(took, sizeof took, now_s() - p->start_s);
    fprintf(stderr, "%sdesign: %zu search%s in %s (%.1f s)\n", p->shown ? "\r\033[K" : "",
            searches, searches == 1 ? "" : "es", took, now_s() - p->start_s);
}

void rb_cli_progress_generate(void *ctx, size_t done, size_t total)
{
    rb_cli_progress *p = ctx;
    double t = now_s();
    if (!p->enabled || (t - p->last_s < RB_PROGRESS_INTERVAL_S && done < total))
        return;
    p->last_s = t;
    char left[32] = "estimating";
    if (done > 0)
        fmt_time(left, sizeof left, (t - p->start_s) / (double)done * (double)(total - done));
    fprintf(stderr, "\rgenerating motions: %zu/%zu components, %s left\033[K", done, total,
            left);
    fflush(stderr);
    p->shown = 1;
}

void rb_cli_progress_clear(rb_cli_progress *p)
{
    if (!p->enabled || !p->shown)
        return;
    fputs("\r\033[K", stderr);
    fflush(stderr);
    p->shown = 0;
}
