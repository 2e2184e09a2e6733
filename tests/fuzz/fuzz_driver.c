/* A plain main() for the fuzz harnesses, so that any compiler can replay
 * inputs through LLVMFuzzerTestOneInput without libFuzzer: the normal build
 * turns every reproducer in tests/fuzz/regressions/<harness>/ into a ctest
 * this way. Arguments are files or directories (every regular file in them
 * is run). A crash is a crash here too; a harness invariant aborts. Prints
 * how many inputs ran and exits 1 if an argument had none or could not be
 * read. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "fuzz_common.h"

static int run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    struct stat sb;
    if (!f || fstat(fileno(f), &sb) != 0 || !S_ISREG(sb.st_mode)) {
        fprintf(stderr, "%s: cannot read\n", path);
        if (f)
            fclose(f);
        return 0;
    }
    size_t cap = (size_t)sb.st_size + 1, n;
    uint8_t *buf = malloc(cap);
    if (!buf) {
        fclose(f);
        return 0;
    }
    n = fread(buf, 1, cap, f);
    fclose(f);
    /* A copy of exactly n bytes, so that ASan sees any read past the end. */
    uint8_t *data = malloc(n ? n : 1);
    if (!data) {
        free(buf);
        return 0;
    }
    memcpy(data, buf, n);
    free(buf);
    fprintf(stderr, "running %s (%zu bytes)\n", path, n);
    LLVMFuzzerTestOneInput(data, n);
    free(data);
    return 1;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every regular file of dir, in name order (so runs are repeatable). */
static size_t run_dir(const char *dir)
{
    DIR *d = opendir(dir);
    char **names = NULL;
    size_t n = 0, cap = 0, ran = 0;
    struct dirent *e;
    if (!d)
        return 0;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.')
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            char **p = realloc(names, cap * sizeof *p);
            if (!p)
                break;
            names = p;
        }
        size_t len = strlen(dir) + strlen(e->d_name) + 2;
        if (!(names[n] = malloc(len)))
            break;
        snprintf(names[n++], len, "%s/%s", dir, e->d_name);
    }
    closedir(d);
    if (n)
        qsort(names, n, sizeof *names, cmp_str);
    for (size_t i = 0; i < n; i++) {
        struct stat sb;
        if (stat(names[i], &sb) == 0 && S_ISREG(sb.st_mode))
            ran += (size_t)run_file(names[i]);
        free(names[i]);
    }
    free(names);
    return ran;
}

int main(int argc, char **argv)
{
    int bad = 0;
    size_t total = 0;
    if (argc < 2) {
        fprintf(stderr, "usage: %s FILE|DIR...\n", argv[0]);
        return 2;
    }
    for (int i = 1; i < argc; i++) {
        struct stat sb;
        size_t ran = 0;
        if (stat(argv[i], &sb) == 0 && S_ISDIR(sb.st_mode))
            ran = run_dir(argv[i]);
        else
            ran = (size_t)run_file(argv[i]);
        if (ran == 0) {
            fprintf(stderr, "%s: no input run\n", argv[i]);
            bad = 1;
        }
        total += ran;
    }
    printf("%zu inputs ran without a crash\n", total);
    return bad;
}
