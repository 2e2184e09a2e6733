/* libFuzzer harness: PEER AT2 records (rb_record_read, RB_REC_AT2). The
 * fallback units are set so that files without a units line still reach
 * the NPTS/DT line and the values. */
#include "fuzz_common.h"
#include "rockbolt/model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rb_record_opts o;
    rb_record_opts_init(&o);
    o.format = RB_REC_AT2;
    o.units_to_mps2 = RB_G0;
    rb_fuzz_record("rec.at2", data, size, &o);
    return 0;
}
