/* SPDX-License-Identifier: MIT */
#include "sw_parts.h"

void sw_parts_run(const sw_parts_runner *runner, sw_part_fn fn, void *arg, uint32_t count)
{
    if (runner && runner->run) {
        runner->run(runner->ctx, fn, arg, count);
        return;
    }
    for (uint32_t p = 0; p < count; p++)
        fn(arg, p);
}
