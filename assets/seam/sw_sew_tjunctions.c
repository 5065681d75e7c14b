/* SPDX-License-Identifier: MIT */
/* Sewing step 3b: T-junctions the intervals left open. Where one loop has
 * an unsewn edge x-b and another an unsewn edge a-b from the same vertex b,
 * and x lies within the tolerance of the chord a-b (strictly between its
 * ends), x is a vertex of the second loop's edge too: it is inserted there
 * (its (u, v) on that chord), and the two loops share the edge x-b. The interval rule misses these where the interval
 * is shorter than the tolerance (it takes it for a point contact) or where
 * x's partner was merged into its neighbour (the boxed sphere). Where the
 * first loop runs a, x, b (the two differ by x alone) the reach is the
 * merges' guard, twice the tolerance, or a thousandth of the chord up to
 * 16 tolerances (a file's tolerance far below its edges). Where x is
 * already a's other neighbour in the second loop (x, a, b), a merges into x
 * instead: an insertion would leave a spike x, a, x with a on one side of
 * the seam only. A second pass takes the free edges a-b that other loops
 * go round through one vertex x, both of its edges sewn (a cusp where an
 * arc meets a line tangentially, its tip a hair off the line: the loop
 * that holds the cusp cut straight to the tip), x going in as above; and
 * the free edges beside a sliver narrower than the tolerance, whose other
 * long side is another loop's free edge: their ends merge pairwise. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sw_math.h"
#include "sw_sew_internal.h"

typedef struct tj_use {
    uint64_t key;         /* the edge: lower vertex << 32 | higher */
    uint32_t loop, slot;  /* the loop's slot ending the run of the edge's first vertex */
} tj_use;

typedef struct tj_insert {
    uint32_t loop, after; /* insert after this slot of the loop */
    sw_seam_slot slot;
    uint32_t merge;       /* SW_SEAM_NONE, or the vertex that becomes slot.vertex instead */
} tj_insert;

static int compare_uses(const void *x, const void *y)
{
    uint64_t a = ((const tj_use *)x)->key, b = ((const tj_use *)y)->key;
    return a < b ? -1 : a > b;
}

static int compare_inserts(const void *x, const void *y)
{
    const tj_insert *a = x, *b = y;
    if (a->loop != b->loop)
        return a->loop < b->loop ? -1 : 1;
    return (a->after > b->after) - (a->after < b->after);
}

/* Where the loops differ by x alone, x may stand off the chord by this
 * much of it, up to this many tolerances. */
#define BETWEEN_OF_EDGE 1e-3
#define BETWEEN_TOLS 16.0

static uint64_t edge_key(uint32_t a, uint32_t b)
{
    return a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
}

/* The slot after k in its loop whose vertex differs from slot k's, as a
 * global slot index; k itself when the loop shows one vertex only. */
static uint32_t next_distinct(const sw_seam_host *h, const sw_seam_loop *lp, uint32_t k)
{
    for (uint32_t d = 1; d < lp->slot_count; d++) {
        uint32_t j = lp->first_slot + (k - lp->first_slot + d) % lp->slot_count;
        if (h->slots[j].vertex != h->slots[k].vertex)
            return j;
    }
    return k;
}

/* Every edge use, recorded at the last slot of its first vertex's run. */
static tj_use *collect_uses(const sw_seam_host *h, size_t *n)
{
    tj_use *uses = malloc(((size_t)h->slot_count + 1) * sizeof *uses);
    *n = 0;
    for (uint32_t l = 0; uses && l < h->loop_count; l++) {
        const sw_seam_loop *lp = &h->loops[l];
        for (uint32_t k = lp->first_slot; k < lp->first_slot + lp->slot_count; k++) {
            uint32_t j = lp->first_slot + (k - lp->first_slot + 1) % lp->slot_count;
            if (h->slots[j].vertex != h->slots[k].vertex)
                uses[(*n)++] = (tj_use){edge_key(h->slots[k].vertex, h->slots[j].vertex), l, k};
        }
    }
    if (uses && *n > 1)
        qsort(uses, *n, sizeof *uses, compare_uses);
    return uses;
}

/* The first of the uses (sorted) of edge key or later. */
static size_t first_use(const tj_use *uses, size_t n, uint64_t key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (uses[mid].key < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* The one use of edge key, or NULL when it has none or several. */
static const tj_use *only_use(const tj_use *uses, size_t n, uint64_t key)
{
    size_t lo = first_use(uses, n, key);
    if (lo >= n || uses[lo].key != key || (lo + 1 < n && uses[lo + 1].key == key))
        return NULL;
    return &uses[lo];
}

static sw_vec3 at(const sew_state *s, uint32_t v)
{
    const double *p = s->poly->p + 3 * (size_t)v;
    return sw_v3(p[0], p[1], p[2]);
}

/* The slot before k in its loop whose vertex differs from slot k's. */
static uint32_t prev_distinct(const sw_seam_host *h, const sw_seam_loop *lp, uint32_t k)
{
    for (uint32_t d = 1; d < lp->slot_count; d++) {
        uint32_t j = lp->first_slot + (k - lp->first_slot + lp->slot_count - d) % lp->slot_count;
        if (h->slots[j].vertex != h->slots[k].vertex)
            return j;
    }
    return k;
}

/* x onto the edge a-b of use u (slots k, j) where its foot lies inside. */
static int insertion_on_edge(const sw_seam_host *h, const tj_use *u, uint32_t k, uint32_t j,
                             sw_vec3 pa, sw_vec3 ab, sw_vec3 px, uint32_t x, tj_insert *out)
{
    double len2 = sw_v3_dot(ab, ab), t = len2 > 0 ? sw_v3_dot(sw_v3_sub(px, pa), ab) / len2 : 0;
    if (!(t > 0.0 && t < 1.0))
        return 0;   /* beyond an end: not on this edge */
    const float *ua = h->slots[k].uv, *ub = h->slots[j].uv;
    *out = (tj_insert){u->loop, k, {x, {(float)(ua[0] + t * (ub[0] - ua[0])),
                                        (float)(ua[1] + t * (ub[1] - ua[1]))}}, SW_SEAM_NONE};
    return 1;
}

/* Would x (between a and b in some loop) go into the use u of edge a-b?
 * Not where x is already a's other neighbour in u's loop (x, a, b): that
 * would give x, a, x, b, a spike out to a and back, with a on one side of
 * the seam only (the boxed sphere: a fillet's trim tip at a sphere's pole
 * whose points were merged into x, 0.023 mm off; the drawn-seam check
 * found the tip as a gap point). Then a merges into x instead when within
 * the reach: both loops run x, b. Likewise b for a, b, x. */
static int insertion(const sew_state *s, const sw_seam_host *h, const tj_use *u, uint32_t x,
                     int between, tj_insert *out)
{
    const sw_seam_loop *lp = &h->loops[u->loop];
    uint32_t k = u->slot, j = next_distinct(h, lp, k);
    uint32_t a = h->slots[k].vertex, b = h->slots[j].vertex;
    sw_vec3 pa = at(s, a), pb = at(s, b), px = at(s, x), ab = sw_v3_sub(pb, pa);
    double reach = fmax(s->tol, sew_gap(s->poly, x) + fmax(sew_gap(s->poly, a), sew_gap(s->poly, b)));
    /* x between a and b in its own loop: the two loops differ by x alone,
     * and the reach is the merges' guard, twice the tolerance, or a
     * thousandth of the chord (up to BETWEEN_TOLS). An arc tangent to a
     * line leaves it slowly: its vertices near the tangent point lie within
     * the tolerance of the line on one face and a little beyond on the
     * other, and with a file's tolerance of 4e-5 mm on a 1.3 mm line, two
     * tolerances was not enough. */
    if (between)
        reach = fmax(reach, fmax(2.0 * s->tol, fmin(BETWEEN_TOLS * s->tol,
                                                     BETWEEN_OF_EDGE * sw_v3_length(ab))));
    if (!(sw_v3_segment_distance(px, pa, pb) <= reach))
        return 0;
    uint32_t spike = h->slots[prev_distinct(h, lp, k)].vertex == x ? a
                   : h->slots[next_distinct(h, lp, j)].vertex == x ? b : SW_SEAM_NONE;
    if (spike != SW_SEAM_NONE && sw_v3_length(sw_v3_sub(at(s, spike), px)) <= reach) {
        *out = (tj_insert){u->loop, k, {x, {0, 0}}, spike};
        return 1;
    }
    /* A tip beyond the reach is a corner of its own: inserted as before, the
     * spike's edge runs twice along the loop (a seam with itself). */
    return insertion_on_edge(h, u, k, j, pa, ab, px, x, out);
}

static uint32_t merged_into(const uint32_t *to, uint32_t v)
{
    while (to[v] != v)
        v = to[v];
    return v;
}

/* Merges (merge != SW_SEAM_NONE) as a map over the slots' vertices: each
 * merged vertex to the one it joins. NULL when out of memory. */
static uint32_t *merge_map(const sw_seam_host *h, const tj_insert *ins, size_t n)
{
    uint32_t top = 0;
    for (uint32_t k = 0; k < h->slot_count; k++)
        top = h->slots[k].vertex > top ? h->slots[k].vertex : top;
    uint32_t *to = malloc(((size_t)top + 1) * sizeof *to);
    for (uint32_t v = 0; to && v <= top; v++)
        to[v] = v;
    for (size_t i = 0; to && i < n; i++) {
        if (ins[i].merge == SW_SEAM_NONE)
            continue;
        uint32_t from = merged_into(to, ins[i].merge), into = merged_into(to, ins[i].slot.vertex);
        if (from != into)
            to[from] = into;
    }
    return to;
}

/* The loops' slots again with the insertions (sorted) in place and the
 * merged vertices replaced. */
static sw_status apply(sw_seam_host *h, const tj_insert *ins, size_t n, sw_error *err)
{
    sw_seam_slot *slots = malloc(((size_t)h->slot_count + n + 1) * sizeof *slots);
    uint32_t *to = merge_map(h, ins, n);
    if (!slots || !to) {
        free(slots), free(to);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "sewing: out of memory for T-junctions");
    }
    uint32_t at_slot = 0;
    size_t next = 0;
    for (uint32_t l = 0; l < h->loop_count; l++) {
        sw_seam_loop *lp = &h->loops[l];
        uint32_t first = at_slot;
        for (uint32_t k = lp->first_slot; k < lp->first_slot + lp->slot_count; k++) {
            slots[at_slot] = h->slots[k];
            slots[at_slot].vertex = merged_into(to, slots[at_slot].vertex);
            at_slot++;
            for (; next < n && ins[next].loop == l && ins[next].after == k; next++)
                if (ins[next].merge == SW_SEAM_NONE) {
                    slots[at_slot] = ins[next].slot;
                    slots[at_slot].vertex = merged_into(to, slots[at_slot].vertex);
                    at_slot++;
                }
        }
        lp->first_slot = first;
        lp->slot_count = at_slot - first;
    }
    free(h->slots);
    free(to);
    h->slots = slots;
    h->slot_count = at_slot;
    return SW_OK;
}

typedef struct tj_end {
    uint32_t vertex;
    uint32_t use;   /* index into the sorted uses */
} tj_end;

static int compare_ends(const void *x, const void *y)
{
    const tj_end *a = x, *b = y;
    if (a->vertex != b->vertex)
        return a->vertex < b->vertex ? -1 : 1;
    return (a->use > b->use) - (a->use < b->use);
}

/* Both ends of every unsewn edge use (every use, with all), sorted by
 * vertex. */
static tj_end *edge_ends(const tj_use *uses, size_t n, int all, size_t *count)
{
    tj_end *ends = malloc((2 * n + 1) * sizeof *ends);
    *count = 0;
    for (size_t i = 0; ends && i < n; i++) {
        if (!all && only_use(uses, n, uses[i].key) != &uses[i])
            continue;
        ends[(*count)++] = (tj_end){(uint32_t)(uses[i].key >> 32), (uint32_t)i};
        ends[(*count)++] = (tj_end){(uint32_t)uses[i].key, (uint32_t)i};
    }
    if (ends && *count > 1)
        qsort(ends, *count, sizeof *ends, compare_ends);
    return ends;
}

/* The first of ends (sorted) at vertex v. */
static size_t first_end(const tj_end *ends, size_t nends, uint32_t v)
{
    size_t lo = 0, hi = nends;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (ends[mid].vertex < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* The vertex beyond x from b in the loop of use w (of edge x-b). */
static uint32_t beyond(const sw_seam_host *h, const tj_use *w, uint32_t x)
{
    const sw_seam_loop *lp = &h->loops[w->loop];
    uint32_t k = w->slot;
    if (h->slots[k].vertex == x)
        return h->slots[prev_distinct(h, lp, k)].vertex;
    return h->slots[next_distinct(h, lp, next_distinct(h, lp, k))].vertex;
}

/* x, of an unsewn edge x-b, into the other unsewn edges at b. */
static void try_end(const sew_state *s, const sw_seam_host *h, const tj_use *uses,
                    const tj_end *ends, size_t nends, size_t i, uint32_t x, uint32_t b,
                    uint8_t *taken, tj_insert *ins, size_t *count)
{
    uint32_t next = beyond(h, &uses[i], x);
    for (size_t k = first_end(ends, nends, b); k < nends && ends[k].vertex == b; k++) {
        const tj_use *u = &uses[ends[k].use];
        uint32_t a = (uint32_t)(u->key >> 32) == b ? (uint32_t)u->key : (uint32_t)(u->key >> 32);
        if (ends[k].use == i || u->loop == uses[i].loop || a == x || taken[ends[k].use])
            continue;
        if (insertion(s, h, u, x, next == a, &ins[*count])) {
            taken[ends[k].use] = 1;
            (*count)++;
            return;
        }
    }
}

/* Is edge key used by a loop other than `loop`? */
static int used_elsewhere(const tj_use *uses, size_t n, uint64_t key, uint32_t loop)
{
    for (size_t lo = first_use(uses, n, key); lo < n && uses[lo].key == key; lo++)
        if (uses[lo].loop != loop)
            return 1;
    return 0;
}

/* Free edge use i, a-b, where other loops go from a to b through one
 * vertex x (edges a-x and x-b): x into it, as where the loops differ by x
 * alone. Returns 1 with *out filled. */
static int detour(const sew_state *s, const sw_seam_host *h, const tj_use *uses, size_t n,
                  const tj_end *ends, size_t nends, size_t i, tj_insert *out)
{
    uint32_t a = (uint32_t)(uses[i].key >> 32), b = (uint32_t)uses[i].key, loop = uses[i].loop;
    for (size_t k = first_end(ends, nends, a); k < nends && ends[k].vertex == a; k++) {
        const tj_use *w = &uses[ends[k].use];
        uint32_t x = (uint32_t)(w->key >> 32) == a ? (uint32_t)w->key : (uint32_t)(w->key >> 32);
        if (x == b || w->loop == loop || !used_elsewhere(uses, n, edge_key(x, b), loop))
            continue;
        if (insertion(s, h, &uses[i], x, 1, out))
            return 1;
    }
    return 0;
}

/* The end of use w other than v. */
static uint32_t other_end(const tj_use *w, uint32_t v)
{
    uint32_t lo = (uint32_t)(w->key >> 32), hi = (uint32_t)w->key;
    return lo == v ? hi : lo;
}

/* Are u and v within the merges' reach of each other? */
static int within_reach(const sew_state *s, uint32_t u, uint32_t v)
{
    double reach = fmax(s->tol, sew_gap(s->poly, u) + sew_gap(s->poly, v));
    return sw_v3_length(sw_v3_sub(at(s, u), at(s, v))) <= reach;
}

/* Free edge use i, a-b, beside another loop's free edge c-d whose ends
 * pair with a and b within the reach, each joined to its partner by an
 * edge: a sliver narrower than the tolerance between two faces, each
 * running along one of its long sides (the Bambu X1C mount: 0.002 mm wide,
 * 3.2 mm long). c merges into a and d into b (out[0], out[1]): both faces
 * run a-b, as OpenCASCADE's sewing pairs two such edges. Returns the
 * partner's use, or n when there is none. */
static size_t sliver(const sew_state *s, const tj_use *uses, size_t n, const tj_end *ends,
                     size_t nends, size_t i, tj_insert *out)
{
    for (int turn = 0; turn < 2; turn++) {
        uint32_t a = turn ? (uint32_t)uses[i].key : (uint32_t)(uses[i].key >> 32);
        uint32_t b = other_end(&uses[i], a);
        for (size_t k = first_end(ends, nends, a); k < nends && ends[k].vertex == a; k++) {
            uint32_t c = other_end(&uses[ends[k].use], a);
            if (c == b || !within_reach(s, a, c))
                continue;
            for (size_t m = first_end(ends, nends, c); m < nends && ends[m].vertex == c; m++) {
                const tj_use *f = &uses[ends[m].use];
                uint32_t d = other_end(f, c);
                size_t bd = first_use(uses, n, edge_key(b, d));
                if (f->loop == uses[i].loop || d == a || d == b || only_use(uses, n, f->key) != f ||
                    !within_reach(s, b, d) || bd >= n || uses[bd].key != edge_key(b, d))
                    continue;
                out[0] = (tj_insert){uses[i].loop, uses[i].slot, {a, {0, 0}}, c};
                out[1] = (tj_insert){uses[i].loop, uses[i].slot, {b, {0, 0}}, d};
                return ends[m].use;
            }
        }
    }
    return n;
}

/* Step 3b's second pass: every free edge with a detour (detour), or
 * beside a sliver's other side (sliver). */
static sw_status insert_detours(sew_state *s, sw_seam_host *h, size_t *inserted)
{
    size_t n = 0, nends = 0, count = 0;
    tj_use *uses = collect_uses(h, &n);
    tj_end *ends = uses ? edge_ends(uses, n, 1, &nends) : NULL;
    tj_insert *ins = malloc((2 * n + 1) * sizeof *ins);
    uint8_t *taken = calloc(n + 1, 1);
    if (!uses || !ends || !ins || !taken) {
        free(uses), free(ends), free(ins), free(taken);
        return sw_error_set(s->err, SW_ERR_NO_MEMORY, "sewing: out of memory for T-junctions");
    }
    for (size_t i = 0; i < n; i++) {
        if (taken[i] || only_use(uses, n, uses[i].key) != &uses[i])
            continue;
        if (detour(s, h, uses, n, ends, nends, i, &ins[count])) {
            count++;
            continue;
        }
        size_t partner = sliver(s, uses, n, ends, nends, i, &ins[count]);
        if (partner < n)
            taken[partner] = 1, count += 2;
    }
    if (count > 1)
        qsort(ins, count, sizeof *ins, compare_inserts);
    sw_status st = count ? apply(h, ins, count, s->err) : SW_OK;
    *inserted += count;
    free(uses), free(ends), free(ins), free(taken);
    return st;
}

sw_status sew_insert_tjunctions(sew_state *s, sw_seam_host *h, size_t *inserted)
{
    *inserted = 0;
    size_t n = 0, nends = 0;
    tj_use *uses = collect_uses(h, &n);
    tj_end *ends = uses ? edge_ends(uses, n, 0, &nends) : NULL;
    tj_insert *ins = malloc((2 * n + 1) * sizeof *ins);
    uint8_t *taken = calloc(n + 1, 1);
    if (!uses || !ends || !ins || !taken) {
        free(uses), free(ends), free(ins), free(taken);
        return sw_error_set(s->err, SW_ERR_NO_MEMORY, "sewing: out of memory for T-junctions");
    }
    size_t count = 0;
    for (size_t e = 0; e < nends; e++) {
        if (e > 0 && ends[e].use == ends[e - 1].use)
            continue;
        size_t i = ends[e].use;
        uint32_t lo = (uint32_t)(uses[i].key >> 32), hi = (uint32_t)uses[i].key;
        try_end(s, h, uses, ends, nends, i, lo, hi, taken, ins, &count);
        try_end(s, h, uses, ends, nends, i, hi, lo, taken, ins, &count);
    }
    if (count > 1)
        qsort(ins, count, sizeof *ins, compare_inserts);
    sw_status st = count ? apply(h, ins, count, s->err) : SW_OK;
    *inserted = count;
    free(uses), free(ends), free(ins), free(taken);
    return st == SW_OK ? insert_detours(s, h, inserted) : st;
}
