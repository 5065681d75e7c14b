/* SPDX-License-Identifier: MIT */
/* The up axis (sw_up_axis.h): names, parsing, vectors, and the pack's
 * ORIENTATION section. Kept apart from sw_pack_read.c so the section is one
 * small addition to the container, not a change to its group rules. */
#include "sw_up_axis.h"

#include <string.h>

static const char *const names[7] = { "-z", "-y", "-x", "invalid", "+x", "+y", "+z" };

int sw_up_axis_valid(int32_t axis) { return axis != 0 && axis >= -3 && axis <= 3; }

const char *sw_up_axis_name(int32_t axis)
{
    return sw_up_axis_valid(axis) ? names[axis + 3] : "invalid";
}

int sw_up_axis_parse(const char *text, int32_t *out)
{
    if (!text)
        return 0;
    int sign = 1;
    if (text[0] == '+' || text[0] == '-')
        sign = *text++ == '-' ? -1 : 1;
    if (text[0] < 'x' || text[0] > 'z' || text[1] != '\0')
        return 0;
    *out = sign * (text[0] - 'x' + 1);
    return 1;
}

sw_vec3 sw_up_axis_vector(int32_t axis)
{
    if (!sw_up_axis_valid(axis))
        axis = SW_UP_DEFAULT;
    double s = axis < 0 ? -1.0 : 1.0;
    int a = axis < 0 ? -axis : axis;
    return sw_v3(a == 1 ? s : 0.0, a == 2 ? s : 0.0, a == 3 ? s : 0.0);
}

int32_t sw_pack_up_axis(const sw_pack *pack)
{
    return pack->orientation ? pack->orientation->up_axis : SW_UP_DEFAULT;
}

static sw_status check_orientation(int index, const sw_pack_orientation *o, sw_error *err)
{
    if (!sw_up_axis_valid(o->up_axis))
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (ORIENTATION): up_axis %d, expected "
                            "1, 2, 3 (x, y, z) or their negatives", index, (int)o->up_axis);
    for (size_t i = 0; i < sizeof o->reserved; i++)
        if (o->reserved[i] != 0)
            return sw_error_set(err, SW_ERR_FORMAT, "ORIENTATION.reserved[%zu]: 0x%02x, "
                                "expected 0", i, o->reserved[i]);
    return SW_OK;
}

sw_status sw_pack_map_orientation(const uint8_t *data, sw_pack *out, sw_error *err)
{
    int found = -1;
    out->orientation = NULL;
    for (uint32_t i = 0; i < out->header->section_count; i++) {
        const sw_pack_section *s = &out->sections[i];
        if (s->type != SW_SECTION_ORIENTATION)
            continue;
        if (found >= 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section %u (ORIENTATION): a second "
                                "ORIENTATION section (the first is section %d)", (unsigned)i,
                                found);
        if (s->size != sizeof(sw_pack_orientation))
            return sw_error_set(err, SW_ERR_FORMAT, "section %u (ORIENTATION): %llu bytes, "
                                "expected %zu", (unsigned)i, (unsigned long long)s->size,
                                sizeof(sw_pack_orientation));
        found = (int)i;
    }
    if (found < 0)
        return SW_OK;
    /* Sections start at multiples of 64 in 8-aligned data: aligned for int32. */
    const sw_pack_orientation *o =
        (const sw_pack_orientation *)(data + out->sections[found].offset);
    sw_status s = check_orientation(found, o, err);
    if (s == SW_OK)
        out->orientation = o;
    return s;
}
