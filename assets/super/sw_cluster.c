/* SPDX-License-Identifier: MIT */
/* Seeded growth and the small clusters' merge (sw_cluster.h). */
#include "sw_cluster.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define NONE 0xFFFFFFFFu
#define PI_F 3.14159265f

/* One cluster while it is built; its members are a list through next_in. */
typedef struct cluster {
    sw_normal_cone cone;
    uint32_t members, part, head;
    uint64_t triangles;
} cluster;

typedef struct state {
    const sw_cluster_input *in;
    sw_cluster_options o;
    uint32_t *cluster_of;     /* per surface; NONE: not yet */
    uint32_t *next_in;        /* per surface: the next member of its cluster, NONE: last */
    uint32_t *mark;           /* per surface or cluster: the stamp that listed it */
    uint32_t *list;           /* the frontier or the neighbouring clusters */
    uint32_t list_count;
    uint32_t stamp;           /* the merge's marks: one per look at a cluster's neighbours */
    cluster *clusters;
    uint32_t count;
    sw_cluster_report report;
} state;

static double span_of(const sw_normal_cone *c)
{
    return c->half_angle < 0 ? 0.0 : c->half_angle >= SW_CONE_FULL ? 3.141592653589793 : c->half_angle;
}

static uint32_t triangles_of(const state *st, uint32_t s)
{
    return st->in->triangles ? st->in->triangles[s] : 0;
}

/* Whether b's members and triangles fit beside a's. */
static int fits(const state *st, const cluster *a, uint32_t members, uint64_t triangles)
{
    return a->members + members <= st->o.max_members &&
           a->triangles + triangles <= st->o.max_triangles;
}

static sw_status resolve_options(const sw_cluster_options *opt, sw_cluster_options *o,
                                 sw_error *err)
{
    *o = opt ? *opt : (sw_cluster_options){ 0 };
    if (o->alpha_rad == 0)
        o->alpha_rad = SW_CLUSTER_ALPHA_DEFAULT;
    if (o->max_members == 0)
        o->max_members = SW_CLUSTER_MAX_MEMBERS_DEFAULT;
    if (o->max_triangles == 0)
        o->max_triangles = SW_CLUSTER_MAX_TRIANGLES_DEFAULT;
    if (o->min_members == 0)
        o->min_members = SW_CLUSTER_MIN_MEMBERS_DEFAULT;
    /* At pi/2 or more a cone no longer tells front from back. */
    if (!(o->alpha_rad > 0 && o->alpha_rad < SW_CONE_FULL))
        return sw_error_set(err, SW_ERR_ARG, "clustering: alpha %g rad, expected in (0, pi/2)",
                            o->alpha_rad);
    return SW_OK;
}

/* Surface s joins cluster c (cone already updated by the caller); its
 * unclustered neighbours of the same part join the frontier. */
static void add_member(state *st, uint32_t c, uint32_t s)
{
    cluster *k = &st->clusters[c];
    st->cluster_of[s] = c;
    st->next_in[s] = k->head;
    k->head = s;
    k->members++;
    k->triangles += triangles_of(st, s);
    const sw_surface_adjacency *a = st->in->adjacency;
    for (uint32_t i = a->first[s]; i < a->first[s + 1]; i++) {
        uint32_t n = a->next[i];
        if (st->cluster_of[n] == NONE && st->mark[n] != c && st->in->parts[n] == k->part) {
            st->mark[n] = c;
            st->list[st->list_count++] = n;
        }
    }
}

/* The frontier candidate whose union with c's cone has the least span,
 * within the caps (*capped: one under alpha was refused by a cap); NONE
 * when the frontier is empty. Drops surfaces clustered meanwhile. */
static uint32_t best_candidate(state *st, uint32_t c, sw_normal_cone *best_cone, int *capped)
{
    const cluster *k = &st->clusters[c];
    uint32_t best = NONE, kept = 0;
    double best_span = INFINITY;
    for (uint32_t i = 0; i < st->list_count; i++) {
        uint32_t s = st->list[i];
        if (st->cluster_of[s] != NONE)
            continue;
        st->list[kept++] = s;
        sw_normal_cone u = sw_normal_cone_union_tight(&k->cone, &st->in->cones[s]);
        double span = span_of(&u);
        if (!fits(st, k, 1, triangles_of(st, s))) {
            *capped |= span <= st->o.alpha_rad;
            continue;
        }
        if (span < best_span || (span == best_span && s < best))
            best = s, best_span = span, *best_cone = u;
    }
    st->list_count = kept;
    return best;
}

/* Grows a new cluster from seed (paper 000, section 3, steps 1a-1f). */
static void grow(state *st, uint32_t seed)
{
    uint32_t c = st->count++;
    cluster *k = &st->clusters[c];
    *k = (cluster){ .cone = st->in->cones[seed], .part = st->in->parts[seed], .head = NONE };
    st->list_count = 0;
    st->mark[seed] = c;
    add_member(st, c, seed);
    if (span_of(&k->cone) > st->o.alpha_rad)
        st->report.wide_alone++;
    int capped = 0;
    for (;;) {
        sw_normal_cone u;
        uint32_t s = best_candidate(st, c, &u, &capped);
        if (s == NONE || span_of(&u) > st->o.alpha_rad)
            break;
        k->cone = u;
        add_member(st, c, s);
    }
    st->report.capped += capped != 0;
}

/* A seed's order: flattest first, ties to the larger surface, then by index. */
typedef struct seed {
    double span, size;
    uint32_t surface;
} seed;

static int compare_seeds(const void *x, const void *y)
{
    const seed *a = x, *b = y;
    if (a->span != b->span)
        return a->span < b->span ? -1 : 1;
    if (a->size != b->size)
        return a->size > b->size ? -1 : 1;
    return (a->surface > b->surface) - (a->surface < b->surface);
}

static int grow_all(state *st)
{
    const sw_cluster_input *in = st->in;
    seed *order = malloc(((size_t)in->surface_count + 1) * sizeof *order);
    if (!order)
        return 0;
    for (uint32_t s = 0; s < in->surface_count; s++)
        order[s] = (seed){ span_of(&in->cones[s]), in->sizes ? in->sizes[s] : 0, s };
    qsort(order, in->surface_count, sizeof *order, compare_seeds);
    for (uint32_t i = 0; i < in->surface_count; i++)
        if (st->cluster_of[order[i].surface] == NONE)
            grow(st, order[i].surface);
    free(order);
    return 1;
}

/* The clusters of c's part adjacent to c, into st->list. */
static void neighbour_clusters(state *st, uint32_t c)
{
    const sw_surface_adjacency *a = st->in->adjacency;
    uint32_t stamp = st->stamp++;
    st->list_count = 0;
    for (uint32_t s = st->clusters[c].head; s != NONE; s = st->next_in[s])
        for (uint32_t i = a->first[s]; i < a->first[s + 1]; i++) {
            uint32_t d = st->cluster_of[a->next[i]];
            if (d != c && st->mark[d] != stamp && st->clusters[d].part == st->clusters[c].part) {
                st->mark[d] = stamp;
                st->list[st->list_count++] = d;
            }
        }
}

/* Small cluster c into the neighbour whose union has the least span, if
 * that stays at most alpha within the caps; 1 when it merged. */
static int merge_small(state *st, uint32_t c)
{
    cluster *k = &st->clusters[c];
    neighbour_clusters(st, c);
    uint32_t best = NONE;
    sw_normal_cone best_cone = { { 0, 0, 0 }, 0 };
    double best_span = INFINITY;
    for (uint32_t i = 0; i < st->list_count; i++) {
        uint32_t d = st->list[i];
        if (!fits(st, &st->clusters[d], k->members, k->triangles))
            continue;
        sw_normal_cone u = sw_normal_cone_union_tight(&st->clusters[d].cone, &k->cone);
        double span = span_of(&u);
        if (span <= st->o.alpha_rad && (span < best_span || (span == best_span && d < best)))
            best = d, best_span = span, best_cone = u;
    }
    if (best == NONE)
        return 0;
    cluster *into = &st->clusters[best];
    uint32_t last = NONE;
    for (uint32_t s = k->head; s != NONE; s = st->next_in[s])
        st->cluster_of[s] = best, last = s;
    st->next_in[last] = into->head;
    into->head = k->head;
    into->members += k->members;
    into->triangles += k->triangles;
    into->cone = best_cone;
    *k = (cluster){ .head = NONE };
    st->report.merged++;
    return 1;
}

/* Until a pass merges nothing: each merge can make a neighbour's union
 * fit that did not before only by removing a cluster, so this ends. */
static void merge_all(state *st)
{
    for (uint32_t c = 0; c < st->count; c++)
        st->mark[c] = NONE;
    for (int changed = 1; changed;) {
        changed = 0;
        for (uint32_t c = 0; c < st->count; c++)
            if (st->clusters[c].members > 0 && st->clusters[c].members < st->o.min_members)
                changed |= merge_small(st, c);
    }
}

void sw_cluster_store_cone(const sw_normal_cone *c, sw_super_surface *rec)
{
    double span = span_of(c);
    if (span >= SW_CONE_FULL) {
        rec->span = PI_F;
        rec->axis[0] = rec->axis[1] = rec->axis[2] = 0.0f;
        return;
    }
    /* No normals known (no patch): any unit axis, span 0. */
    sw_vec3 axis = c->half_angle < 0 ? sw_v3(0, 0, 1) : c->axis;
    rec->axis[0] = (float)axis.x, rec->axis[1] = (float)axis.y, rec->axis[2] = (float)axis.z;
    /* Widened past the rounding of the axis to floats (about 1e-7 rad), so
     * the stored cone still holds every member's. */
    float f = (float)(span + 2e-6);
    rec->span = f < SW_SUPER_SPAN_FULL ? f : PI_F;
    if (!(rec->span < SW_SUPER_SPAN_FULL))
        rec->axis[0] = rec->axis[1] = rec->axis[2] = 0.0f;
}

/* The live clusters as records, in growth order, members increasing. */
static int write_out(state *st, sw_clusters_built *out)
{
    uint32_t n = st->in->surface_count, live = 0;
    for (uint32_t c = 0; c < st->count; c++)
        if (st->clusters[c].members > 0)
            st->mark[c] = live++;
    out->supers = calloc((size_t)live + 1, sizeof *out->supers);
    out->members = malloc(((size_t)n + 1) * sizeof *out->members);
    out->super_of = malloc(((size_t)n + 1) * sizeof *out->super_of);
    if (!out->supers || !out->members || !out->super_of)
        return 0;
    uint32_t first = 0;
    for (uint32_t c = 0; c < st->count; c++) {
        const cluster *k = &st->clusters[c];
        if (k->members == 0)
            continue;
        sw_super_surface *r = &out->supers[st->mark[c]];
        *r = (sw_super_surface){ .first_member = first, .part = k->part };
        sw_cluster_store_cone(&k->cone, r);
        first += k->members;
    }
    for (uint32_t s = 0; s < n; s++) { /* surfaces in order: members increasing */
        sw_super_surface *r = &out->supers[st->mark[st->cluster_of[s]]];
        out->super_of[s] = st->mark[st->cluster_of[s]];
        out->members[r->first_member + r->member_count++] = s;
    }
    out->view = (sw_supers){ .supers = out->supers, .members = out->members,
                             .super_of = out->super_of, .super_count = live, .surface_count = n };
    st->report.clusters = live;
    return 1;
}

static int state_alloc(state *st, uint32_t n)
{
    size_t m = (size_t)n + 1;
    st->cluster_of = malloc(m * sizeof *st->cluster_of);
    st->next_in = malloc(m * sizeof *st->next_in);
    st->mark = malloc(m * sizeof *st->mark);
    st->list = malloc(m * sizeof *st->list);
    st->clusters = malloc(m * sizeof *st->clusters);
    if (!st->cluster_of || !st->next_in || !st->mark || !st->list || !st->clusters)
        return 0;
    for (uint32_t s = 0; s < n; s++)
        st->cluster_of[s] = NONE, st->mark[s] = NONE;
    return 1;
}

static void state_free(state *st)
{
    free(st->cluster_of);
    free(st->next_in);
    free(st->mark);
    free(st->list);
    free(st->clusters);
}

sw_status sw_cluster_surfaces(const sw_cluster_input *in, const sw_cluster_options *opt,
                              sw_clusters_built *out, sw_cluster_report *report, sw_error *err)
{
    memset(out, 0, sizeof *out);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    state st = { .in = in };
    sw_status status = resolve_options(opt, &st.o, err);
    if (status != SW_OK)
        return status;
    if (in->adjacency->surface_count != in->surface_count)
        return sw_error_set(err, SW_ERR_ARG, "clustering: adjacency of %u surfaces for %u",
                            (unsigned)in->adjacency->surface_count, (unsigned)in->surface_count);
    st.report.surfaces = in->surface_count;
    int ok = state_alloc(&st, in->surface_count) && grow_all(&st);
    if (ok) {
        merge_all(&st);
        ok = write_out(&st, out);
    }
    state_free(&st);
    if (!ok) {
        sw_clusters_built_free(out);
        return sw_error_set(err, SW_ERR_NO_MEMORY, "clustering: out of memory for %u surfaces",
                            (unsigned)in->surface_count);
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    st.report.seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    if (report)
        *report = st.report;
    return SW_OK;
}

void sw_clusters_built_free(sw_clusters_built *b)
{
    free(b->supers);
    free(b->members);
    free(b->super_of);
    memset(b, 0, sizeof *b);
}
