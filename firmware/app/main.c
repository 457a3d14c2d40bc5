/* ringloc-fw: the firmware on the robot's computer. */
#include "rl_cli.h"
#include "rl_fw.h"

int main(int argc, char **argv)
{
    rl_cli_start("ringloc-fw");
    return rl_fw_main(NULL, argc, argv);
}
