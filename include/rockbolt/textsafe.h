/* User text on its way out: names, tags, paths and messages that came from
 * case files and lists reach terminals, text reports, JUnit and CSV. Two
 * shared writers keep them harmless there (docs/robustness.md, "Text from
 * inputs in outputs"):
 *
 * - rb_text_escape shows control characters instead of sending them, so a
 *   name with "\e[2K\rPASS" cannot redraw a FAIL line as PASS: C0 controls
 *   and DEL as \t, \n, \r or \xHH (ESC is \x1b), C1 controls written in
 *   UTF-8 as \u0080 to \u009f, the bidirectional and invisible format
 *   characters (U+200B to U+200F, U+2028 to U+202E, U+2066 to U+2069 and
 *   their kin) and U+FFFE, U+FFFF (not XML 1.0) as \u202e, and bytes that
 *   are not UTF-8 (surrogates' encodings included) as \xHH. Every other
 *   character, backslash included, is kept as it is.
 * - rb_csv_field writes one CSV text field: escaped as above, then, when
 *   it begins with '=', '+', '-', '@', a tab or a carriage return (the
 *   characters spreadsheets take as the start of a formula), also after
 *   leading blanks (which spreadsheets may trim on import), prefixed with
 *   a single quote inside a quoted field; quoted also when it holds a comma
 *   or a double quote (doubled). Numbers are not text fields: columns of
 *   numbers are written with printf and never pass through here. */
#ifndef ROCKBOLT_TEXTSAFE_H
#define ROCKBOLT_TEXTSAFE_H

#include <stddef.h>
#include <stdio.h>

/* Like snprintf: writes at most size - 1 bytes and a NUL (never a partial
 * escape or character) into out, and returns the length the whole escaped
 * text needs. s NULL is "". */
size_t rb_text_escape_to(char *out, size_t size, const char *s);

/* The escaped text in a fixed buffer (truncated, as rb_text_escape_to);
 * returns out, so it can be passed straight to printf. */
const char *rb_text_escape_buf(const char *s, char *out, size_t size);

/* The escaped text in a new string (free it); NULL on NOMEM. */
char *rb_text_escape(const char *s);

/* As rb_text_escape, but tab and newline are kept as they are: for
 * preformatted text in HTML and SVG (rb_plot_escape adds XML's own). */
char *rb_text_escape_lines(const char *s);

/* The characters a terminal shows for escaped text s (code points; a byte
 * that is not UTF-8 counts as one), for padding it in a column. */
size_t rb_text_width(const char *s);

/* Whether s needs escaping at all (has a byte that would change). */
int rb_text_needs_escape(const char *s);

/* One CSV text field, as above, in a new string (free it); NULL on NOMEM.
 * always_quote puts quotes around it even when none are needed. */
char *rb_csv_field(const char *s, int always_quote);

/* The same field written to fp; 0, or -1 on NOMEM or a write error. */
int rb_csv_field_write(FILE *fp, const char *s, int always_quote);

/* Where the first byte that is not part of valid UTF-8 lies in s[0..len)
 * (overlong forms and surrogates are invalid); len if there is none. */
size_t rb_utf8_invalid_at(const char *s, size_t len);

/* s with each byte that is not UTF-8 written as \xHH and nothing else
 * changed, in a new string (free it); NULL on NOMEM. For outputs that
 * keep control characters but must be UTF-8 (JSON). s NULL is "". */
char *rb_utf8_fix(const char *s);

/* JSON text (as cJSON prints it) with each C1 control and each of the
 * format characters rb_text_escape shows as \uXXXX written as that JSON
 * escape instead of raw UTF-8, so that a reader sees them for what they
 * are and the text still reads back to the same strings. Only valid
 * UTF-8 is touched: in JSON it can only be inside strings. A new string
 * (free it); NULL on NOMEM. */
char *rb_json_escape_format(const char *json);

#endif
