/* "Did you mean": how far a word is from another, for the hints of the
 * case loader and the command line. Internal to the libraries (src/util). */
#ifndef RB_UTIL_NEAREST_H
#define RB_UTIL_NEAREST_H

#include <stddef.h>

/* Levenshtein distance of a and b, letters compared without case, capped
 * at 9 (enough for hints; words of 63 bytes or more are 9 from anything). */
int rb_edit_distance(const char *a, const char *b);

/* The largest distance that still reads as a typo of a word of len letters:
 * 1 up to 4 letters, 2 up to 8, else 3. */
int rb_typo_limit(size_t len);

#endif
