/* libFuzzer harness: target spectrum tables (rb_spectrum_table_read), the
 * two-column CSV a synthetic motion's `spectrum: {type: table}` names. A
 * table that reads has 2 to max_points rows, frequencies increasing within
 * RB_SPECTRUM_MIN_HZ to RB_SPECTRUM_MAX_HZ and ordinates in (0, 1000 g];
 * a refused one has a message naming the file and hands back nothing; a
 * table that reads at n rows is refused with RB_ERR_LIMIT at n - 1. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fuzz_common.h"
#include "rockbolt/model.h"
#include "rockbolt/spectrum.h"

static void check_refused(rb_status st, const rb_diag *d, const double *f, const double *a)
{
    if (st != RB_ERR_IO && st != RB_ERR_PARSE && st != RB_ERR_INVALID
        && st != RB_ERR_LIMIT && st != RB_ERR_NOMEM)
        rb_fuzz_fail("rb_spectrum_table_read returned an unexpected status",
                     rb_status_str(st));
    if (f || a)
        rb_fuzz_fail("a refused table handed back its rows", NULL);
    if (st != RB_ERR_NOMEM && (!d->msg[0] || !strstr(d->file, "table.csv")))
        rb_fuzz_fail("a refused table's message does not name the file", d->msg);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[512];
    double *f = NULL, *a = NULL;
    size_t n = 0, max = 64;
    rb_diag d;
    rb_fuzz_write("table.csv", data, size);
    rb_fuzz_path(path, sizeof path, "table.csv");
    rb_diag_clear(&d);
    rb_status st = rb_spectrum_table_read(path, NULL, RB_G0, max, &f, &a, &n, &d);
    if (st != RB_OK) {
        check_refused(st, &d, f, a);
        return 0;
    }
    if (n < 2 || n > max)
        rb_fuzz_fail("a table that reads has fewer than 2 rows or more than the limit",
                     NULL);
    for (size_t i = 0; i < n; i++) {
        if (!(f[i] >= RB_SPECTRUM_MIN_HZ && f[i] <= RB_SPECTRUM_MAX_HZ)
            || (i > 0 && !(f[i] > f[i - 1])))
            rb_fuzz_fail("a table's frequencies are out of range or not increasing", NULL);
        if (!(a[i] > 0 && a[i] <= RB_SPECTRUM_MAX_ACCEL_MPS2))
            rb_fuzz_fail("a table's ordinate is out of range", NULL);
    }
    free(f);
    free(a);
    double *f2 = NULL, *a2 = NULL;
    size_t n2 = 0;
    rb_diag_clear(&d);
    st = rb_spectrum_table_read(path, NULL, RB_G0, n - 1, &f2, &a2, &n2, &d);
    if (n > 2 && st != RB_ERR_LIMIT)
        rb_fuzz_fail("a table one row over the limit was not refused with RB_ERR_LIMIT",
                     rb_status_str(st));
    if (st == RB_OK) {
        free(f2);
        free(a2);
    } else {
        check_refused(st, &d, f2, a2);
    }
    return 0;
}
