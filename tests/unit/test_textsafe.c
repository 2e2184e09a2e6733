/* The shared writers of user text (include/rockbolt/textsafe.h): control
 * characters shown escaped, CSV fields guarded against formulas. */
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/textsafe.h"

static int esc_is(const char *in, const char *want)
{
    char *got = rb_text_escape(in);
    int ok = got && strcmp(got, want) == 0;
    if (!ok)
        fprintf(stderr, "escape: got '%s', want '%s'\n", got ? got : "(null)", want);
    free(got);
    return ok;
}

static int csv_is(const char *in, const char *want)
{
    char *got = rb_csv_field(in, 0);
    int ok = got && strcmp(got, want) == 0;
    if (!ok)
        fprintf(stderr, "csv: got '%s', want '%s'\n", got ? got : "(null)", want);
    free(got);
    return ok;
}

static void test_escape(void)
{
    CHECK(esc_is("plain name", "plain name"));
    CHECK(esc_is("", ""));
    CHECK(esc_is(NULL, ""));
    /* the spoof of the issue: erase the line, draw PASS over FAIL */
    CHECK(esc_is("x\x1b[2K\rPASS", "x\\x1b[2K\\rPASS"));
    CHECK(esc_is("a\tb\nc", "a\\tb\\nc"));
    CHECK(esc_is("\x01\x7f", "\\x01\\x7f"));
    /* UTF-8 is kept, C1 controls (U+009B, CSI) and stray bytes are not */
    CHECK(esc_is("P\xc3\xa9rez \xe2\x80\x94 ok", "P\xc3\xa9rez \xe2\x80\x94 ok"));
    CHECK(esc_is("a\xc2\x9b" "2J", "a\\u009b2J"));
    CHECK(esc_is("\x9b" "2J\xff", "\\x9b2J\\xff"));
    CHECK(esc_is("back\\slash", "back\\slash"));
    /* bidirectional and invisible format characters are shown, not sent:
     * an RLO would reverse the rest of a table line */
    CHECK(esc_is("a\xe2\x80\xae" "b", "a\\u202eb"));
    CHECK(esc_is("\xe2\x81\xa6x\xe2\x81\xa9", "\\u2066x\\u2069"));
    CHECK(esc_is("\xe2\x80\x8b\xe2\x80\x8f\xe2\x80\xa8\xe2\x80\xa9\xef\xbb\xbf",
                 "\\u200b\\u200f\\u2028\\u2029\\ufeff"));
    /* U+FFFE and U+FFFF are not XML 1.0 characters; surrogates' encodings
     * are not UTF-8 */
    CHECK(esc_is("t\xef\xbf\xbe\xef\xbf\xbf", "t\\ufffe\\uffff"));
    CHECK(esc_is("\xed\xa0\x80", "\\xed\\xa0\\x80"));
    /* the characters next to them are kept */
    CHECK(esc_is("\xe2\x80\x8a\xe2\x80\x90\xef\xbf\xbd", "\xe2\x80\x8a\xe2\x80\x90\xef\xbf\xbd"));
    /* preformatted text keeps its lines */
    char *kept = rb_text_escape_lines("a\tb\nc\r\xc2\x85");
    CHECK(kept && strcmp(kept, "a\tb\nc\\r\\u0085") == 0);
    free(kept);
    CHECK(rb_text_needs_escape("x\x1b") && !rb_text_needs_escape("plain \xc3\xa9"));
    /* a fixed buffer never ends in half an escape */
    char buf[6];
    size_t n = rb_text_escape_to(buf, sizeof buf, "ab\x1b" "cd");
    CHECK(n == 8 && strcmp(buf, "ab") == 0);
    CHECK(strcmp(rb_text_escape_buf("abc", buf, sizeof buf), "abc") == 0);
}

static void test_csv(void)
{
    CHECK(csv_is("P-101", "P-101"));
    CHECK(csv_is("P-103, spare", "\"P-103, spare\""));
    CHECK(csv_is("say \"hi\"", "\"say \"\"hi\"\"\""));
    /* formula starters get a quote inside a quoted field */
    CHECK(csv_is("=HYPERLINK(\"http://x\",\"y\")", "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\""));
    CHECK(csv_is("+1+2", "\"'+1+2\""));
    CHECK(csv_is("-1.5", "\"'-1.5\""));
    CHECK(csv_is("@SUM(A1)", "\"'@SUM(A1)\""));
    CHECK(csv_is("\t=1", "\"'\\t=1\""));
    /* after leading blanks too: spreadsheets that trim on import */
    CHECK(csv_is(" =1+1", "\"' =1+1\""));
    CHECK(csv_is("  \t-2", "\"'  \\t-2\""));
    CHECK(csv_is("\xc2\xa0@x", "\"'\xc2\xa0@x\""));
    CHECK(csv_is(" P-1", " P-1"));
    CHECK(csv_is("\r=1", "\"'\\r=1\""));
    /* not at the start: harmless */
    CHECK(csv_is("a=b", "a=b"));
    /* control characters escaped, one row per line */
    CHECK(csv_is("a\nb", "a\\nb"));
    char *q = rb_csv_field("ok", 1);
    CHECK(q && strcmp(q, "\"ok\"") == 0);
    free(q);
}

static int fix_is(const char *in, const char *want)
{
    char *got = rb_utf8_fix(in);
    int ok = got && strcmp(got, want) == 0;
    free(got);
    return ok;
}

/* JSON keeps control characters but must be UTF-8: only bad bytes change */
static void test_utf8(void)
{
    CHECK(rb_utf8_invalid_at("abc", 3) == 3);
    CHECK(rb_utf8_invalid_at("P\xc3\xa9", 3) == 3);
    CHECK(rb_utf8_invalid_at("Pumpe-\xd6l", 9) == 6);       /* cp1252 */
    CHECK(rb_utf8_invalid_at("ab\xc3", 3) == 2);            /* cut short */
    CHECK(rb_utf8_invalid_at("\xc0\xaf", 2) == 0);          /* overlong */
    CHECK(rb_utf8_invalid_at("\xed\xa0\x80", 3) == 0);      /* surrogate */
    CHECK(rb_utf8_invalid_at("\xf0\x9f\x98\x80", 4) == 4);  /* 4 bytes, at the end */
    CHECK(fix_is("Pumpe-\xd6l-1", "Pumpe-\\xd6l-1"));
    CHECK(fix_is("a\x1b\xc3\xa9\xff", "a\x1b\xc3\xa9\\xff"));
    CHECK(fix_is(NULL, ""));
}

static int json_is(const char *in, const char *want)
{
    char *got = rb_json_escape_format(in);
    int ok = got && strcmp(got, want) == 0;
    free(got);
    return ok;
}

/* JSON text: the format characters and C1 controls become \u escapes,
 * everything else (ASCII, other UTF-8, 4-byte characters, bytes that are
 * not UTF-8, JSON's own escapes) is left as it is */
static void test_json(void)
{
    CHECK(json_is("{\"a\":\t\"x\"}", "{\"a\":\t\"x\"}"));
    CHECK(json_is("\"a\xe2\x80\xae" "b\"", "\"a\\u202eb\""));
    CHECK(json_is("\xe2\x80\xaa\xe2\x80\xab\xe2\x80\xac\xe2\x80\xad",
                  "\\u202a\\u202b\\u202c\\u202d"));
    CHECK(json_is("\xe2\x81\xa6\xe2\x81\xa7\xe2\x81\xa8\xe2\x81\xa9",
                  "\\u2066\\u2067\\u2068\\u2069"));
    CHECK(json_is("\xe2\x80\x8b\xe2\x80\x8c\xe2\x80\x8d\xe2\x80\x8e\xe2\x80\x8f",
                  "\\u200b\\u200c\\u200d\\u200e\\u200f"));
    CHECK(json_is("\xe2\x80\xa8\xe2\x80\xa9\xef\xbb\xbf\xc2\x85",
                  "\\u2028\\u2029\\ufeff\\u0085"));
    CHECK(json_is("P\xc3\xa9rez \xe2\x80\x94 \xf0\x9f\x98\x80",
                  "P\xc3\xa9rez \xe2\x80\x94 \xf0\x9f\x98\x80"));
    CHECK(json_is("\\u202e \xff\xe2\x80", "\\u202e \xff\xe2\x80"));
    CHECK(json_is("", ""));
}

int main(void)
{
    test_escape();
    test_csv();
    test_utf8();
    test_json();
    TEST_MAIN_END();
}
