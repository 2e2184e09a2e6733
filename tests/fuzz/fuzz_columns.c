/* libFuzzer harness: column records. Each input is read three ways: as one
 * column (dt given), as two columns (time, acceleration) and with the
 * format guessed (RB_REC_AUTO), which also runs the header sniffing that
 * decides between AT2, COSMOS and columns. */
#include "fuzz_common.h"
#include "rockbolt/model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rb_record_opts o;
    rb_record_opts_init(&o);
    o.units_to_mps2 = RB_G0;
    o.format = RB_REC_ONE_COLUMN;
    o.dt_s = 0.01;
    rb_fuzz_record("rec.txt", data, size, &o);
    o.format = RB_REC_TWO_COLUMN;
    o.dt_s = 0.0;
    rb_fuzz_record("rec.txt", data, size, &o);
    o.format = RB_REC_AUTO;
    o.dt_s = 0.01;
    rb_fuzz_record("rec.txt", data, size, &o);
    return 0;
}
