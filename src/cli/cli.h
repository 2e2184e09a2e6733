/* The rockbolt command line: what the cli_*.c files share.
 *
 * The CLI is the only part of rockbolt that prints. It parses the command
 * line, calls the library, turns statuses into the documented exit codes
 * and prints diagnostics as "FILE:LINE:COL: error: KEY: MESSAGE". */
#ifndef RB_CLI_H
#define RB_CLI_H

#include <getopt.h>
#include "rockbolt/plot.h"
#include "rockbolt/rockbolt.h"
#include "rockbolt/run.h"
#include "rockbolt/sandbox.h"

/* Exit codes, as documented in --help and README.md. */
typedef enum {
    RB_EXIT_PASS = 0,     /* the design passes its criteria */
    RB_EXIT_FAIL = 1,     /* it fails them */
    RB_EXIT_USAGE = 2,    /* bad input or usage; nothing written */
    RB_EXIT_INTERNAL = 3  /* internal or solver error */
} rb_exit;

typedef enum {
    RB_CMD_NONE = 0,
    RB_CMD_HELP,
    RB_CMD_VERSION,
    RB_CMD_CHECK,
    RB_CMD_DESIGN,
    RB_CMD_INIT,
    RB_CMD_FRAGILITY,
    RB_CMD_SPECTRUM,
    RB_CMD_MOTION
} rb_cli_command;

typedef struct {
    rb_cli_command command;
    const char *case_path;    /* check: the case file */
    const char *json_path;    /* --json FILE, or NULL */
    const char *text_path;    /* --text FILE, or NULL */
    const char *history_path; /* --history FILE, or NULL */
    int quiet;                /* --quiet: nothing on stdout */
    const char *init_path;    /* init: the file to create */
    int init_ac156;           /* init --ac156: the AC156 starter */
    const char *sweep_csv_path; /* design: --sweep-csv FILE, or NULL */
    int threads;              /* design: -j N; 0: every processor */
    const char *svg_path;     /* --svg FILE: the figures, or NULL */
    const char *html_path;    /* --html FILE: report and figures, or NULL */
    const char *sandbox_dir;  /* --sandbox DIR: inputs must lie inside, or NULL */
    rb_sandbox sandbox;       /* opened from sandbox_dir once parsed */
    const char *help_command; /* help: the command asked about, or NULL */
    const char *csv_path;     /* fragility: --csv FILE, or NULL */
    const char *dir_path;     /* motion: --dir DIR, or NULL */
    const char *p58_path;     /* fragility: --p58 FILE, or NULL */
    const char *pdf_path;     /* --pdf FILE: the calculation package, or NULL */
    unsigned long long seed;  /* fragility: --seed N of the bootstrap */
    rb_spectrum_opts spectrum; /* spectrum: --damping, --from, --to, --per-octave */
    rb_plot_scale x_scale;    /* fragility: --x-scale of the figure (log) */
    int x_scale_given;
    const char *sweep_gap;    /* fragility: --sweep-gap FROM:TO:STEP, or NULL */
    rb_fragility_intensity intensity; /* fragility: --intensity pfa|sa */
    int intensity_given;
    double gap_ratios[RB_FRAGILITY_SWEEP_MAX_POINTS]; /* its grid */
    size_t n_gap_ratios;
} rb_cli_opts;

/* Parse argv into o. Returns RB_EXIT_PASS, or RB_EXIT_USAGE after printing
 * what is wrong. Strings in o point into argv. */
rb_exit rb_cli_args_parse(int argc, char **argv, rb_cli_opts *o);

/* --seed N of fragility and batch --fragility: a whole number that fits
 * 64 bits; RB_EXIT_USAGE after printing what is wrong. */
rb_exit rb_cli_take_seed(const char *v, unsigned long long *out);
/* --intensity pfa|sa, once: *given is set (fragility and batch). */
rb_exit rb_cli_take_intensity(const char *v, rb_fragility_intensity *out, int *given);

/* --sandbox DIR of check, design and batch: confine every input to DIR
 * (rockbolt/sandbox.h) before anything is read. RB_EXIT_USAGE after
 * printing why when DIR is not a directory. NULL: nothing to do. */
rb_exit rb_cli_sandbox(const char *dir, rb_sandbox *sb);

/* fragility and spectrum (cli_case_outputs.c): plan --json, --csv, --svg,
 * --html, --p58 and --pdf against the case; load the case and add the files it read to
 * the plan's inputs. Each prints what went wrong. */
#include "rockbolt/outplan.h"
rb_exit rb_cli_plan_case_outputs(const rb_cli_opts *o, rb_outplan *p);
rb_exit rb_cli_load_case_planned(const rb_cli_opts *o, rb_case *c, rb_outplan *p);
/* What such a command renders of its result (ctx): new strings, NULL when
 * memory runs out; the figure as rb_plot's functions make one. */
typedef struct {
    const void *ctx;
    const char *title;        /* of the figure and the page */
    const char *what;         /* "fragility": for the stdout error */
    char *(*text)(const void *ctx);
    char *(*json)(const void *ctx);
    char *(*csv)(const void *ctx);
    rb_status (*figure)(const void *ctx, const char *title, char **out, rb_diag *d);
    char *(*p58)(const void *ctx);  /* fragility --p58; NULL elsewhere */
    const rb_case *kase;      /* --pdf: the cover's case; NULL elsewhere */
    /* the outputs planned under the option other_opt (motion's --dir),
     * filled by other with the plan's index; NULL elsewhere */
    const char *other_opt;
    rb_status (*other)(const void *ctx, size_t i, FILE *fp, rb_diag *d);
} rb_cli_renders;
/* Write the planned outputs (all or none), then the text on stdout unless
 * --quiet or an output is stdout. */
rb_exit rb_cli_emit_case_outputs(const rb_cli_opts *o, rb_outplan *p, const rb_cli_renders *r);

/* rb_case_load_cached of the case o names, under o's sandbox: with a
 * progress line on a terminal while the loader generates a suite's
 * motions (minutes for a large one), unless --quiet. */
rb_status rb_cli_case_load(const rb_cli_opts *o, rb_case *c, rb_diag_list *diags);

/* rockbolt motion (cli_motion.c). */
rb_exit rb_cli_motion_run(const rb_cli_opts *o);

/* --reports DIR of batch, --dir DIR of motion: DIR is created if missing
 * (its parent must exist; *created then set), else must be a writable
 * directory. RB_EXIT_USAGE after printing why, naming opt. */
rb_exit rb_cli_output_dir(const char *dir, const char *opt, int *created);

/* rockbolt spectrum (cli_spectrum.c). */
rb_exit rb_cli_spectrum_run(const rb_cli_opts *o);

/* rockbolt fragility (cli_fragility.c). */
rb_exit rb_cli_fragility_run(const rb_cli_opts *o);

/* check and design share one flow; design adds the searches. */
rb_exit rb_cli_check_run(const rb_cli_opts *o);

/* The design step of `rockbolt design`, between solving and reporting:
 * runs rb_run_design_checked on the check's runs of the motions (checked,
 * one a motion) and prints a failure. */
rb_exit rb_cli_design_step(const rb_cli_opts *o, const rb_case *c, const rb_result *checked,
                           rb_case_design *d);

/* The file name of the i-th of n files asked for under one name (sweep
 * CSVs, figures): the name itself when n is 1, else with "-<i+1>" before
 * its extension. NULL on overflow. */
const char *rb_cli_numbered_name(const char *base, size_t i, size_t n, char *buf,
                                  size_t size);
rb_exit rb_cli_init_run(const rb_cli_opts *o);

/* "rockbolt batch ARGS" and "rockbolt merge ARGS": argv holds the
 * arguments after the command word. Exit codes as in docs/batch.md. */
rb_exit rb_cli_batch_main(int argc, char **argv);
rb_exit rb_cli_merge_main(int argc, char **argv);

/* --help on stdout; --version on stdout. */
void rb_cli_help_print(void);
void rb_cli_version_print(void);

/* One command's usage and options on stdout (`rockbolt help COMMAND`,
 * `rockbolt COMMAND --help`); RB_EXIT_USAGE after an error when there is
 * no such command. */
rb_exit rb_cli_help_command_print(const char *name);

/* The candidate closest to word (an option, "--jsn=x" counts as "--jsn")
 * when close enough to be a likely typo, else NULL. */
const char *rb_cli_nearest(const char *word, const char *const *cands);

/* "unknown WHAT 'WORD' [for 'CMD'][; did you mean 'X'?] (see ...)". */
void rb_cli_unknown_word(const char *what, const char *word, const char *const *cands,
                         const char *cmd);

/* An unknown option of cmd, with a "did you mean" from the options its
 * help documents, or the command it belongs to. */
void rb_cli_unknown_option(const char *cmd, const char *arg);

/* The option loop of every command (cli_getopt.c), over glibc's
 * getopt_long. rb_cli_getopt_next returns an option's value (its short
 * letter or long val) with its value in arg and its name as written in
 * name; 1 for an operand (in arg); ':' when the option in name lacks its
 * value; '?' after printing an unknown option; -1 at the end. */
typedef struct {
    const char *cmd;
    int argc;
    char **argv;
    char optstring[32];
    const struct option *longs;
    int rest;                 /* after "--": operands only */
    const char *arg;
    char name[64];
} rb_cli_getopt;

void rb_cli_getopt_init(rb_cli_getopt *g, const char *cmd, int argc, char **argv,
                        const char *shorts, const struct option *longs);
int rb_cli_getopt_next(rb_cli_getopt *g);

/* Diagnostics on stderr, one line each. */
#if defined(__GNUC__)
#define RB_PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define RB_PRINTF_LIKE(f, a)
#endif

/* "FILE:LINE:COL: error: KEY: MESSAGE"; FILE defaults to "rockbolt", the
 * position is left out when unknown, "KEY: " when the key is empty. */
void rb_cli_diag_print(const rb_diag *d);
/* The same line to out. */
void rb_cli_diag_fprint(FILE *out, const rb_diag *d);

/* The same for an error with no position: file (NULL: "rockbolt"), key
 * (NULL or "": none) and a printf-style message. */
void rb_cli_error(const char *file, const char *key, const char *fmt, ...)
    RB_PRINTF_LIKE(3, 4);

#endif
