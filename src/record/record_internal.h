/* Pieces shared by the record readers (record_*.c), not part of the public
 * API: a line reader that knows where it is in the file, number tokens,
 * a bounded growing buffer of values, and diagnostics that name the file,
 * line and column. */
#ifndef RB_RECORD_INTERNAL_H
#define RB_RECORD_INTERNAL_H

#include <stdio.h>
#include "rockbolt/record.h"

/* Longest line accepted; real records have lines under 200 characters, so
 * anything longer is not a record and must not make us buffer a whole
 * file. */
#define RB_REC_LINE_MAX 65536
#define RB_REC_DEFAULT_MAX_POINTS 10000000u
/* Bytes in one record file: 10 million samples in the widest common
 * layout (E15.7 with a blank, 16 bytes each) take 160 MB; past 256 MiB a
 * file is refused before reading (1 GiB of blank lines was read for 45 s). */
#define RB_REC_MAX_BYTES (256ull * 1024 * 1024)

#if defined(__GNUC__)
#define RB_REC_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define RB_REC_PRINTF(fmt, args)
#endif

typedef struct {
    FILE *fp;
    const char *path;
    rb_diag *diag;   /* may be NULL */
    char *line;      /* the current line without its end, NUL-terminated */
    size_t len;
    size_t cap;
    long lineno;     /* 1-based number of the current line; 0 before any */
    unsigned long long nread; /* bytes read since the start, for the limit */
} rb_rec_reader;

/* Open path for reading; RB_ERR_IO (with diag) if it cannot be opened. */
rb_status rb_rec_reader_open(rb_rec_reader *r, const char *path, rb_diag *diag);
void rb_rec_reader_close(rb_rec_reader *r);
/* Read the next line into r->line. *got is 0 at the end of the file. */
rb_status rb_rec_reader_next(rb_rec_reader *r, int *got);
/* Back to before the first line. */
rb_status rb_rec_reader_rewind(rb_rec_reader *r);

/* Fill the diag (file, line, col, message) and return status. */
rb_status rb_rec_fail_at(const rb_rec_reader *r, rb_status status, long line,
                         int col, const char *fmt, ...) RB_REC_PRINTF(5, 6);
/* The same at the current line. */
rb_status rb_rec_fail(const rb_rec_reader *r, rb_status status, int col,
                      const char *fmt, ...) RB_REC_PRINTF(4, 5);
/* The same at the end of the file (after the last character read). */
rb_status rb_rec_fail_eof(const rb_rec_reader *r, rb_status status,
                          const char *fmt, ...) RB_REC_PRINTF(3, 4);

/* A stretch of the current line. col is 1-based. */
typedef struct {
    const char *s;
    size_t len;
    int col;
} rb_rec_token;

/* The next token of line from *pos on, separated by blanks (and commas
 * when commas is set). 0 when the line has no more. */
int rb_rec_token_next(const char *line, size_t *pos, int commas, rb_rec_token *tok);
/* The fixed-width field [start, start + width) of the current line, with
 * its blanks trimmed; 0 when the line ends before start. */
int rb_rec_token_field(const rb_rec_reader *r, size_t start, size_t width,
                       rb_rec_token *tok);
/* Parse a decimal number (Fortran D exponents allowed). RB_ERR_PARSE for
 * anything else, RB_ERR_INVALID for NaN, infinity and overflow. */
rb_status rb_rec_number_parse(const char *s, size_t len, double *out);
/* The same, filling the diag: what names what the token was expected to
 * be ("an acceleration value"). */
rb_status rb_rec_token_number(const rb_rec_reader *r, const rb_rec_token *tok,
                              const char *what, double *out);
/* A non-negative integer token (digits only) into *out; values above
 * limit (which must be below SIZE_MAX / 16) come out as limit + 1.
 * RB_ERR_PARSE with diag otherwise. */
rb_status rb_rec_token_count(const rb_rec_reader *r, const rb_rec_token *tok,
                             const char *what, size_t limit, size_t *out);
/* Case-insensitive search of word in the first len bytes of s; returns
 * the offset or -1. */
long rb_rec_find(const char *s, size_t len, const char *word);

/* Values read so far, grown geometrically up to max. */
typedef struct {
    double *v;
    size_t n;
    size_t cap;
    size_t max;
} rb_rec_values;

void rb_rec_values_init(rb_rec_values *b, size_t max);
void rb_rec_values_free(rb_rec_values *b);
/* Append raw * factor; RB_ERR_LIMIT, RB_ERR_NOMEM or RB_ERR_INVALID (a
 * product that overflows) with the diag pointing at tok. */
rb_status rb_rec_values_push(rb_rec_values *b, const rb_rec_reader *r,
                             const rb_rec_token *tok, double raw, double factor);
/* Hand the values to out (which then owns them); b is left empty. */
void rb_rec_values_move(rb_rec_values *b, double dt_s, double t0_s, rb_series *out);

/* The factor to m/s^2 of a unit named in a record ("G", "cm/sec/sec",
 * "gal", "(g)"); 0 if the name is not an acceleration unit we know. */
double rb_rec_units_lookup(const char *name, size_t len);
/* The options' max_points with 0 meaning the default, and never more than
 * an array of doubles can hold. */
size_t rb_rec_max_points(const rb_record_opts *o);
/* Check a dt the file states against the options' dt_s, if any. */
rb_status rb_rec_check_dt(const rb_rec_reader *r, const rb_record_opts *o,
                          double file_dt, double rel_tol, long line, int col);

rb_status rb_record_read_at2(rb_rec_reader *r, const rb_record_opts *o, rb_series *out);
rb_status rb_record_read_cosmos(rb_rec_reader *r, const rb_record_opts *o, rb_series *out);
rb_status rb_record_read_two_column(rb_rec_reader *r, const rb_record_opts *o,
                                    rb_series *out);
rb_status rb_record_read_one_column(rb_rec_reader *r, const rb_record_opts *o,
                                    rb_series *out);

#endif
