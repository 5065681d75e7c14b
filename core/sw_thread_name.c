/* SPDX-License-Identifier: MIT */
#include "sw_thread_name.h"

#include <sys/prctl.h>

void sw_thread_name(const char *name)
{
    /* PR_SET_NAME names the calling thread, not the process; no
     * _GNU_SOURCE needed, unlike pthread_setname_np. */
    prctl(PR_SET_NAME, name, 0, 0, 0);
}
