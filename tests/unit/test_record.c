/* Record reading: the shipped records against their provenance (count,
 * step, peak, its sign and time), every accepted header form and unit
 * spelling, and every refusal with the status, line and column it must
 * report. Bad files are written into a fresh temporary directory. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "harness.h"
#include "rockbolt/model.h"
#include "rockbolt/record.h"

static char tmp_dir[256];
static char tmp_path[512];
static char made[64][512];
static int n_made;

/* Write text (len bytes, or strlen if len is 0) to tmp_dir/name. */
static const char *put_n(const char *name, const char *text, size_t len)
{
    snprintf(tmp_path, sizeof tmp_path, "%s/%s", tmp_dir, name);
    FILE *f = fopen(tmp_path, "wb");
    if (!f || fwrite(text, 1, len, f) != len) {
        fprintf(stderr, "cannot write %s\n", tmp_path);
        exit(2);
    }
    fclose(f);
    int seen = 0;
    for (int i = 0; i < n_made; i++)
        seen |= strcmp(made[i], tmp_path) == 0;
    if (!seen && n_made < 64)
        snprintf(made[n_made++], sizeof made[0], "%s", tmp_path);
    return tmp_path;
}

static const char *put(const char *name, const char *text)
{
    return put_n(name, text, strlen(text));
}

static rb_record_opts opts_g(void)
{
    rb_record_opts o;
    rb_record_opts_init(&o);
    o.units_to_mps2 = RB_G0;
    return o;
}

/* Read expecting failure: out must come back empty. */
static rb_status read_fail(const char *path, const rb_record_opts *o, rb_diag *d)
{
    rb_series s;
    rb_status st = rb_record_read(path, o, &s, d);
    CHECK(s.accel_mps2 == NULL && s.n == 0);
    rb_series_free(&s);
    return st;
}

#define EXPECT_FAIL(path, opts, want, want_line, want_col, needle) do { \
    rb_diag d_; rb_status s_ = read_fail((path), (opts), &d_); \
    int ok_ = s_ == (want) && d_.line == (want_line) && d_.col == (want_col) \
              && strstr(d_.msg, (needle)) != NULL && strcmp(d_.file, (path)) == 0; \
    CHECK(ok_); \
    if (!ok_) fprintf(stderr, "  got status %d at %d:%d: %s\n", (int)s_, d_.line, \
                      d_.col, d_.msg); } while (0)

typedef struct {
    const char *path;
    rb_record_format format;
    double dt_opt;
    size_t npts;
    double dt;
    double pga_g;     /* signed */
    double t_peak;
    double first_g;
} shipped;

static void test_shipped_records(void)
{
    const shipped recs[] = {
        {"cases/records/elcentro_1940_ns.at2", RB_REC_AT2, 0.0, 4000, 0.01,
         -0.3129, 2.15, -0.6403182e-02},
        {"cases/records/elcentro_1940_ns_ngawest2.at2", RB_REC_AT2, 0.0, 5372, 0.01,
         -0.2808, 2.18, 0.9984852e-03},
        {"cases/records/elcentro_1940_ns_peknold.at2", RB_REC_AT2, 0.0, 1559, 0.02,
         -0.3188, 2.02, 0.00630},
        {"cases/records/taft_1952_s69e.txt", RB_REC_ONE_COLUMN, 0.01, 5437, 0.01,
         -0.1803, 3.75, -0.0005621619},
    };
    for (size_t k = 0; k < sizeof recs / sizeof recs[0]; k++) {
        for (int pass = 0; pass < 2; pass++) {
            rb_record_opts o = opts_g();
            rb_series s;
            rb_diag d;
            o.format = pass ? recs[k].format : RB_REC_AUTO;
            o.dt_s = recs[k].dt_opt;
            rb_status st = rb_record_read(recs[k].path, &o, &s, &d);
            CHECK(st == RB_OK);
            if (st != RB_OK) {
                fprintf(stderr, "  %s:%d:%d: %s\n", d.file, d.line, d.col, d.msg);
                continue;
            }
            size_t ip = 0;
            for (size_t i = 0; i < s.n; i++)
                if (fabs(s.accel_mps2[i]) > fabs(s.accel_mps2[ip]))
                    ip = i;
            CHECK(s.n == recs[k].npts);
            CHECK_REL(s.dt_s, recs[k].dt, 1e-12);
            CHECK(s.t0_s == 0.0);
            CHECK_NEAR(s.accel_mps2[ip] / RB_G0, recs[k].pga_g, 0.00005);
            CHECK_NEAR((double)ip * s.dt_s, recs[k].t_peak, 1e-9);
            CHECK_REL(s.accel_mps2[0], recs[k].first_g * RB_G0, 1e-12);
            CHECK_REL(rb_series_peak(&s), fabs(s.accel_mps2[ip]), 0.0);
            rb_series_free(&s);
        }
    }
}

static void test_units(void)
{
    const struct { const char *name; double f; } ok[] = {
        {"g", RB_G0}, {"G", RB_G0}, {"(g)", RB_G0}, {"G.", RB_G0},
        {"m/s^2", 1.0}, {"M/S2", 1.0}, {"m/sec/sec", 1.0},
        {"cm/s^2", 0.01}, {"CM/SEC/SEC", 0.01}, {"cm/sec2", 0.01}, {"gal", 0.01},
        {"Gal", 0.01}, {"in/s^2", 0.0254}, {"IN/SEC/SEC", 0.0254},
        {"mm/s^2", 0.001}, {"mm/s/s", 0.001}, {"ft/s^2", 0.3048}, {"mg", 1e-3 * RB_G0},
    };
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++) {
        double f = 0.0;
        CHECK(rb_record_units_parse(ok[i].name, &f) == RB_OK);
        CHECK_REL(f, ok[i].f, 1e-15);
    }
    const char *bad[] = {"", "cm/s", "cm", "furlongs", "kg", "m/s^3", "gg"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        double f = -1.0;
        CHECK(rb_record_units_parse(bad[i], &f) == RB_ERR_PARSE && f == -1.0);
    }
    CHECK(rb_record_units_parse(NULL, NULL) == RB_ERR_INVALID);
}

/* Read a file expected to be good; returns n and fills s. */
static size_t read_ok(const char *path, const rb_record_opts *o, rb_series *s)
{
    rb_diag d;
    rb_status st = rb_record_read(path, o, s, &d);
    CHECK(st == RB_OK);
    if (st != RB_OK)
        fprintf(stderr, "  %s:%d:%d: %s\n", d.file, d.line, d.col, d.msg);
    return st == RB_OK ? s->n : 0;
}

static void test_at2_forms(void)
{
    rb_record_opts o;
    rb_record_opts_init(&o);
    rb_series s;
    /* Units from line 3 win; D exponents; CRLF line ends; no final newline. */
    const char *p = put("a.at2", "PEER\r\nX\r\nACCELERATION IN UNITS OF CM/SEC/SEC\r\n"
                        "NPTS=  3, DT= .00500 SEC\r\n  1.0D+01  -2.5 \r\n 3E0");
    if (read_ok(p, &o, &s) == 3) {
        CHECK_REL(s.accel_mps2[0], 0.10, 1e-15);
        CHECK_REL(s.accel_mps2[1], -0.025, 1e-15);
        CHECK_REL(s.accel_mps2[2], 0.03, 1e-15);
        CHECK(s.dt_s == 0.005);
    }
    rb_series_free(&s);
    /* Positional line 4 of early NGA files, units "(g)", name without .at2. */
    p = put("b.dat", "x\ny\nThe units are (g)\n  2   0.0200   NPTS, DT\n .5 -.25\n");
    if (read_ok(p, &o, &s) == 2) {
        CHECK_REL(s.accel_mps2[1], -0.25 * RB_G0, 1e-15);
        CHECK(s.dt_s == 0.02);
    }
    rb_series_free(&s);
    /* No units on line 3: the options' factor is used. */
    o.units_to_mps2 = 2.0;
    p = put("c.at2", "x\ny\nz\nNPTS=2, DT=0.01 SEC,\n1 2\n");
    if (read_ok(p, &o, &s) == 2)
        CHECK(s.accel_mps2[1] == 4.0);
    rb_series_free(&s);
    /* A matching dt_s in the options is accepted. */
    o.dt_s = 0.01;
    CHECK(read_ok(p, &o, &s) == 2);
    rb_series_free(&s);
}

/* A file that is not a record (a system file, a secret) is refused at a
 * line and column with what was expected, and none of its text is quoted:
 * the message goes into JUnit, JSON and CSV artefacts. */
static void test_no_content_quoted(void)
{
    static const char *const bodies[] = {
        "root:x:0:0:root:/root:/bin/bash\n",
        "0.1\nsecret-token-1234\n",
        "0 1\n0.01 secret-token-1234\n",
        "a\nb\nIN UNITS OF secret-token-1234\nNPTS=1, DT=.01\n1\n",
        "PEER\nX\nUNITS OF G\nsecret-token-1234\n",
        "PEER\nX\nUNITS OF G\nNPTS= secret-token-1234, DT= .01 SEC\n",
        "PEER\nX\nUNITS OF G\nNPTS= 2, DT= secret SEC\n",
    };
    rb_record_opts o;
    rb_record_opts_init(&o);
    for (size_t i = 0; i < sizeof bodies / sizeof bodies[0]; i++) {
        rb_diag d;
        const char *path = put(i >= 4 ? "q.at2" : "q.txt", bodies[i]);
        o.units_to_mps2 = i >= 3 ? 0.0 : 9.80665;
        o.dt_s = i == 1 ? 0.01 : 0.0;
        rb_status st = read_fail(path, &o, &d);
        CHECK(st != RB_OK && d.line > 0 && d.msg[0]);
        CHECK(!strstr(d.msg, "root") && !strstr(d.msg, "secret"));
        if (strstr(d.msg, "root") || strstr(d.msg, "secret"))
            fprintf(stderr, "  quoted: %s\n", d.msg);
    }
}

static void test_at2_errors(void)
{
    rb_record_opts o;
    rb_record_opts_init(&o);
    const char *h = "PEER\nX\nUNITS OF G\n";
    char buf[512];
#define AT2(body) (snprintf(buf, sizeof buf, "%s%s", h, body), put("e.at2", buf))
    EXPECT_FAIL(AT2("NPTS=  3, DT= .01 SEC\n 1 2 abc\n"), &o, RB_ERR_PARSE, 5, 6,
                "(a number), found text that is not a number");
    EXPECT_FAIL(AT2("NPTS=  3, DT= .01 SEC\n 1 2\n\n"), &o, RB_ERR_PARSE, 6, 1,
                "NPTS = 3, found the end of the file after 2 values");
    EXPECT_FAIL(AT2("NPTS=  3, DT= .01 SEC\n 1 2\n 3  4\n"), &o, RB_ERR_PARSE, 6, 5,
                "found more values");
    EXPECT_FAIL(AT2("NPTS=  3, DT= 0.0 SEC\n 1 2 3\n"), &o, RB_ERR_INVALID, 4, 15,
                "expected DT > 0 s, found a number at or below zero");
    EXPECT_FAIL(AT2("NPTS=  3, DT= -.01 SEC\n 1 2 3\n"), &o, RB_ERR_INVALID, 4, 15,
                "at or below zero");
    EXPECT_FAIL(AT2("NPTS=  3, DT= NaN SEC\n 1 2 3\n"), &o, RB_ERR_INVALID, 4, 15,
                "finite number, found NaN, infinity");
    EXPECT_FAIL(AT2("NPTS=  3, DT= 1e999 SEC\n 1 2 3\n"), &o, RB_ERR_INVALID, 4, 15,
                "finite");
    EXPECT_FAIL(AT2("NPTS=  3, DT= .01 SEC\n 1 nan 3\n"), &o, RB_ERR_INVALID, 5, 4,
                "finite number, found NaN, infinity");
    EXPECT_FAIL(AT2("NPTS=  3, DT= .01 SEC\n 1 2\n-INF\n"), &o, RB_ERR_INVALID, 6, 1,
                "finite number, found NaN");
    EXPECT_FAIL(AT2("NPTS=  3, DT= .01 SEC\n 1 2 1e400\n"), &o, RB_ERR_INVALID, 5, 6,
                "out of range");
    EXPECT_FAIL(AT2("NPTS=  3, DT= .01 SEC\n 1 0x10 3\n"), &o, RB_ERR_PARSE, 5, 4,
                "found text that is not a number");
    EXPECT_FAIL(AT2("NPTS=  abc, DT= .01 SEC\n"), &o, RB_ERR_PARSE, 4, 8,
                "NPTS (a whole number), found text that is not one");
    EXPECT_FAIL(AT2("NPTS=  0, DT= .01 SEC\n"), &o, RB_ERR_INVALID, 4, 8, "NPTS > 0");
    EXPECT_FAIL(AT2("NPTS=  3\n"), &o, RB_ERR_PARSE, 4, 9, "expected 'DT=");
    EXPECT_FAIL(AT2("NPTS=  3, DT=\n"), &o, RB_ERR_PARSE, 4, 14, "after 'DT='");
    EXPECT_FAIL(AT2("hello\n"), &o, RB_ERR_PARSE, 4, 1, "expected 'NPTS= <n>");
    EXPECT_FAIL(AT2(""), &o, RB_ERR_PARSE, 3, 11, "4 header lines");
    o.max_points = 5;
    EXPECT_FAIL(AT2("NPTS=  6, DT= .01 SEC\n1 2 3 4 5 6\n"), &o, RB_ERR_LIMIT, 4, 8,
                "point limit of 5");
    o.max_points = 0;
    EXPECT_FAIL(AT2("NPTS=99999999999999999999999, DT= .01 SEC\n"), &o, RB_ERR_LIMIT,
                4, 6, "point limit of 10000000");
    o.dt_s = 0.02;
    EXPECT_FAIL(AT2("NPTS=  1, DT= .01 SEC\n1\n"), &o, RB_ERR_INVALID, 4, 1,
                "the file gives dt = 0.01 s but the options say dt = 0.02 s");
    o.dt_s = 0.0;
    EXPECT_FAIL(put("u.at2", "a\nb\nIN UNITS OF FURLONGS/FORTNIGHT\nNPTS=1, DT=.01\n1\n"),
                &o, RB_ERR_PARSE, 3, 13, "after 'UNITS', found other text");
    EXPECT_FAIL(put("u.at2", "a\nb\nnothing useful\nNPTS=1, DT=.01\n1\n"),
                &o, RB_ERR_INVALID, 3, 1, "give units_to_mps2");
    EXPECT_FAIL(put("u.at2", "a\nb\nVELOCITY TIME HISTORY IN UNITS OF CM/S\nNPTS=1, DT=.01\n1\n"),
                &o, RB_ERR_PARSE, 3, 1, "found a velocity record");
#undef AT2
}

/* Appended to the first integer-header line by cosmos4 (blanks that cut
 * the last field short). */
static const char *cosmos_int_tail = "";

/* A COSMOS V2 file with 2-line integer and real headers; the data block
 * line and values are given. dt is in real-header entry 62 (ms). */
static const char *cosmos4(const char *units_code, const char *dt_ms, const char *dt_s,
                           const char *block)
{
    static char buf[8192];
    char ints[512], reals[2048];
    snprintf(ints, sizeof ints, "  20 Integer-header values follow on  2 lines, Format= (10I8)\n"
             "       2       1%8s     120       1    -999    -999    -999    -999%s\n"
             "    -999    -999    -999    -999    -999    -999    -999    -999    -999    -999"
             "    -999\n", units_code, cosmos_int_tail);
    size_t n = (size_t)snprintf(reals, sizeof reals,
                                "  65 Real-header values follow on 13 lines, Format= (5F15.6)\n");
    for (int i = 1; i <= 65; i++) {
        const char *v = i == 62 ? dt_ms : i == 34 ? dt_s : "-999.0";
        n += (size_t)snprintf(reals + n, sizeof reals - n, "%15s%s", v, i % 5 ? "" : "\n");
    }
    snprintf(buf, sizeof buf,
             "Corrected acceleration    (Format v01.20 with 13 text lines) Src: test\n"
             "line 2\nline 3\nline 4\nline 5\nline 6\nline 7\nline 8\nline 9\n"
             "line 10\nline 11\nline 12\n"
             "Values used when parameter or data value is unknown/unspecified:   -999, -999.0\n"
             "%s%s   2 Comment line(s) follow, each starting with a \"|\":\n| one\n| two\n%s",
             ints, reals, block);
    return put("rec.V2", buf);
}

static const char *cosmos(const char *units_code, const char *dt_ms, const char *block)
{
    return cosmos4(units_code, dt_ms, "0.005", block);
}

static void test_cosmos(void)
{
    rb_record_opts o;
    rb_series s;
    rb_record_opts_init(&o);
    /* Fields of F10.5 that touch, cm/s^2 from code 4, dt 10 ms. */
    const char *p = cosmos("4", "10.0",
        "       5 acceleration pts, approx    0 secs, units=cm/sec2 (04), Format=(3F10.5)\n"
        "-123.45678  98.76543   0.00001\n"
        "   1.00000-200.00000\n"
        "End-of-data for Chan  1 acceleration\n");
    if (read_ok(p, &o, &s) == 5) {
        CHECK_REL(s.accel_mps2[0], -1.2345678, 1e-14);
        CHECK_REL(s.accel_mps2[4], -2.0, 1e-14);
        CHECK_REL(s.dt_s, 0.01, 1e-15);
    }
    rb_series_free(&s);
    /* Unknown units code: the data line's text; unknown R62: R34 in s. */
    p = cosmos("-999", "-999.0",
        "       2 acceleration pts, approx    0 secs, units=g (02), Format=(2E15.6)\n"
        "   1.000000E-01  -2.000000E-01\n");
    if (read_ok(p, &o, &s) == 2) {
        CHECK_REL(s.accel_mps2[1], -0.2 * RB_G0, 1e-14);
        CHECK_REL(s.dt_s, 0.005, 1e-15);
    }
    rb_series_free(&s);
    /* Header is 13 text + 3 int + 14 real + 3 comment lines: data line 34. */
    const char *line = "       3 acceleration pts, approx    0 secs, units=cm/sec2 (04), "
                       "Format=(3F10.5)\n";
    char blk[512];
    snprintf(blk, sizeof blk, "%s   1.00000   2.00000\nEnd-of-data for Chan  1\n", line);
    EXPECT_FAIL(cosmos("4", "10.0", blk), &o, RB_ERR_PARSE, 36, 1,
                "says 3 points, found the end of the block after 2");
    snprintf(blk, sizeof blk, "%s   1.00000   2.00000\n", line);
    EXPECT_FAIL(cosmos("4", "10.0", blk), &o, RB_ERR_PARSE, 35, 21,
                "found the end of the file after 2");
    snprintf(blk, sizeof blk, "%s   1.00000   2.00000   3.00000   4.00000\n", line);
    EXPECT_FAIL(cosmos("4", "10.0", blk), &o, RB_ERR_PARSE, 35, 34, "found more values");
    snprintf(blk, sizeof blk, "%s   1.00000   2.00000   3.00000\n   4.00000\n", line);
    EXPECT_FAIL(cosmos("4", "10.0", blk), &o, RB_ERR_PARSE, 36, 4, "found more values");
    snprintf(blk, sizeof blk, "%s   1.00000   2.0x000   3.00000\n", line);
    EXPECT_FAIL(cosmos("4", "10.0", blk), &o, RB_ERR_PARSE, 35, 14, "found text that is not a number");
    snprintf(blk, sizeof blk, "%s   1.00000             3.00000\n", line);
    EXPECT_FAIL(cosmos("4", "10.0", blk), &o, RB_ERR_PARSE, 35, 11, "found text that is not a number");
    snprintf(blk, sizeof blk, "%s   1.00000   2.00000   3.00000\n", line);
    EXPECT_FAIL(cosmos4("4", "-999.0", "-999.0", blk), &o, RB_ERR_INVALID, 34, 1,
                "time step");
    EXPECT_FAIL(cosmos("4", "0.0", blk), &o, RB_ERR_INVALID, 34, 1, "time step");
    EXPECT_FAIL(cosmos("4", "10.0", "    3 velocity pts, approx 0 secs\n"), &o,
                RB_ERR_PARSE, 34, 1, "expected an acceleration data block");
    o.max_points = 2;
    EXPECT_FAIL(cosmos("4", "10.0", blk), &o, RB_ERR_LIMIT, 34, 8, "point limit of 2");
    o.max_points = 0;
    /* A header line that ends in a field of blanks cut short (found by
     * the fuzzer: the search for text after that blank field read past
     * the end of the line). The blanks are no value: line 1 holds 9, line
     * 2 holds 11, and the 20 values stand. */
    cosmos_int_tail = "   ";
    if (read_ok(cosmos("4", "10.0", blk), &o, &s) == 3)
        CHECK_REL(s.dt_s, 0.01, 1e-15);
    rb_series_free(&s);
    cosmos_int_tail = "";
    EXPECT_FAIL(put("x.v2", "Corrected acceleration  no format marker\n"), &o,
                RB_ERR_PARSE, 1, 1, "expected a COSMOS header line");
}

static void test_two_column(void)
{
    rb_record_opts o = opts_g();
    rb_series s;
    const char *p = put("t.csv", "# time, accel\n1.000, 0.1\n1.005,-0.2\n\n1.010 , 0.3\n");
    if (read_ok(p, &o, &s) == 3) {
        CHECK_REL(s.dt_s, 0.005, 1e-12);
        CHECK(s.t0_s == 1.0);
        CHECK_REL(s.accel_mps2[1], -0.2 * RB_G0, 1e-15);
    }
    rb_series_free(&s);
    /* Times printed to 3 digits round by up to 0.1 % of the step: accepted. */
    p = put("t.txt", "0 1\n0.333 2\n0.667 3\n1.000 4\n1.333 5\n");
    if (read_ok(p, &o, &s) == 5)
        CHECK_REL(s.dt_s, 0.33325, 1e-12);
    rb_series_free(&s);
    EXPECT_FAIL(put("t.txt", "0 1\n0.01 2\n0.02 3\n0.04 4\n0.05 5\n"), &o, RB_ERR_INVALID,
                4, 1, "expected a uniform time step of 0.01 s");
    EXPECT_FAIL(put("t.txt", "0 1\n0 2\n"), &o, RB_ERR_INVALID, 2, 1,
                "expected times to increase");
    EXPECT_FAIL(put("t.txt", "0 1\n0.01 2\n0.02\n"), &o, RB_ERR_PARSE, 3, 5,
                "found one");
    EXPECT_FAIL(put("t.txt", "0 1\n0.01 2 7\n"), &o, RB_ERR_PARSE, 2, 8,
                "found more");
    EXPECT_FAIL(put("t.txt", "0 1\n0.01 x2\n"), &o, RB_ERR_PARSE, 2, 6, "found text that is not a number");
    EXPECT_FAIL(put("t.txt", "0 1\n0.01 inf\n"), &o, RB_ERR_INVALID, 2, 6, "found NaN, infinity");
    EXPECT_FAIL(put("t.txt", "0 1\n"), &o, RB_ERR_INVALID, 1, 0, "at least two rows");
    o.dt_s = 0.02;
    EXPECT_FAIL(put("t.txt", "0 1\n0.01 2\n"), &o, RB_ERR_INVALID, 0, 0,
                "the options say dt = 0.02 s");
    o.units_to_mps2 = 0.0;
    EXPECT_FAIL(put("t.txt", "0 1\n0.02 2\n"), &o, RB_ERR_INVALID, 0, 0,
                "give units_to_mps2");
}

static void test_one_column(void)
{
    rb_record_opts o = opts_g();
    rb_series s;
    o.dt_s = 0.005;
    const char *p = put("o.txt", "0.5\n\n# note\n-0.25\n");
    if (read_ok(p, &o, &s) == 2) {
        CHECK(s.dt_s == 0.005 && s.t0_s == 0.0);
        CHECK_REL(s.accel_mps2[1], -0.25 * RB_G0, 1e-15);
    }
    rb_series_free(&s);
    EXPECT_FAIL(put("o.txt", "0.5\n0.5 0.25\n"), &o, RB_ERR_PARSE, 2, 5,
                "one value per row");
    o.format = RB_REC_TWO_COLUMN;
    EXPECT_FAIL(put("o.txt", "0.5\n0.25\n"), &o, RB_ERR_PARSE, 1, 4,
                "(time, acceleration), found one");
    o.format = RB_REC_ONE_COLUMN;
    o.max_points = 3;
    EXPECT_FAIL(put("o.txt", "1\n2\n3\n4\n"), &o, RB_ERR_LIMIT, 4, 1,
                "more than 3 values (the point limit)");
    o.max_points = 0;
    EXPECT_FAIL(put("o.txt", "\n# only a comment\n\n"), &o, RB_ERR_PARSE, 3, 1,
                "found none");
    o.dt_s = 0.0;
    EXPECT_FAIL(put("o.txt", "1\n"), &o, RB_ERR_INVALID, 0, 0, "give dt_s > 0");
}

static void test_files_and_options(void)
{
    rb_record_opts o = opts_g();
    o.dt_s = 0.01;
    char missing[600];
    snprintf(missing, sizeof missing, "%s/no-such-file.at2", tmp_dir);
    EXPECT_FAIL(missing, &o, RB_ERR_IO, 0, 0, "cannot open the file");
    EXPECT_FAIL(tmp_dir, &o, RB_ERR_IO, 0, 0, "expected a regular file");
    EXPECT_FAIL("/dev/null", &o, RB_ERR_IO, 0, 0, "expected a regular file");
    EXPECT_FAIL(put("empty.txt", ""), &o, RB_ERR_PARSE, 1, 1, "empty file");
    EXPECT_FAIL(put("blank.txt", "\n  \n"), &o, RB_ERR_PARSE, 2, 3, "found no data");
    EXPECT_FAIL(put("words.txt", "hello world\n"), &o, RB_ERR_PARSE, 1, 1,
                "cannot tell the format");
    EXPECT_FAIL(put("three.txt", "1 2 3\n"), &o, RB_ERR_PARSE, 1, 1, "found 3 values");
    EXPECT_FAIL(put_n("nul.txt", "0.1\n0.\0002\n", 9), &o, RB_ERR_PARSE, 2, 3,
                "NUL byte");
    char *longline = malloc(70000);
    if (longline) {
        memset(longline, ' ', 69998);
        longline[0] = '1';
        longline[69998] = '\n';
        longline[69999] = '\0';
        EXPECT_FAIL(put("long.txt", longline), &o, RB_ERR_LIMIT, 1, 65537,
                    "longer than 65536");
        free(longline);
    }
    rb_record_opts bad = o;
    bad.units_to_mps2 = -1.0;
    EXPECT_FAIL(put("ok.txt", "1\n"), &bad, RB_ERR_INVALID, 0, 0, "units_to_mps2");
    bad = o;
    bad.dt_s = NAN;
    EXPECT_FAIL(put("ok.txt", "1\n"), &bad, RB_ERR_INVALID, 0, 0, "dt_s");
    bad = o;
    bad.format = (rb_record_format)42;
    EXPECT_FAIL(put("ok.txt", "1\n"), &bad, RB_ERR_INVALID, 0, 0, "format");
    rb_series s;
    CHECK(rb_record_read(NULL, &o, &s, NULL) == RB_ERR_INVALID);
    CHECK(rb_record_read(put("ok.txt", "1\n"), NULL, &s, NULL) == RB_ERR_INVALID);
}

/* Deterministic junk built from the pieces records are made of: whatever
 * comes back, nothing may crash or leak, a failure must say where, and a
 * success must be a usable series. */
static void test_hostile_input(void)
{
    static const char *const pieces[] = {
        "0.1", "-2.5e-3", "7", " ", " ", "  ", "\n", "\n", "\t", ",", "#", "\r\n",
        "NPTS=", "DT=", "UNITS OF G", "nan", "x", "3D2", ".", "-", "1e999", "\n\n",
        "(Format v01.20 with 13 text lines)", "acceleration pts", "SEC"};
    const size_t n_pieces = sizeof pieces / sizeof pieces[0];
    unsigned long x = 987654321UL;
    char buf[1200];
    int good = 0;
    for (int round = 0; round < 1000; round++) {
        size_t len = 0, target = 10 + (size_t)(round % 400);
        if (round % 3 == 0)
            len = (size_t)snprintf(buf, sizeof buf, "a\nb\nUNITS OF G\nNPTS= %d, DT= .01\n",
                                   round % 7);
        while (len < target) {
            x = x * 6364136223846793005UL + 1442695040888963407UL;
            const char *piece = pieces[(x >> 33) % n_pieces];
            size_t k = strlen(piece);
            if (len + k >= sizeof buf)
                break;
            memcpy(buf + len, piece, k);
            len += k;
        }
        const char *p = put_n(round % 2 ? "junk.at2" : "junk.txt", buf, len);
        rb_record_opts o = opts_g();
        o.dt_s = round % 4 ? 0.01 : 0.0;
        rb_series s;
        rb_diag d;
        if (rb_record_read(p, &o, &s, &d) == RB_OK) {
            good++;
            int sane = s.n > 0 && s.dt_s > 0.0 && isfinite(s.dt_s);
            for (size_t i = 0; sane && i < s.n; i++)
                sane = isfinite(s.accel_mps2[i]);
            CHECK(sane);
        } else {
            CHECK(d.msg[0] != '\0' && strcmp(d.file, p) == 0);
        }
        rb_series_free(&s);
    }
    printf("hostile input: %d of 1000 junk files read as records\n", good);
}

int main(void)
{
    snprintf(tmp_dir, sizeof tmp_dir, "%s/rb_record_XXXXXX",
             getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(tmp_dir)) {
        fprintf(stderr, "cannot make a temporary directory\n");
        return 2;
    }
    test_shipped_records();
    test_units();
    test_at2_forms();
    test_at2_errors();
    test_no_content_quoted();
    test_cosmos();
    test_two_column();
    test_one_column();
    test_files_and_options();
    test_hostile_input();
    for (int i = 0; i < n_made; i++)
        remove(made[i]);
    rmdir(tmp_dir);
    TEST_MAIN_END();
}
