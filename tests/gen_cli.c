/* The showroom generator as its own program, for test_gen.sh: the function
 * seamwalk-pack's `gen` command calls, so the tests do not depend on the CLI
 * wiring. Usage: gen_cli showroom --patches N -o SCENE.ini [...]. */
#include <stdio.h>

#include "sw_gen_showroom.h"

int main(int argc, char **argv)
{
    int rc = sw_pack_cmd_gen(argc - 1, argv + 1);
    if (fflush(stdout) != 0 && rc == 0)
        rc = 1;
    return rc;
}
