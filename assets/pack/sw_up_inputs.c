/* SPDX-License-Identifier: MIT */
/* The build's up axis (sw_up_inputs.h). */
#include "sw_up_inputs.h"

#include <string.h>
#include <strings.h>

#include "sw_up_axis.h"

static int has_extension(const char *path, const char *ext)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    return dot && strcasecmp(dot, ext) == 0;
}

int32_t sw_up_input_default(const char *path, int32_t scene_up_axis)
{
    static const char *const z_up[] = { ".stp", ".step", ".igs", ".iges" };
    for (size_t i = 0; i < sizeof z_up / sizeof *z_up; i++)
        if (has_extension(path, z_up[i]))
            return SW_UP_POS_Z;
    if (has_extension(path, ".ini") && sw_up_axis_valid(scene_up_axis))
        return scene_up_axis;
    return SW_UP_POS_Y;
}

/* "a.step (+z), b.txt (+y)" on one line. */
static void print_inputs(FILE *warn, const char *const *paths, const int32_t *defaults, int count)
{
    for (int i = 0; i < count; i++)
        fprintf(warn, "%s%s (%s)", i ? ", " : "", paths[i], sw_up_axis_name(defaults[i]));
}

int32_t sw_up_inputs_choose(const char *const *paths, const int32_t *defaults, int count,
                          int32_t override, FILE *warn)
{
    if (override != 0)
        return override;
    if (count < 1)
        return SW_UP_DEFAULT;
    int differ = 0;
    for (int i = 1; i < count; i++)
        differ |= defaults[i] != defaults[0];
    if (differ && warn) {
        fprintf(warn, "warning: the inputs' up axes differ: ");
        print_inputs(warn, paths, defaults, count);
        fprintf(warn, "; the pack takes the first input's, %s (--up sets it)\n",
                sw_up_axis_name(defaults[0]));
    }
    return defaults[0];
}
