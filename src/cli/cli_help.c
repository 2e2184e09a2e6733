/* --help and --version texts. The exit codes listed here are the contract
 * scripts rely on; README.md repeats them. */
#include <stdio.h>
#include "cli.h"

void rb_cli_help_print(void)
{
    fputs(
"usage: rockbolt check CASE.yaml [--json FILE] [--text FILE] [--history FILE]\n"
"                      [--svg FILE] [--html FILE] [--sandbox DIR] [--quiet]\n"
"       rockbolt design CASE.yaml [check's options] [-j N] [--sweep-csv FILE]\n"
"       rockbolt batch INPUT... [--base CASE] [-j N] [--design] [--csv FILE]\n"
"                      [--json FILE] [--junit FILE] [--reports DIR]\n"
"                      [--shard I/N] [--sandbox DIR] [--quiet]\n"
"       rockbolt merge SHARD.json... [--json FILE] [--csv FILE] [--junit FILE]\n"
"       rockbolt init [FILE]\n"
"       rockbolt --help | --version\n"
"\n"
"Checks the seismic anchorage of rocking equipment: a cabinet on a base\n"
"plate, held down by bolt rows with a gap, under floor motions.\n"
"\n"
"commands:\n"
"  check CASE.yaml   solve every motion of the case, judge each against the\n"
"                    case's criteria and report; the text report goes to\n"
"                    standard output unless --text or --quiet is given\n"
"  design CASE.yaml  check, then the design searches of every motion: the\n"
"                    design factor for bolts staying elastic and for bolts\n"
"                    not breaking, the recommended gap ratio, the case's\n"
"                    sweeps and code-static comparison (docs/design.md);\n"
"                    verdict and exit code as for check\n"
"  batch INPUT...    check many cases: case files, directories (their\n"
"                    *.yaml), glob patterns and equipment lists (.csv, one\n"
"                    row per cabinet overriding a base case); a summary\n"
"                    table on standard output, a progress line on a\n"
"                    terminal; --design adds the design factor and the\n"
"                    recommended gap; --reports DIR writes each case's\n"
"                    JSON and text report; --shard I/N runs every N-th\n"
"                    item from the I-th; --sandbox DIR as for check (no\n"
"                    default); exit 0 all pass, 1 a case fails,\n"
"                    2 a case cannot be read, 3 a solver error (docs/batch.md)\n"
"  merge SHARD.json...  combine the --json summaries of the shards of one\n"
"                    batch into the summary a single run gives; refuses\n"
"                    shards run on other inputs and rows edited by hand\n"
"                    (each summary carries SHA-256 digests)\n"
"  init [FILE]       write a commented starter case to FILE (default\n"
"                    case.yaml); never overwrites an existing file\n"
"\n",
        stdout);
    /* two strings: C99 compilers need only take 4095 characters in one */
    fputs(
"options of check:\n"
"  --json FILE       write the JSON report (docs/report-format.md)\n"
"  --text FILE       write the text report to FILE; standard output then\n"
"                    gets only the verdict line\n"
"  --history FILE    write the time histories as CSV (one row per output\n"
"                    interval of the case, default 0.01 s)\n"
"  --svg FILE        draw the stacked time-history figure of each motion\n"
"                    (thesis Figs. 5.13-6.18) and, for design, each sweep;\n"
"                    several figures go to FILE-1, FILE-2, ... in that order\n"
"  --html FILE       one self-contained page: the text report and the figures\n"
"  --sandbox DIR     every input (the case, its extends bases, its records;\n"
"                    for batch also lists and row bases) must resolve to a\n"
"                    file inside DIR, links and '..' followed, else exit 2\n"
"                    naming the key and the file; shipped records allowed\n"
"  -q, --quiet       print nothing on standard output\n"
"\n"
"options of design (and all of check's):\n"
"  -j, --threads N   threads for the searches (default: every processor);\n"
"                    the results do not depend on N\n"
"  --sweep-csv FILE  write each sweep as CSV: FILE itself for one sweep,\n"
"                    FILE-1, FILE-2, ... (before the extension) for several\n"
"  -h, --help        this text\n"
"  -V, --version     the version\n"
"\n"
"Output files are written whole or not at all, and their directories are\n"
"checked before solving.\n"
"\n"
"exit codes:\n"
"  0  the design passes its criteria for every motion\n"
"  1  it fails them for at least one motion\n"
"  2  bad input or usage (nothing written)\n"
"  3  internal or solver error\n"
"\n"
"environment:\n"
"  RB_TEMPLATE_DIR   directory searched first for report.txt and\n"
"                    starter.yaml (a built-in copy is used otherwise)\n",
        stdout);
}

void rb_cli_version_print(void)
{
    printf("rockbolt %s (JSON report format %d)\n", RB_VERSION_STRING,
           RB_REPORT_FORMAT_VERSION);
}
