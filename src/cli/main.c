/* rockbolt: entry point. Parses the command line and hands over to the
 * command; nothing else happens here. */
#include <string.h>
#include "cli.h"
#include "rockbolt/outplan.h"

int main(int argc, char **argv)
{
    rb_cli_opts o;
    /* a signal removes the temporary files of outputs being written */
    rb_outplan_signals_install();
    /* batch and merge parse their own options (cli_batch.c, cli_merge.c) */
    if (argc > 1 && strcmp(argv[1], "batch") == 0)
        return (int)rb_cli_batch_main(argc - 2, argv + 2);
    if (argc > 1 && strcmp(argv[1], "merge") == 0)
        return (int)rb_cli_merge_main(argc - 2, argv + 2);
    rb_exit e = rb_cli_args_parse(argc, argv, &o);
    if (e != RB_EXIT_PASS)
        return (int)e;
    switch (o.command) {
    case RB_CMD_HELP:
        if (o.help_command)
            return (int)rb_cli_help_command_print(o.help_command);
        rb_cli_help_print();
        return RB_EXIT_PASS;
    case RB_CMD_VERSION:
        rb_cli_version_print();
        return RB_EXIT_PASS;
    case RB_CMD_CHECK:
    case RB_CMD_DESIGN:
        return (int)rb_cli_check_run(&o);
    case RB_CMD_INIT:
        return (int)rb_cli_init_run(&o);
    case RB_CMD_FRAGILITY:
        return (int)rb_cli_fragility_run(&o);
    case RB_CMD_SPECTRUM:
        return (int)rb_cli_spectrum_run(&o);
    case RB_CMD_MOTION:
        return (int)rb_cli_motion_run(&o);
    case RB_CMD_NONE:
        break;
    }
    return RB_EXIT_INTERNAL;
}
