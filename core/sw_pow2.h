/* SPDX-License-Identifier: MIT */
/* The power of two hash tables are sized by. No allocation. */
#ifndef SW_POW2_H
#define SW_POW2_H

#include <stdint.h>

/* The smallest power of two >= n and >= least (least a power of two),
 * at most 2^31. */
static inline uint32_t sw_pow2_at_least(uint32_t n, uint32_t least)
{
    uint32_t p = least;
    while (p < n && p < 0x80000000u)
        p <<= 1;
    return p;
}

#endif
