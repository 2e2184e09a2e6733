/* libFuzzer harness: COSMOS V2 records (rb_record_read, RB_REC_COSMOS_V2),
 * with fallback units so that files whose headers lack them still reach
 * the data block. */
#include "fuzz_common.h"
#include "rockbolt/model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rb_record_opts o;
    rb_record_opts_init(&o);
    o.format = RB_REC_COSMOS_V2;
    o.units_to_mps2 = 0.01;
    rb_fuzz_record("rec.v2", data, size, &o);
    return 0;
}
