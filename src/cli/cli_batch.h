/* What cli_batch*.c and cli_merge.c share. */
#ifndef RB_CLI_BATCH_H
#define RB_CLI_BATCH_H

#include "cli.h"
#include "rockbolt/batch.h"
#include "rockbolt/outplan.h"

typedef struct {
    const char **inputs;      /* owned array; strings point into argv */
    size_t n_inputs;
    const char *json_path, *csv_path, *junit_path;
    const char *p58_path;     /* batch: --p58 FILE, or NULL */
    const char *pdf_path;     /* batch: --pdf FILE, the summary's package, or NULL */
    const char *reports_dir;  /* batch only */
    const char *base;         /* batch: --base CASE */
    const char *sandbox_dir;  /* batch: --sandbox DIR, or NULL */
    rb_sandbox sandbox;       /* opened from sandbox_dir once parsed */
    const char *encoding;     /* batch: --encoding NAME, or NULL (UTF-8) */
    int design;               /* batch: --design */
    int fragility;            /* batch: --fragility */
    unsigned long long seed;  /* batch: --seed N of the fragility's bootstrap */
    int seed_given;
    rb_fragility_intensity intensity; /* batch: --intensity pfa|sa */
    int intensity_given;
    int threads;              /* batch: -j N; 0: every processor */
    size_t shard, n_shards;   /* batch: --shard I/N; 0/0: all */
    int quiet, help;
    rb_outplan plan;          /* every output and input (rockbolt/outplan.h) */
    /* The summary's cases as they are done, rendered in each format asked
     * for (NULL: not asked for), and the diagnostics of the cases that
     * could not be run: copied out between head and tail at the end, so
     * that memory does not grow with the list (cli_batch_stream.c). */
    FILE *spool[RB_BATCH_N_FORMATS];
    FILE *error_spool;
    /* Each spool's name when made (removed at once, named in errors):
     * [RB_BATCH_N_FORMATS] is the error spool's. */
    char *spool_path[RB_BATCH_N_FORMATS + 1];
    /* The first spool that could not be written or read back: its name
     * (one of spool_path) and the system's reason. */
    const char *spool_failed;
    int spool_errno;
} rb_batch_cli;

rb_exit rb_cli_batch_parse(int argc, char **argv, int is_merge, rb_batch_cli *o);
void rb_cli_batch_cli_free(rb_batch_cli *o);

/* Plan the summary outputs and the inputs named on the command line
 * (before any work): clashes and unwritable outputs are exit 2. */
rb_exit rb_cli_batch_check_outputs(rb_batch_cli *o);

/* Print a planning error; the exit code it calls for. */
rb_exit rb_cli_plan_error(rb_status st, const rb_diag *d);

/* What batch and merge both do first: parse, answer --help (then *done is
 * set and o already freed), check the output paths. */
rb_exit rb_cli_batch_begin(int argc, char **argv, int is_merge, rb_batch_cli *o,
                           int *done);

/* Open the spools for the outputs asked for; exit 2 when they cannot be
 * (the directory named, with the reason). */
rb_exit rb_cli_stream_open(rb_batch_cli *o);
/* After a spool failed (o->spool_failed): say which and why; exit 2, as
 * for an output that cannot be written. */
rb_exit rb_cli_stream_error(const rb_batch_cli *o);
/* An rb_batch_opts sink (ctx: the rb_batch_cli): the cases into the spools. */
rb_status rb_cli_stream_sink(void *ctx, const rb_batch_summary *s,
                             const rb_batch_case *cases, size_t first, size_t n);
/* Write head, spooled cases and tail of format f to out. */
rb_status rb_cli_stream_copy(rb_batch_cli *o, rb_batch_format f, const rb_batch_summary *s,
                             FILE *out);
void rb_cli_stream_close(rb_batch_cli *o);

/* Write the summary outputs asked for, all or none; print the table
 * unless quiet; return the exit code the summary calls for. s is streamed
 * (its cases are in the spools) or whole (they are spooled here first). */
rb_exit rb_cli_batch_finish(rb_batch_cli *o, const rb_batch_summary *s);

/* The progress line on stderr (cli_batch_progress.c). */
typedef struct {
    int enabled;              /* stderr is a terminal and not --quiet */
    double start_s, last_s;
    int shown;                /* a line is on the screen */
} rb_cli_progress;

void rb_cli_progress_start(rb_cli_progress *p, int quiet);
void rb_cli_progress_update(void *ctx, const rb_batch_progress *bp);
/* Clear the line; with a summary of the wall time when enabled. */
void rb_cli_progress_end(rb_cli_progress *p, size_t cases);

/* The same for design's searches (rb_design_progress_fn). */
void rb_cli_progress_design(void *ctx, size_t done, size_t total, const char *what);
void rb_cli_progress_design_end(rb_cli_progress *p, size_t searches);
/* A suite's motions as the case loader generates them
 * (rb_case_set_generate_progress); rb_cli_progress_clear takes the line
 * away once the case is loaded, before anything else is printed. */
void rb_cli_progress_generate(void *ctx, size_t done, size_t total);
void rb_cli_progress_clear(rb_cli_progress *p);

#endif
