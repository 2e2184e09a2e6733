/* Shared by the fuzz harnesses: the loaders take a path, not a buffer, so
 * each input is written to a file in a private scratch directory first.
 * Going through a real file is deliberate: it keeps the harnesses on the
 * same code path as `rockbolt check` (fopen, the size cap, fseek/rewind in
 * the record sniffing) instead of an in-memory side door.
 *
 * The scratch directory lives on /dev/shm when it can (every input is one
 * write, and tmpfs keeps that cheap), else in $TMPDIR or /tmp, and is
 * removed at exit. */
#ifndef RB_FUZZ_COMMON_H
#define RB_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>

/* The scratch directory, made on first use; aborts if it cannot be. */
const char *rb_fuzz_dir(void);
/* dir/rel, in a static buffer per call site kept by the caller. */
void rb_fuzz_path(char *buf, size_t size, const char *rel);
/* Write len bytes to dir/rel (making parent directories); aborts on
 * failure, since a harness that cannot write its input tests nothing. */
void rb_fuzz_write(const char *rel, const uint8_t *data, size_t len);
/* A violated invariant: print why and abort, which libFuzzer reports as a
 * crash with the input saved. */
void rb_fuzz_fail(const char *why, const char *detail);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#endif

#include "rockbolt/record.h"

/* Write data to dir/rel and read it with opts, then check what every read
 * must satisfy whatever the bytes: a success is a usable series within the
 * point limit; a failure is a known status with a message naming the file
 * and an empty series; and a file that reads at n points is refused with
 * RB_ERR_LIMIT when max_points is below n. Returns the status. */
rb_status rb_fuzz_record(const char *rel, const uint8_t *data, size_t len,
                         const rb_record_opts *opts);
