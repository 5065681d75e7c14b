/* SPDX-License-Identifier: MIT */
/* The record checks of the trimmed-surface sections (SURFACES, TRIM_LOOPS,
 * TRIM_CURVES, TRIM_DATA, PATCH_DOMAINS, TRIM_MASKS). Like sw_pack_validate.c
 * it checks every index and every value the runtime divides by or walks
 * along, once, so code over a validated pack needs no checks. Messages name
 * the record and field: "TRIM_CURVES[4].knots[7]: ...". Rules:
 * assets/PACK_FORMAT.md, "Validation rules". */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "sw_pack_validate.h"

enum { MAX_TRIM_DEGREE = 15 };

/* Every TRIM_DATA value finite, so the curve checks below compare numbers. */
static sw_status validate_trim_data(const sw_pack *pack, sw_error *err)
{
    for (uint32_t i = 0; i < pack->trim_data_count; i++)
        if (!isfinite(pack->trim_data[i]))
            return sw_error_set(err, SW_ERR_FORMAT, "TRIM_DATA[%u]: %g, expected a finite number",
                                (unsigned)i, (double)pack->trim_data[i]);
    return SW_OK;
}

static sw_status check_curve_fields(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_trim_curve *c = &pack->trim_curves[i];
    if (c->degree < 1 || c->degree > MAX_TRIM_DEGREE)
        return sw_error_set(err, SW_ERR_FORMAT, "TRIM_CURVES[%u].degree: %u, expected 1..%d",
                            (unsigned)i, c->degree, MAX_TRIM_DEGREE);
    if (c->flags & ~(unsigned)(SW_TRIM_RATIONAL | SW_TRIM_COMPUTED))
        return sw_error_set(err, SW_ERR_FORMAT, "TRIM_CURVES[%u].flags: 0x%x has unknown bits",
                            (unsigned)i, c->flags);
    if (c->reserved != 0 || c->reserved2 != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "TRIM_CURVES[%u].%s: %u, expected 0",
                            (unsigned)i, c->reserved ? "reserved" : "reserved2",
                            (unsigned)(c->reserved ? c->reserved : c->reserved2));
    if (c->count < (uint32_t)c->degree + 1)
        return sw_error_set(err, SW_ERR_FORMAT, "TRIM_CURVES[%u].count: %u, expected at least "
                            "degree + 1 = %u", (unsigned)i, (unsigned)c->count, c->degree + 1u);
    uint64_t floats = (uint64_t)c->count * 4 + c->degree + 1;
    if ((uint64_t)c->first_float + floats > pack->trim_data_count)
        return sw_error_set(err, SW_ERR_RANGE, "TRIM_CURVES[%u].first_float: %u + %llu floats "
                            "exceeds TRIM_DATA count %u", (unsigned)i, (unsigned)c->first_float,
                            (unsigned long long)floats, (unsigned)pack->trim_data_count);
    return SW_OK;
}

/* Non-decreasing, clamped (the first and the last degree + 1 knots equal),
 * and spanning a non-empty range, so evaluation by de Boor is defined. */
static sw_status check_curve_knots(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_trim_curve *c = &pack->trim_curves[i];
    const float *k = &pack->trim_data[c->first_float];
    uint32_t n = c->count + c->degree + 1, p = c->degree;
    for (uint32_t j = 1; j < n; j++)
        if (k[j] < k[j - 1])
            return sw_error_set(err, SW_ERR_FORMAT, "TRIM_CURVES[%u].knots[%u]: %g < knots[%u] "
                                "%g, expected non-decreasing", (unsigned)i, (unsigned)j,
                                (double)k[j], (unsigned)(j - 1), (double)k[j - 1]);
    for (uint32_t j = 1; j <= p; j++) {
        uint32_t at = k[j] != k[0] ? j : k[n - 1 - j] != k[n - 1] ? n - 1 - j : n;
        if (at < n)
            return sw_error_set(err, SW_ERR_FORMAT, "TRIM_CURVES[%u].knots[%u]: %g, expected "
                                "%g (clamped: the first and last degree + 1 knots are equal)",
                                (unsigned)i, (unsigned)at, (double)k[at],
                                (double)(at == j ? k[0] : k[n - 1]));
    }
    if (!(k[p] < k[c->count]))
        return sw_error_set(err, SW_ERR_FORMAT, "TRIM_CURVES[%u].knots: empty range %g..%g",
                            (unsigned)i, (double)k[p], (double)k[c->count]);
    return SW_OK;
}

static sw_status check_curve_weights(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_trim_curve *c = &pack->trim_curves[i];
    const float *points = &pack->trim_data[(size_t)c->first_float + c->count + c->degree + 1];
    int rational = (c->flags & SW_TRIM_RATIONAL) != 0;
    for (uint32_t j = 0; j < c->count; j++) {
        float w = points[(size_t)j * 3 + 2];
        if (rational && !(w > 0.0f))
            return sw_error_set(err, SW_ERR_RANGE, "TRIM_CURVES[%u].points[%u].w: %g, expected "
                                "> 0", (unsigned)i, (unsigned)j, (double)w);
        if (!rational && w != 1.0f)
            return sw_error_set(err, SW_ERR_FORMAT, "TRIM_CURVES[%u].points[%u].w: %g, expected "
                                "1 (the curve is not rational)", (unsigned)i, (unsigned)j,
                                (double)w);
    }
    return SW_OK;
}

static sw_status validate_loop(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_trim_loop *l = &pack->trim_loops[i];
    if (l->flags & ~(uint32_t)SW_LOOP_OUTER)
        return sw_error_set(err, SW_ERR_FORMAT, "TRIM_LOOPS[%u].flags: 0x%x has unknown bits",
                            (unsigned)i, (unsigned)l->flags);
    if (l->curve_count == 0)
        return sw_error_set(err, SW_ERR_FORMAT, "TRIM_LOOPS[%u].curve_count: 0, expected at "
                            "least 1", (unsigned)i);
    if ((uint64_t)l->first_curve + l->curve_count > pack->trim_curve_count)
        return sw_error_set(err, SW_ERR_RANGE, "TRIM_LOOPS[%u].first_curve: %u + curve_count %u "
                            "exceeds TRIM_CURVES count %u", (unsigned)i,
                            (unsigned)l->first_curve, (unsigned)l->curve_count,
                            (unsigned)pack->trim_curve_count);
    return SW_OK;
}

/* u0, u1, v0, v1: finite, u0 < u1, v0 < v1. */
static sw_status check_domain(const char *rec, uint32_t i, const float d[4], sw_error *err)
{
    for (int a = 0; a < 2; a++) {
        float lo = d[2 * a], hi = d[2 * a + 1];
        char axis = a ? 'v' : 'u';
        if (!isfinite(lo) || !isfinite(hi))
            return sw_error_set(err, SW_ERR_FORMAT, "%s[%u].domain: %c range %g..%g is not "
                                "finite", rec, (unsigned)i, axis, (double)lo, (double)hi);
        if (!(lo < hi))
            return sw_error_set(err, SW_ERR_FORMAT, "%s[%u].domain: %c0 %g >= %c1 %g", rec,
                                (unsigned)i, axis, (double)lo, axis, (double)hi);
    }
    return SW_OK;
}

static sw_status validate_surface(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_surface *s = &pack->surfaces[i];
    if (s->part >= pack->meta->part_count)
        return sw_error_set(err, SW_ERR_RANGE, "SURFACES[%u].part: %u, but PARTS has %u entries",
                            (unsigned)i, (unsigned)s->part, (unsigned)pack->meta->part_count);
    const sw_pack_part *part = &pack->parts[s->part];
    uint64_t end = (uint64_t)s->first_patch + s->patch_count;
    uint64_t part_end = (uint64_t)part->first_patch + part->patch_count;
    if (s->first_patch < part->first_patch || end > part_end)
        return sw_error_set(err, SW_ERR_RANGE, "SURFACES[%u].first_patch: %u + patch_count %u "
                            "is outside PARTS[%u]'s patches [%u, %llu)", (unsigned)i,
                            (unsigned)s->first_patch, (unsigned)s->patch_count,
                            (unsigned)s->part, (unsigned)part->first_patch,
                            (unsigned long long)part_end);
    if ((uint64_t)s->first_loop + s->loop_count > pack->trim_loop_count)
        return sw_error_set(err, SW_ERR_RANGE, "SURFACES[%u].first_loop: %u + loop_count %u "
                            "exceeds TRIM_LOOPS count %u", (unsigned)i, (unsigned)s->first_loop,
                            (unsigned)s->loop_count, (unsigned)pack->trim_loop_count);
    if (s->flags != 0)
        return sw_error_set(err, SW_ERR_FORMAT, "SURFACES[%u].flags: 0x%x, expected 0 in "
                            "version %u", (unsigned)i, (unsigned)s->flags, SW_PACK_VERSION);
    return check_domain("SURFACES", i, s->domain, err);
}

/* Whether the patch range [lo, hi] lies in the surface's [s0, s1] up to a few
 * float steps: writers round both from doubles, possibly computed apart. */
static int range_inside(float lo, float hi, float s0, float s1)
{
    double slack = 4.0 * FLT_EPSILON * fmax(fabs((double)s0), fabs((double)s1));
    return (double)lo >= (double)s0 - slack && (double)hi <= (double)s1 + slack;
}

static sw_status validate_patch_domain(const sw_pack *pack, uint32_t i, sw_error *err)
{
    const sw_pack_patch_domain *d = &pack->patch_domains[i];
    if (d->surface >= pack->surface_count)
        return sw_error_set(err, SW_ERR_RANGE, "PATCH_DOMAINS[%u].surface: %u, but SURFACES has "
                            "%u entries", (unsigned)i, (unsigned)d->surface,
                            (unsigned)pack->surface_count);
    const sw_pack_surface *s = &pack->surfaces[d->surface];
    if (i < s->first_patch || i - s->first_patch >= s->patch_count)
        return sw_error_set(err, SW_ERR_RANGE, "PATCH_DOMAINS[%u].surface: %u, but that surface "
                            "holds patches [%u, %llu)", (unsigned)i, (unsigned)d->surface,
                            (unsigned)s->first_patch,
                            (unsigned long long)s->first_patch + s->patch_count);
    if (d->mask != SW_MASK_NONE && d->mask >= pack->trim_mask_count)
        return sw_error_set(err, SW_ERR_RANGE, "PATCH_DOMAINS[%u].mask: %u, but TRIM_MASKS has "
                            "%u entries (0x%08x: none)", (unsigned)i, (unsigned)d->mask,
                            (unsigned)pack->trim_mask_count, SW_MASK_NONE);
    sw_status st = check_domain("PATCH_DOMAINS", i, d->domain, err);
    for (int a = 0; st == SW_OK && a < 2; a++)
        if (!range_inside(d->domain[2 * a], d->domain[2 * a + 1], s->domain[2 * a],
                          s->domain[2 * a + 1]))
            st = sw_error_set(err, SW_ERR_RANGE, "PATCH_DOMAINS[%u].domain: %c range %g..%g is "
                              "outside SURFACES[%u]'s %g..%g", (unsigned)i, a ? 'v' : 'u',
                              (double)d->domain[2 * a], (double)d->domain[2 * a + 1],
                              (unsigned)d->surface, (double)s->domain[2 * a],
                              (double)s->domain[2 * a + 1]);
    return st;
}

/* Every patch names the one surface whose range holds it, so the surfaces'
 * ranges must not overlap. Each patch passes this for at most one surface
 * (the one it names), so the loop stops after patch_count + 1 steps however
 * long the claimed ranges are. */
static sw_status check_surface_ranges_disjoint(const sw_pack *pack, sw_error *err)
{
    for (uint32_t i = 0; i < pack->surface_count; i++) {
        const sw_pack_surface *s = &pack->surfaces[i];
        for (uint32_t p = s->first_patch; p - s->first_patch < s->patch_count; p++)
            if (pack->patch_domains[p].surface != i)
                return sw_error_set(err, SW_ERR_RANGE, "SURFACES[%u].first_patch: its patches "
                                    "[%u, %llu) include patch %u of SURFACES[%u]", (unsigned)i,
                                    (unsigned)s->first_patch,
                                    (unsigned long long)s->first_patch + s->patch_count,
                                    (unsigned)p, (unsigned)pack->patch_domains[p].surface);
    }
    return SW_OK;
}

sw_status sw_pack_validate_trim(const sw_pack *pack, sw_error *err)
{
    if (!pack->surfaces)
        return SW_OK;
    sw_status s = validate_trim_data(pack, err);
    for (uint32_t i = 0; s == SW_OK && i < pack->trim_curve_count; i++)
        if ((s = check_curve_fields(pack, i, err)) == SW_OK &&
            (s = check_curve_knots(pack, i, err)) == SW_OK)
            s = check_curve_weights(pack, i, err);
    for (uint32_t i = 0; s == SW_OK && i < pack->trim_loop_count; i++)
        s = validate_loop(pack, i, err);
    for (uint32_t i = 0; s == SW_OK && i < pack->surface_count; i++)
        s = validate_surface(pack, i, err);
    for (uint32_t i = 0; s == SW_OK && i < pack->meta->patch_count; i++)
        s = validate_patch_domain(pack, i, err);
    return s == SW_OK ? check_surface_ranges_disjoint(pack, err) : s;
}
