/* SPDX-License-Identifier: MIT */
/* Clustering into super-surfaces (assets/super/sw_cluster.h), checked by
 * what the clusters must be, on hand-built surfaces and, given a pack's
 * path, on a real pack (the teaset, built by CTest):
 * - every surface in exactly one cluster, members of one part;
 * - every cluster connected through the Seam Graph's adjacency;
 * - the stored cone holds every member's cone, and every sampled normal
 *   of every member patch (random (u, v), sw_bezier_eval) lies inside it;
 * - no cluster past alpha or a cap unless it is one surface alone;
 * - no small cluster left beside one it could merge with under alpha;
 * - the pack's stored clusters are what sw_cluster_pack makes again. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_test.h"
#include "pack_file.h"
#include "sw_bezier.h"
#include "sw_cluster.h"
#include "sw_surface_cone.h"

#define DEG (3.14159265358979323846 / 180.0)

static double angle_between(sw_vec3 a, sw_vec3 b)
{
    return atan2(sw_v3_length(sw_v3_cross(a, b)), sw_v3_dot(a, b));
}

static sw_vec3 axis_of(const sw_super_surface *r)
{
    return sw_v3(r->axis[0], r->axis[1], r->axis[2]);
}

/* The stored cone as a normal cone (empty axis: the full sphere). */
static sw_normal_cone stored_cone(const sw_super_surface *r)
{
    sw_normal_cone c = { axis_of(r), r->span };
    return c;
}

/* ---- the invariants ---- */

static void check_partition(const sw_cluster_input *in, const sw_supers *v)
{
    uint32_t *seen = calloc(in->surface_count + 1, sizeof *seen);
    for (uint32_t k = 0; k < v->super_count; k++) {
        const sw_super_surface *r = &v->supers[k];
        SW_CHECK(r->member_count >= 1);
        for (uint32_t m = r->first_member; m < r->first_member + r->member_count; m++) {
            uint32_t s = v->members[m];
            SW_CHECK_MSG(s < in->surface_count && seen[s]++ == 0, "surface %u listed twice", s);
            SW_CHECK_MSG(v->super_of[s] == k, "SUPER_OF[%u] %u, listed in %u", s, v->super_of[s], k);
            SW_CHECK_MSG(in->parts[s] == r->part, "surface %u of part %u in part %u's cluster", s,
                         in->parts[s], r->part);
        }
    }
    for (uint32_t s = 0; s < in->surface_count; s++)
        SW_CHECK_MSG(seen[s] == 1, "surface %u in %u clusters", s, seen[s]);
    free(seen);
}

/* Breadth-first from the first member over adjacency within the cluster. */
static void check_connected(const sw_cluster_input *in, const sw_supers *v)
{
    const sw_surface_adjacency *a = in->adjacency;
    uint32_t *queue = malloc((in->surface_count + 1) * sizeof *queue);
    uint8_t *reached = calloc(in->surface_count + 1, 1);
    for (uint32_t k = 0; k < v->super_count; k++) {
        const sw_super_surface *r = &v->supers[k];
        uint32_t head = 0, tail = 0;
        queue[tail++] = v->members[r->first_member];
        reached[queue[0]] = 1;
        while (head < tail) {
            uint32_t s = queue[head++];
            for (uint32_t i = a->first[s]; i < a->first[s + 1]; i++)
                if (v->super_of[a->next[i]] == k && !reached[a->next[i]]) {
                    reached[a->next[i]] = 1;
                    queue[tail++] = a->next[i];
                }
        }
        SW_CHECK_MSG(tail == r->member_count, "cluster %u: %u of %u members reached", k, tail,
                     r->member_count);
    }
    free(queue);
    free(reached);
}

/* The stored span is at least the angle from the stored axis to every
 * member cone's edge; within alpha and the caps unless alone. */
static void check_cones_and_caps(const sw_cluster_input *in, const sw_cluster_options *o,
                                 const sw_supers *v)
{
    for (uint32_t k = 0; k < v->super_count; k++) {
        const sw_super_surface *r = &v->supers[k];
        uint64_t triangles = 0;
        for (uint32_t m = r->first_member; m < r->first_member + r->member_count; m++) {
            const sw_normal_cone *c = &in->cones[v->members[m]];
            triangles += in->triangles ? in->triangles[v->members[m]] : 0;
            if (c->half_angle < 0 || r->span >= SW_SUPER_SPAN_FULL)
                continue;
            SW_CHECK_MSG(c->half_angle < SW_CONE_FULL, "cluster %u has a cone but member %u none",
                         k, v->members[m]);
            double edge = angle_between(axis_of(r), c->axis) + c->half_angle;
            SW_CHECK_MSG(edge <= r->span, "cluster %u: member %u's cone edge %.9g past span %.9g",
                         k, v->members[m], edge, (double)r->span);
        }
        if (r->member_count == 1)
            continue;
        SW_CHECK_MSG(r->span <= o->alpha_rad + 1e-5, "cluster %u: span %g over alpha", k,
                     (double)r->span);
        SW_CHECK(r->member_count <= o->max_members && triangles <= o->max_triangles);
    }
}

static uint64_t cluster_triangles(const sw_cluster_input *in, const sw_supers *v, uint32_t k)
{
    uint64_t t = 0;
    const sw_super_surface *r = &v->supers[k];
    for (uint32_t m = r->first_member; in->triangles && m < r->first_member + r->member_count; m++)
        t += in->triangles[v->members[m]];
    return t;
}

/* No small cluster beside one of its part it could join within alpha and
 * the caps (the stored cones are a little wider than the clustering's, so
 * a pair they let merge is one the clustering would have merged). */
static void check_no_mergeable_small(const sw_cluster_input *in, const sw_cluster_options *o,
                                     const sw_supers *v)
{
    const sw_surface_adjacency *a = in->adjacency;
    for (uint32_t s = 0; s < in->surface_count; s++)
        for (uint32_t i = a->first[s]; i < a->first[s + 1]; i++) {
            uint32_t c = v->super_of[s], d = v->super_of[a->next[i]];
            const sw_super_surface *rc = &v->supers[c], *rd = &v->supers[d];
            if (c == d || rc->part != rd->part || rc->member_count >= o->min_members ||
                rc->member_count + rd->member_count > o->max_members ||
                cluster_triangles(in, v, c) + cluster_triangles(in, v, d) > o->max_triangles)
                continue;
            sw_normal_cone cc = stored_cone(rc), cd = stored_cone(rd);
            sw_normal_cone u = sw_normal_cone_union_tight(&cd, &cc);
            double span = u.half_angle >= SW_CONE_FULL ? 3.2 : u.half_angle;
            SW_CHECK_MSG(span > o->alpha_rad, "small cluster %u (%u members) could join %u: "
                         "span %g <= alpha %g", c, rc->member_count, d, span, o->alpha_rad);
        }
}

static void check_all(const sw_cluster_input *in, const sw_cluster_options *opt,
                      const sw_supers *v)
{
    sw_cluster_options o = opt ? *opt : (sw_cluster_options){ 0 };
    o.alpha_rad = o.alpha_rad ? o.alpha_rad : SW_CLUSTER_ALPHA_DEFAULT;
    o.max_members = o.max_members ? o.max_members : SW_CLUSTER_MAX_MEMBERS_DEFAULT;
    o.max_triangles = o.max_triangles ? o.max_triangles : SW_CLUSTER_MAX_TRIANGLES_DEFAULT;
    o.min_members = o.min_members ? o.min_members : SW_CLUSTER_MIN_MEMBERS_DEFAULT;
    check_partition(in, v);
    check_connected(in, v);
    check_cones_and_caps(in, &o, v);
    check_no_mergeable_small(in, &o, v);
}

/* ---- hand-built surfaces ---- */

enum { MAX_SYNTH = 64 };
typedef struct synth {
    sw_normal_cone cones[MAX_SYNTH];
    uint32_t parts[MAX_SYNTH], triangles[MAX_SYNTH];
    uint32_t pairs[2 * MAX_SYNTH][2];
    uint32_t n, pair_count;
    sw_surface_adjacency adjacency;
    sw_cluster_input in;
} synth;

/* Surface i's cone: axis turned by angle_deg about y from +z. */
static void set_cone(synth *t, uint32_t i, double angle_deg, double half_deg)
{
    t->cones[i] = (sw_normal_cone){ sw_v3(sin(angle_deg * DEG), 0, cos(angle_deg * DEG)),
                                     half_deg * DEG };
}

/* n surfaces in a chain 0-1-...-(n-1), part 0, 100 triangles each. */
static void make_chain(synth *t, uint32_t n)
{
    memset(t, 0, sizeof *t);
    t->n = n;
    for (uint32_t i = 0; i < n; i++) {
        set_cone(t, i, 0, 0);
        t->triangles[i] = 100;
        if (i > 0) {
            t->pairs[t->pair_count][0] = i - 1;
            t->pairs[t->pair_count++][1] = i;
        }
    }
}

static void finish(synth *t)
{
    sw_error err = { 0 };
    SW_CHECK(sw_surface_adjacency_from_pairs(t->n, (const uint32_t (*)[2])t->pairs, t->pair_count,
                                             &t->adjacency, &err) == SW_OK);
    t->in = (sw_cluster_input){ .surface_count = t->n, .cones = t->cones, .parts = t->parts,
                                .triangles = t->triangles, .adjacency = &t->adjacency };
}

static sw_clusters_built run(synth *t, const sw_cluster_options *o, sw_cluster_report *rep)
{
    finish(t);
    sw_clusters_built b;
    sw_error err = { 0 };
    SW_CHECK_MSG(sw_cluster_surfaces(&t->in, o, &b, rep, &err) == SW_OK, "%s", err.message);
    check_all(&t->in, o, &b.view);
    return b;
}

static void done(synth *t, sw_clusters_built *b)
{
    sw_clusters_built_free(b);
    sw_surface_adjacency_free(&t->adjacency);
}

/* Cones turning 10 degrees a surface: alpha 25 takes 6 surfaces a cluster
 * (flat cones 0..50 degrees apart: half-angle 25, and a hair of rounding). */
static void test_growth_stops_at_alpha(void)
{
    synth t;
    make_chain(&t, 12);
    for (uint32_t i = 0; i < 12; i++)
        set_cone(&t, i, 10.0 * i, 0);
    sw_cluster_options o = { .alpha_rad = 25.001 * DEG };
    sw_cluster_report rep;
    sw_clusters_built b = run(&t, &o, &rep);
    SW_CHECK_MSG(b.view.super_count == 2, "%u clusters", b.view.super_count);
    SW_CHECK(b.view.supers[0].member_count == 6 && b.view.supers[1].member_count == 6);
    SW_CHECK(fabs(b.view.supers[0].span - 25 * DEG) < 1e-5);
    SW_CHECK(rep.clusters == 2 && rep.surfaces == 12 && rep.wide_alone == 0);
    done(&t, &b);
}

/* Two parts side by side never share a cluster, however flat. */
static void test_parts_apart(void)
{
    synth t;
    make_chain(&t, 6);
    for (uint32_t i = 3; i < 6; i++)
        t.parts[i] = 1;
    sw_clusters_built b = run(&t, NULL, NULL);
    SW_CHECK(b.view.super_count == 2 && b.view.supers[0].part != b.view.supers[1].part);
    done(&t, &b);
}

/* A flat chain of 20 capped at 8 members, then at 450 triangles (4 of 100
 * each: the caps keep detail controllable). */
static void test_caps(void)
{
    synth t;
    make_chain(&t, 20);
    sw_cluster_options o = { .max_members = 8, .min_members = 1 };
    sw_cluster_report rep;
    sw_clusters_built b = run(&t, &o, &rep);
    SW_CHECK_MSG(b.view.super_count == 3 && rep.capped >= 2, "%u clusters, %u capped",
                 b.view.super_count, rep.capped);
    done(&t, &b);
    make_chain(&t, 20);
    o = (sw_cluster_options){ .max_triangles = 450, .min_members = 1 };
    b = run(&t, &o, NULL);
    SW_CHECK_MSG(b.view.super_count == 5, "%u clusters", b.view.super_count);
    done(&t, &b);
}

/* A surface wider than alpha is alone; the full sphere is stored as span
 * pi without an axis. */
static void test_wide_alone(void)
{
    synth t;
    make_chain(&t, 3);
    set_cone(&t, 1, 0, 70);
    t.cones[2] = (sw_normal_cone){ sw_v3(0, 0, 0), 2.0 };
    sw_cluster_report rep;
    sw_clusters_built b = run(&t, NULL, &rep);
    SW_CHECK(b.view.super_count == 3 && rep.wide_alone == 2);
    const sw_super_surface *full = &b.view.supers[b.view.super_of[2]];
    SW_CHECK(full->span == 3.14159265f && full->axis[0] == 0 && full->axis[2] == 0);
    done(&t, &b);
}

/* Seeds flattest first: the flat middle surface of a V seeds, takes the
 * side within alpha first, and the tilted rest grows apart. */
static void test_seed_flattest(void)
{
    synth t;
    make_chain(&t, 5);
    double tilt[5] = { -60, -30, 0, 20, 40 };
    double half[5] = { 5, 5, 0, 5, 5 };
    for (uint32_t i = 0; i < 5; i++)
        set_cone(&t, i, tilt[i], half[i]);
    sw_cluster_options o = { .alpha_rad = 20 * DEG, .min_members = 1 };
    sw_clusters_built b = run(&t, &o, NULL);
    SW_CHECK(b.view.super_of[2] == 0 && b.view.super_of[3] == 0 && b.view.super_of[1] != 0);
    done(&t, &b);
}

static void test_bad_options(void)
{
    synth t;
    make_chain(&t, 2);
    finish(&t);
    sw_clusters_built b;
    sw_error err = { 0 };
    sw_cluster_options o = { .alpha_rad = 2.0 };
    SW_CHECK(sw_cluster_surfaces(&t.in, &o, &b, NULL, &err) == SW_ERR_ARG &&
             strstr(err.message, "alpha 2 rad, expected in (0, pi/2)"));
    SW_CHECK(b.supers == NULL);
    sw_surface_adjacency_free(&t.adjacency);
}

/* The tight union: the smallest cone holding two, and never smaller. */
static void test_union_tight(void)
{
    sw_normal_cone a = { sw_v3(0, 0, 1), 10 * DEG }, b = { sw_v3(sin(40 * DEG), 0, cos(40 * DEG)),
                                                          0 };
    sw_normal_cone u = sw_normal_cone_union_tight(&a, &b);
    SW_CHECK(fabs(u.half_angle - 25 * DEG) < 1e-9);
    SW_CHECK(angle_between(u.axis, a.axis) + a.half_angle <= u.half_angle);
    SW_CHECK(angle_between(u.axis, b.axis) + b.half_angle <= u.half_angle);
    sw_normal_cone inside = { sw_v3(sin(5 * DEG), 0, cos(5 * DEG)), 2 * DEG };
    u = sw_normal_cone_union_tight(&a, &inside);
    SW_CHECK(u.half_angle == a.half_angle);
    sw_normal_cone opposite = { sw_v3(0, 0, -1), 0 };
    SW_CHECK(sw_normal_cone_union_tight(&a, &opposite).half_angle >= SW_CONE_FULL);
}

/* ---- a real pack ---- */

static sw_cluster_input pack_input(const sw_pack *pack, sw_normal_cone *cones, uint32_t *parts,
                                   uint32_t *triangles, sw_surface_adjacency *adjacency)
{
    sw_error err = { 0 };
    SW_CHECK(sw_cluster_surface_cones(pack, cones, &err) == SW_OK);
    const sw_levels *l = &pack->levels;
    for (uint32_t s = 0; s < pack->surface_count; s++) {
        parts[s] = pack->surfaces[s].part;
        triangles[s] = l->surface_levels && l->surface_levels[s] < l->surface_levels[s + 1]
                           ? l->levels[l->surface_levels[s]].index_count / 3
                           : 0;
    }
    SW_CHECK(sw_surface_adjacency_build(&pack->seam, adjacency, &err) == SW_OK);
    return (sw_cluster_input){ .surface_count = pack->surface_count, .cones = cones,
                               .parts = parts, .triangles = triangles, .adjacency = adjacency };
}

/* Every sampled normal of every member patch inside its cluster's cone. */
static uint64_t check_sampled_normals(const sw_pack *pack)
{
    const sw_supers *v = &pack->supers;
    double ctrl[4 * (SW_BEZIER_MAX_DEGREE + 1) * (SW_BEZIER_MAX_DEGREE + 1)];
    uint64_t sampled = 0;
    srand(23);
    for (uint32_t s = 0; s < pack->surface_count; s++) {
        const sw_super_surface *r = &v->supers[v->super_of[s]];
        if (r->span >= SW_SUPER_SPAN_FULL)
            continue;
        const sw_pack_surface *ps = &pack->surfaces[s];
        for (uint32_t i = ps->first_patch; i < ps->first_patch + ps->patch_count; i++) {
            const sw_bezier_patchf pf = sw_pack_patch_view(pack, i, NULL);
            sw_bezier_patch bp = sw_bezier_patch_from_float(&pf, ctrl);
            for (int k = 0; k < 64; k++) {
                sw_surface_point sp;
                sw_bezier_eval(&bp, rand() / (double)RAND_MAX, rand() / (double)RAND_MAX,
                               SW_EVAL_FIRST, &sp);
                sw_vec3 n = sw_v3_cross(sp.du, sp.dv);
                if (!(sw_v3_length(n) > 1e-12 * sw_v3_length(sp.du) * sw_v3_length(sp.dv)))
                    continue; /* a degenerate point: no normal of its own */
                double off = angle_between(axis_of(r), n);
                SW_CHECK_MSG(off <= r->span + 1e-5, "surface %u patch %u: normal %.6g rad off "
                             "the axis of cluster %u, span %.6g", s, i, off, v->super_of[s],
                             (double)r->span);
                sampled++;
            }
        }
    }
    return sampled;
}

static void test_pack(const char *path)
{
    sw_pack pack;
    uint8_t *bytes = sw_test_open_pack_file(path, &pack);
    if (!bytes)
        return;
    sw_error err = { 0 };
    SW_CHECK_MSG(pack.supers.supers && pack.supers.super_count > 0, "%s has no super-surfaces",
                 path);
    uint32_t n = pack.surface_count;
    sw_normal_cone *cones = malloc((n + 1) * sizeof *cones);
    uint32_t *parts = malloc((n + 1) * sizeof *parts), *tris = malloc((n + 1) * sizeof *tris);
    sw_surface_adjacency adjacency;
    sw_cluster_input in = pack_input(&pack, cones, parts, tris, &adjacency);
    const sw_cluster_options defaults = { 0 };
    check_all(&in, &defaults, &pack.supers);
    uint64_t sampled = check_sampled_normals(&pack);
    SW_CHECK(sampled > 0);
    /* Made again from the pack: the same clusters (the build is deterministic). */
    sw_clusters_built b;
    SW_CHECK(sw_cluster_pack(&pack, NULL, NULL, &b, NULL, &err) == SW_OK);
    SW_CHECK(b.view.super_count == pack.supers.super_count &&
             memcmp(b.supers, pack.supers.supers, n ? b.view.super_count * sizeof *b.supers : 0) == 0 &&
             memcmp(b.members, pack.supers.members, n * sizeof *b.members) == 0);
    printf("%s: %u surfaces in %u super-surfaces, %llu normals sampled inside their cones\n",
           path, n, pack.supers.super_count, (unsigned long long)sampled);
    sw_clusters_built_free(&b);
    sw_surface_adjacency_free(&adjacency);
    free(cones);
    free(parts);
    free(tris);
    free(bytes);
}

int main(int argc, char **argv)
{
    if (argc == 2) {
        test_pack(argv[1]);
        return sw_test_finish();
    }
    SW_RUN(test_union_tight);
    SW_RUN(test_growth_stops_at_alpha);
    SW_RUN(test_parts_apart);
    SW_RUN(test_caps);
    SW_RUN(test_wide_alone);
    SW_RUN(test_seed_flattest);
    SW_RUN(test_bad_options);
    return sw_test_finish();
}
