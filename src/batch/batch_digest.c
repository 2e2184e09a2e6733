/* Digests that let `rockbolt merge` tell shards of one work list from
 * shards of another and a summary row as written from one edited by hand
 * (docs/batch.md, "Sharding"). SHA-256 from nettle.
 *
 * - The inputs digest covers the whole work list every shard builds alike:
 *   for each item its source, line, tag, base and overrides, then the bytes
 *   of every distinct case file, list and base those items name, in byte
 *   order of their paths. Two shards agree on it only when they read the
 *   same list, cases and bases.
 * - A case's digest covers its summary object as the JSON writer prints it
 *   without the digest itself (cJSON, unformatted): reading the shard back
 *   and printing it again gives the same text, so any change to a verdict,
 *   a number or a name shows. It is a checksum, not a signature: whoever
 *   edits a row and recomputes the digest is not stopped. */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <nettle/sha2.h>
#include "batch_summary.h"

static void hex(const unsigned char *d, char out[RB_BATCH_DIGEST_CHARS])
{
    static const char h[] = "0123456789abcdef";
    memcpy(out, "sha256:", 7);
    for (size_t i = 0; i < SHA256_DIGEST_SIZE; i++) {
        out[7 + 2 * i] = h[d[i] >> 4];
        out[8 + 2 * i] = h[d[i] & 15];
    }
    out[7 + 2 * SHA256_DIGEST_SIZE] = '\0';
}

void rb_batch_digest_text(const char *text, char out[RB_BATCH_DIGEST_CHARS])
{
    struct sha256_ctx c;
    unsigned char d[SHA256_DIGEST_SIZE];
    sha256_init(&c);
    sha256_update(&c, strlen(text), (const uint8_t *)text);
    sha256_digest(&c, sizeof d, d);
    hex(d, out);
}

/* A string with its length first, so that fields cannot run together. */
static void put_str(struct sha256_ctx *c, const char *s)
{
    char len[32];
    s = s ? s : "";
    int n = snprintf(len, sizeof len, "%zu:", strlen(s));
    sha256_update(c, (size_t)n, (const uint8_t *)len);
    sha256_update(c, strlen(s), (const uint8_t *)s);
}

/* The file's bytes, as far as its loader reads them. Only a regular file
 * is read (opened without waiting, as the loaders do): a FIFO or a device
 * among the inputs would block or never end, and the loader refuses it
 * anyway. Nor more than limit, the loader's own bound: a file over it is
 * digested by its size, unread, as the loader refuses it unread (a sparse
 * 1 TB file), and one that reads on past its stated size
 * (/proc/self/pagemap says 0 bytes) is cut there. */
static void put_file(struct sha256_ctx *c, const char *path, size_t limit)
{
    unsigned char buf[65536];
    struct stat sb;
    size_t n, total = 0;
    char size[64];
    put_str(c, path);
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    if (fd < 0 || fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) {
        if (fd >= 0)
            close(fd);
        put_str(c, "(not read)");
        return;
    }
    if ((unsigned long long)sb.st_size > limit) {
        close(fd);
        snprintf(size, sizeof size, "(over the limit: %lld bytes)", (long long)sb.st_size);
        put_str(c, size);
        return;
    }
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        close(fd);
        put_str(c, "(not read)");
        return;
    }
    while (total <= limit && (n = fread(buf, 1, sizeof buf, f)) > 0) {
        sha256_update(c, n, buf);
        total += n;
    }
    int err = ferror(f);
    fclose(f);
    put_str(c, err ? "(read error)" : total > limit ? "(over the limit)" : "(end)");
}

typedef struct {
    const char *path;
    size_t limit;
} digest_file;

static int cmp_file(const void *a, const void *b)
{
    const digest_file *x = a, *y = b;
    int k = strcmp(x->path, y->path);
    return k ? k : (x->limit > y->limit) - (x->limit < y->limit);
}

rb_status rb_batch_list_digest(const rb_batch_list *l, char out[RB_BATCH_DIGEST_CHARS])
{
    struct sha256_ctx c;
    unsigned char d[SHA256_DIGEST_SIZE];
    digest_file *files = malloc((2 * l->n + 1) * sizeof *files);
    size_t n_files = 0;
    if (!files)
        return RB_ERR_NOMEM;
    sha256_init(&c);
    for (size_t i = 0; i < l->n; i++) {
        const rb_batch_item *it = &l->items[i];
        char num[64];
        snprintf(num, sizeof num, "%d/%d/%zu", it->line, it->bad, it->n_ov);
        put_str(&c, it->source);
        put_str(&c, num);
        put_str(&c, it->tag);
        put_str(&c, it->base);
        for (size_t k = 0; k < it->n_ov; k++) {
            put_str(&c, it->ov[k].key);
            put_str(&c, it->ov[k].value);
        }
        /* a row's source is its list; an item's without a line, a case */
        files[n_files].path = it->source;
        files[n_files++].limit = it->line > 0 ? RB_CSV_MAX_BYTES : RB_CASE_MAX_FILE_BYTES;
        if (it->base) {
            files[n_files].path = it->base;
            files[n_files++].limit = RB_CASE_MAX_FILE_BYTES;
        }
    }
    qsort(files, n_files, sizeof *files, cmp_file);
    /* a path named twice is read once, to the larger of its limits */
    for (size_t i = 0; i < n_files; i++)
        if (i + 1 == n_files || strcmp(files[i].path, files[i + 1].path) != 0)
            put_file(&c, files[i].path, files[i].limit);
    free(files);
    sha256_digest(&c, sizeof d, d);
    hex(d, out);
    return RB_OK;
}
