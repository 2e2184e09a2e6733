# Work and resource bounds that need more than one case file: inputs that
# must never block (FIFOs), record files over the byte limit, and batch
# memory against the length of the list (docs/robustness.md).
rb_shell_tests(PREFIX limits SCRIPT tests/limits/limits.sh SCRATCH limits LABEL robustness
               TIMEOUT 180
               TESTS fifo_batch fifo_check fifo_list fifo_base record_bytes batch_tmpdir
                     batch_memory digest_huge merge_fifo batch_tmpdir_full
                     record_once merge_huge merge_memory)
