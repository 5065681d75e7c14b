/* SPDX-License-Identifier: MIT */
/* The super-surfaces' sections (SUPER_SURFACES, SUPER_MEMBERS, SUPER_OF;
 * core/sw_super.h), found, mapped and checked once at load. Kept apart from
 * sw_pack_read.c, as ORIENTATION is: the group has no counts record, its
 * sizes are its counts. Rules: assets/PACK_FORMAT.md, "Super-surfaces".
 *
 * "Every surface in exactly one super-surface" is checked without scratch
 * memory (the reader allocates nothing): SUPER_MEMBERS has one entry per
 * surface, a record's members are strictly increasing (no repeat inside
 * one), and SUPER_OF[s] names the one record that may list s (no repeat
 * across two); a list of surface_count entries without repeats is every
 * surface once. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "sw_pack_validate.h"

_Static_assert(sizeof(sw_super_surface) == 32, "sw_super_surface");
_Static_assert(offsetof(sw_super_surface, span) == 12, "sw_super_surface.span");
_Static_assert(offsetof(sw_super_surface, axis) == 16, "sw_super_surface.axis");
_Static_assert(offsetof(sw_super_surface, reserved) == 28, "sw_super_surface.reserved");

enum { GROUP = 3 };
static const uint32_t group_types[GROUP] = { SW_SECTION_SUPER_SURFACES, SW_SECTION_SUPER_MEMBERS,
                                             SW_SECTION_SUPER_OF };
static const uint64_t group_records[GROUP] = { sizeof(sw_super_surface), sizeof(uint32_t),
                                               sizeof(uint32_t) };

/* All three or none, beside SURFACES, the two lists one entry per surface. */
static sw_status check_group(const sw_pack *pack, const int32_t index[GROUP], sw_error *err)
{
    int present = (index[0] >= 0) + (index[1] >= 0) + (index[2] >= 0);
    if (present == 0)
        return SW_OK;
    for (int k = 0; k < GROUP; k++)
        if (index[k] < 0)
            return sw_error_set(err, SW_ERR_FORMAT, "section table: no %s section (the "
                                "super-surfaces' three sections appear together)",
                                sw_section_type_name(group_types[k]));
    if (!pack->surfaces)
        return sw_error_set(err, SW_ERR_FORMAT, "section %d (SUPER_SURFACES): present without "
                            "a SURFACES section (its members index SURFACES)", (int)index[0]);
    for (int k = 1; k < GROUP; k++) {
        uint64_t n = pack->sections[index[k]].size / sizeof(uint32_t);
        if (n != pack->surface_count)
            return sw_error_set(err, SW_ERR_FORMAT, "section %d (%s): %llu entries, expected "
                                "one per surface (%u)", (int)index[k],
                                sw_section_type_name(group_types[k]), (unsigned long long)n,
                                (unsigned)pack->surface_count);
    }
    return SW_OK;
}

/* The cone: a finite span in [0, pi]; a unit axis below SW_SUPER_SPAN_FULL
 * (the walk may cull by it), zero above (there is no cone to point). */
static sw_status check_cone(uint32_t k, const sw_super_surface *r, sw_error *err)
{
    if (!(isfinite(r->span) && r->span >= 0.0f && r->span <= 3.14159274f))
        return sw_error_set(err, SW_ERR_FORMAT, "SUPER_SURFACES[%u].span: %g, expected finite "
                            "radians in [0, pi]", (unsigned)k, (double)r->span);
    double len2 = 0;
    for (int i = 0; i < 3; i++) {
        if (!isfinite(r->axis[i]))
            return sw_error_set(err, SW_ERR_FORMAT, "SUPER_SURFACES[%u].axis.%c: %g, expected a "
                                "finite number", (unsigned)k, "xyz"[i], (double)r->axis[i]);
        len2 += (double)r->axis[i] * r->axis[i];
    }
    int cone = r->span < SW_SUPER_SPAN_FULL;
    if (cone ? fabs(len2 - 1.0) > 1e-4 : len2 != 0.0)
        return sw_error_set(err, SW_ERR_FORMAT, "SUPER_SURFACES[%u].axis: length %g, expected "
                            "%s", (unsigned)k, sqrt(len2),
                            cone ? "1 (a unit axis for a span below pi/2)"
                                 : "0 (a span of pi/2 or more has no axis)");
    return SW_OK;
}

/* Record k's own fields; next is where its members must start. */
static sw_status check_record(const sw_pack *pack, uint32_t k, uint64_t next, sw_error *err)
{
    const sw_super_surface *r = &pack->supers.supers[k];
    unsigned ku = (unsigned)k;
    if (r->reserved != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "SUPER_SURFACES[%u].reserved: %u, expected 0",
                            ku, (unsigned)r->reserved);
    if (r->member_count == 0)
        return sw_error_set(err, SW_ERR_FORMAT, "SUPER_SURFACES[%u].member_count: 0, expected "
                            ">= 1", ku);
    if (r->first_member != next)
        return sw_error_set(err, SW_ERR_FORMAT, "SUPER_SURFACES[%u].first_member: %u, expected "
                            "%llu (the records' members follow each other in SUPER_MEMBERS)",
                            ku, (unsigned)r->first_member, (unsigned long long)next);
    if ((uint64_t)r->first_member + r->member_count > pack->surface_count)
        return sw_error_set(err, SW_ERR_RANGE, "SUPER_SURFACES[%u].first_member: %u + "
                            "member_count %u exceeds SUPER_MEMBERS count %u", ku,
                            (unsigned)r->first_member, (unsigned)r->member_count,
                            (unsigned)pack->surface_count);
    if (r->part >= pack->meta->part_count)
        return sw_error_set(err, SW_ERR_RANGE, "SUPER_SURFACES[%u].part: %u, expected < %u "
                            "(PARTS count)", ku, (unsigned)r->part,
                            (unsigned)pack->meta->part_count);
    return check_cone(k, r, err);
}

/* Member m of record k: a surface of the record's part, after the one
 * before it, that SUPER_OF gives to k. */
static sw_status check_member(const sw_pack *pack, uint32_t k, uint32_t m, sw_error *err)
{
    const sw_supers *sp = &pack->supers;
    const sw_super_surface *r = &sp->supers[k];
    uint32_t s = sp->members[m];
    if (s >= pack->surface_count)
        return sw_error_set(err, SW_ERR_RANGE, "SUPER_MEMBERS[%u]: surface %u, expected < %u "
                            "(SURFACES count)", (unsigned)m, (unsigned)s,
                            (unsigned)pack->surface_count);
    if (m > r->first_member && s <= sp->members[m - 1])
        return sw_error_set(err, SW_ERR_FORMAT, "SUPER_MEMBERS[%u]: surface %u after %u, expected "
                            "a record's members strictly increasing", (unsigned)m, (unsigned)s,
                            (unsigned)sp->members[m - 1]);
    if (pack->surfaces[s].part != r->part)
        return sw_error_set(err, SW_ERR_FORMAT, "SUPER_MEMBERS[%u]: surface %u of part %u in "
                            "super-surface %u of part %u (a super-surface is one part's)",
                            (unsigned)m, (unsigned)s, (unsigned)pack->surfaces[s].part,
                            (unsigned)k, (unsigned)r->part);
    if (sp->super_of[s] != k)
        return sw_error_set(err, SW_ERR_FORMAT, "SUPER_MEMBERS[%u]: surface %u in super-surface "
                            "%u, but SUPER_OF[%u] is %u (every surface is in exactly one)",
                            (unsigned)m, (unsigned)s, (unsigned)k, (unsigned)s,
                            (unsigned)sp->super_of[s]);
    return SW_OK;
}

static sw_status check_records(const sw_pack *pack, sw_error *err)
{
    const sw_supers *sp = &pack->supers;
    for (uint32_t s = 0; s < sp->surface_count; s++)
        if (sp->super_of[s] >= sp->super_count)
            return sw_error_set(err, SW_ERR_RANGE, "SUPER_OF[%u]: %u, expected < %u "
                                "(SUPER_SURFACES count)", (unsigned)s,
                                (unsigned)sp->super_of[s], (unsigned)sp->super_count);
    uint64_t next = 0;
    for (uint32_t k = 0; k < sp->super_count; k++) {
        sw_status st = check_record(pack, k, next, err);
        const sw_super_surface *r = &sp->supers[k];
        for (uint32_t m = r->first_member; st == SW_OK && m < r->first_member + r->member_count;
             m++)
            st = check_member(pack, k, m, err);
        if (st != SW_OK)
            return st;
        next += r->member_count;
    }
    if (next != sp->surface_count)
        return sw_error_set(err, SW_ERR_FORMAT, "SUPER_SURFACES: members of %llu surfaces, "
                            "expected every one of the %u", (unsigned long long)next,
                            (unsigned)sp->surface_count);
    return SW_OK;
}

sw_status sw_pack_map_supers(const uint8_t *data, sw_pack *out, sw_error *err)
{
    int32_t index[GROUP];
    out->supers = (sw_supers){ 0 };
    sw_status st = sw_pack_find_group(out, group_types, group_records, GROUP, index, err);
    if (st == SW_OK)
        st = check_group(out, index, err);
    if (st != SW_OK || index[0] < 0)
        return st;
    const sw_pack_section *sec = out->sections;
    sw_supers v = {
        .supers = (const sw_super_surface *)(data + sec[index[0]].offset),
        .members = (const uint32_t *)(data + sec[index[1]].offset),
        .super_of = (const uint32_t *)(data + sec[index[2]].offset),
        .super_count = (uint32_t)(sec[index[0]].size / sizeof(sw_super_surface)),
        .surface_count = out->surface_count };
    out->supers = v;
    st = check_records(out, err);
    if (st != SW_OK)
        out->supers = (sw_supers){ 0 };
    return st;
}
