/* SPDX-License-Identifier: MIT */
/* Which up axis a build writes into its pack (the ORIENTATION section): each
 * input's own convention, unless `seamwalk-pack build --up` says otherwise.
 * STEP and IGES are z-up (mechanical CAD), Newell listings and .bpt y-up (as
 * written), a scene what its up_axis key says, else y-up (scenes are
 * authored y-up, turning z-up parts with `rotate`). Host only; called by
 * seamwalk_pack_main.c. */
#ifndef SW_UP_INPUTS_H
#define SW_UP_INPUTS_H

#include <stdint.h>
#include <stdio.h>

/* The up axis (enum sw_up_axis) the input at path asks for, by its
 * extension (case-insensitive); scene_up_axis is a scene's up_axis key
 * (0: not given), ignored for other inputs. */
int32_t sw_up_input_default(const char *path, int32_t scene_up_axis);

/* The pack's up axis: override when it is not 0, else defaults[0] (the first
 * input's). Without an override, inputs whose defaults differ get one warning
 * line on warn (may be NULL) naming every file with its axis. */
int32_t sw_up_inputs_choose(const char *const *paths, const int32_t *defaults, int count,
                          int32_t override, FILE *warn);

#endif
