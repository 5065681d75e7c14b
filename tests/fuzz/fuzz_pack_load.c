/* SPDX-License-Identifier: MIT */
/* Fuzz target: the runtime's threaded loader. seamwalk checks a pack on
 * its loader thread with helper threads taking the checks' parts
 * (core/sw_parts_threads.h, sw_pack_open_memory_with); whatever order
 * the threads finish in, the answer must be the serial reader's, status
 * and message alike. Each input is tried as it is and resealed
 * (fuzz_reseal.h), so the Seam Graph's and the levels' parts run too. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_reseal.h"
#include "sw_pack.h"
#include "sw_parts_threads.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void same_answer(const uint8_t *buf, size_t size)
{
    sw_pack serial, threaded;
    sw_error e1 = {0}, e2 = {0};
    sw_status s1 = sw_pack_open_memory(buf, size, &serial, &e1);
    sw_parts_threads threads;
    sw_parts_runner runner = sw_parts_threads_runner(&threads, 2);
    sw_status s2 = sw_pack_open_memory_with(buf, size, &runner, &threaded, &e2);
    if (s1 != s2 || (s1 != SW_OK && strcmp(e1.message, e2.message) != 0))
        abort();   /* reported by the fuzzer as a crash */
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t *buf = fuzz_copy(data, size);
    if (!buf)
        return 0;
    same_answer(buf, size);
    if (size >= sizeof(sw_pack_header)) {
        reseal(buf, size);
        same_answer(buf, size);
    }
    free(buf);
    return 0;
}
