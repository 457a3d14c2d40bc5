/* ringloc run: the firmware (the same entry point as ringloc-fw). */
#include "rl_cmd.h"
#include "rl_fw.h"

int rl_cmd_run(int argc, char **argv)
{
    return rl_fw_main("run", argc, argv);
}
